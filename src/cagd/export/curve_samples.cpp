#include "cagd/export/curve_samples.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "cagd/analysis/arc_length_parameter.hpp"

namespace cagd::exports {

namespace {

constexpr int kSampleDigits = 15;

void put_sample_number(std::ostream& out, double v) {
    if (v == 0.0) {
        out.put('0');
        return;
    }
    char buf[64];
#if defined(__cpp_lib_to_chars)
    const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, kSampleDigits);
    out.write(buf, r.ptr - buf);
#else
    // The standard library of the WebAssembly build (Emscripten's libc++ 14) has no floating-point
    // to_chars; printf's %.*g is what to_chars(general, precision) is specified to print.
    const int length = std::snprintf(buf, sizeof buf, "%.*g", kSampleDigits, v);
    out.write(buf, length);
#endif
}

}  // namespace

Outcome write_curve_samples(std::ostream& out, const Curve& c, const SampleOptions& o) {
    const char* who = "cagd::exports::write_curve_samples";
    const std::vector<double> br = c.breakpoints();
    const bool by_length = o.arc_length_samples != 0;
    if (by_length && o.arc_length_samples < 2)
        fail_input(who, "arc-length samples must be at least 2, got " + std::to_string(o.arc_length_samples));
    if (!by_length && o.per_piece < 1)
        fail_input(who, "samples per piece must be at least 1, got " + std::to_string(o.per_piece));
    const double rows =
        by_length ? o.arc_length_samples : static_cast<double>(o.per_piece) * static_cast<double>(br.size() - 1) + 1;
    if (rows > static_cast<double>(o.max_rows))
        fail_input(who, "the samples would make " + full_precision(rows) + " rows, more than the limit of " +
                            std::to_string(o.max_rows));
    std::vector<double> ts;
    ts.reserve(static_cast<std::size_t>(rows));
    if (by_length) {
        const analysis::ArcLengthParameter s(
            std::shared_ptr<const Curve>(std::shared_ptr<const Curve>{}, &c));  // non-owning
        for (int j = 0; j < o.arc_length_samples; ++j)
            ts.push_back(j + 1 == o.arc_length_samples ? c.t_max()
                                                       : s.parameter_at(s.length() * j / (o.arc_length_samples - 1)));
    } else {
        for (std::size_t k = 0; k + 1 < br.size(); ++k)
            for (int j = 0; j < o.per_piece + (k + 2 == br.size() ? 1 : 0); ++j)
                ts.push_back(br[k] + (br[k + 1] - br[k]) * j / o.per_piece);
    }
    const int d = c.dimension();
    const char* names = "xyz";
    std::vector<std::string> header{o.parameter_column};
    for (const char* prefix : {"", "d", "dd"})
        for (int k = 0; k < d; ++k) header.push_back(std::string(prefix) + names[k]);
    for (std::size_t i = 0; i < header.size(); ++i) out << (i ? "," : "") << header[i];
    out << '\n';
    for (std::size_t row = 0; row < ts.size(); ++row) {
        const Eigen::MatrixXd J = c.jet(ts[row], 2);
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i < d; ++i)
                if (!std::isfinite(J(k, i)))
                    return {Status::not_representable, "column " + header[static_cast<std::size_t>(1 + k * d + i)] +
                                                           " of row " + std::to_string(row + 1) + " is " +
                                                           full_precision(J(k, i))};
        put_sample_number(out, ts[row]);
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i < d; ++i) {
                out.put(',');
                put_sample_number(out, J(k, i));
            }
        out.put('\n');
    }
    return {};
}

}  // namespace cagd::exports
