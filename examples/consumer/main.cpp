// The C2 cubic spline with chord-length parameter (registry method cubic-b) through five points,
// and its arc length: cagd used from outside the repository.
#include <cagd/analysis/curve_measures.hpp>
#include <cagd/methods/method_registry.hpp>
#include <cstdio>

int main() {
    cagd::PointList points(5, 2);
    points << 0, 0, 1, 2, 3, 3, 4, 1, 6, 0;
    const cagd::methods::InterpolationResult result = cagd::methods::interpolate("cubic-b", points, false);
    if (!result.outcome.ok()) {
        std::fprintf(stderr, "cubic-b: %s\n", result.outcome.message.c_str());
        return 1;
    }
    std::printf("cubic-b length %.15g\n", cagd::analysis::accurate_arc_length(*result.interpolant->curve).value);
    return 0;
}
