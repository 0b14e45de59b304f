// libFuzzer target: methods::interpolate for every configuration of the registry on arbitrary points.
// Input bytes: configuration (1 byte, modulo the configuration count), flags (1 byte: bit 0 closed, bit 1 raw
// doubles), then points — raw mode: 16 bytes per point, two IEEE doubles as they come (NaN, Inf,
// 1e300, denormals); grid mode: 2 bytes per point, signed bytes / 4 (repeated points, collinear
// runs, hairpins, tiny and huge turns). At most 48 points.
// Contract checked: interpolate returns or throws cagd::InvalidInput; a returned curve with an ok
// outcome is finite at every node parameter (no silent NaN); ASan/UBSan see nothing.
// Seed corpus: tests/fuzz/corpus/interpolate.
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "cagd/core/errors.hpp"
#include "cagd/methods/method_registry.hpp"

// Build the per-process caches (the pseudo-spline's 36-node table: seconds under ASan) before the
// first timed input.
// Eight points: more than any configuration's fewest (eigen-spline-5 needs 6).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    cagd::PointList p(8, 2);
    p << 0, 0, 1, 0.5, 2, 0, 3, 1, 4, 0.2, 5, 0.9, 6, 0.1, 7, 0.6;
    for (const cagd::methods::Configuration& c : cagd::methods::configurations())
        cagd::methods::interpolate(c, p, false);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace cagd;
    if (size < 2) return 0;
    const std::vector<methods::Configuration>& configurations = methods::configurations();
    const methods::Configuration& m = configurations[data[0] % configurations.size()];
    const bool closed = data[1] & 1, raw = data[1] & 2;
    const std::size_t stride = raw ? 16 : 2, n = std::min<std::size_t>((size - 2) / stride, 48);
    PointList p(static_cast<Eigen::Index>(n), 2);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* q = data + 2 + i * stride;
        if (raw) {
            double x, y;
            std::memcpy(&x, q, 8);
            std::memcpy(&y, q + 8, 8);
            p.row(static_cast<Eigen::Index>(i)) << x, y;
        } else {
            p.row(static_cast<Eigen::Index>(i)) << static_cast<std::int8_t>(q[0]) / 4.0,
                static_cast<std::int8_t>(q[1]) / 4.0;
        }
    }
    try {
        const methods::InterpolationResult r = methods::interpolate(m, p, closed);
        if (r.outcome.ok()) {
            if (!r.interpolant) std::abort();
            for (double t : r.interpolant->node_parameters)
                if (!r.interpolant->curve->point(t).allFinite()) std::abort();
        }
    } catch (const InvalidInput&) {}
    return 0;
}
