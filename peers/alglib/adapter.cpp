// ALGLIB as its users call it: pspline2build / pspline3build (closed: …buildperiodic) on the points,
// with one of ALGLIB's spline types and parameterizations, then pspline2diff / pspline3diff at the
// parameter values pspline2parametervalues gives. Each span is a cubic in ALGLIB's parameter t, so
// its value and derivative at both ends give its Bézier points exactly up to rounding.
// Configurations TYPE-PARAMETER: TYPE akima (open only, at least 5 points), catmull-rom
// (parabolically terminated, tension 0; closed: cyclic), cubic (parabolically terminated; closed:
// cyclic); PARAMETER uniform, chord, centripetal. GPL, like Debian's ALGLIB: a program of its own,
// never linked into the library or the command. Protocol: peers/protocol.mjs (docs/peers.md).
#include <libalglib/interpolation.h>

#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::string number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.17g", v);
    return b;
}

std::string point(const double* p, int d) {
    std::string s = "[";
    for (int k = 0; k < d; ++k) s += (k ? "," : "") + number(p[k]);
    return s + "]";
}

std::string error_line(const std::string& message) { return "{\"error\":\"" + message + "\"}"; }

// The answer to one request (a document line or an error line).
std::string answer(const std::string& configuration, bool closed, int n, int d, const std::vector<double>& p) {
    const std::size_t dash = configuration.find('-', configuration.rfind("catmull-rom", 0) == 0 ? 11 : 0);
    const std::string type = configuration.substr(0, dash), parameter = dash == std::string::npos ? "" : configuration.substr(dash + 1);
    const int st = type == "akima" ? 0 : type == "catmull-rom" ? 1 : type == "cubic" ? 2 : -1;
    const int pt = parameter == "uniform" ? 0 : parameter == "chord" ? 1 : parameter == "centripetal" ? 2 : -1;
    if (st < 0 || pt < 0)
        return error_line("unknown configuration; alglib has TYPE-PARAMETER, TYPE akima, catmull-rom or cubic, "
                          "PARAMETER uniform, chord or centripetal");
    if (closed && st == 0) return error_line("ALGLIB has no periodic Akima spline");
    if (!closed && st == 0 && n < 5) return error_line("ALGLIB's Akima spline needs at least 5 points");
    if (n < (closed ? 3 : 2)) return error_line("ALGLIB needs at least 2 points (closed: 3)");
    try {
        alglib::real_2d_array xy;
        xy.setlength(n, d);
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < d; ++k) xy(i, k) = p[static_cast<std::size_t>(i * d + k)];
        alglib::pspline2interpolant s2;
        alglib::pspline3interpolant s3;
        alglib::real_1d_array t;
        alglib::ae_int_t count = 0;
        if (d == 2) {
            closed ? alglib::pspline2buildperiodic(xy, n, st, pt, s2) : alglib::pspline2build(xy, n, st, pt, s2);
            alglib::pspline2parametervalues(s2, count, t);
        } else {
            closed ? alglib::pspline3buildperiodic(xy, n, st, pt, s3) : alglib::pspline3build(xy, n, st, pt, s3);
            alglib::pspline3parametervalues(s3, count, t);
        }
        std::vector<double> breaks(t.getcontent(), t.getcontent() + count);
        if (closed) breaks.push_back(1.0);  // a periodic spline's parameter runs over [0, 1)
        // Value and derivative at t (a node's derivative agrees on both sides: every type is C1).
        const auto jet = [&](double at, double* value, double* slope) {
            if (d == 2)
                alglib::pspline2diff(s2, at, value[0], slope[0], value[1], slope[1]);
            else
                alglib::pspline3diff(s3, at, value[0], slope[0], value[1], slope[1], value[2], slope[2]);
        };
        std::ostringstream o;
        o << "{\"format\":\"cagd-curve\",\"format_version\":1,\"library_version\":\"" << ALGLIB_VERSION
          << "\",\"registry\":\"\",\"method\":{\"closed\":" << (closed ? "true" : "false") << ",\"name\":\"alglib:"
          << configuration << "\",\"parameter\":\"" << parameter
          << " (ALGLIB's, on [0, 1])\",\"parameters\":{}},\"points\":[";
        for (int i = 0; i < n; ++i) o << (i ? "," : "") << point(&p[static_cast<std::size_t>(i * d)], d);
        o << "],\"dimension\":" << d << ",\"degree\":3,\"exact\":true,\"max_distance\":0,\"tolerance\":0,\"breaks\":[";
        for (std::size_t i = 0; i < breaks.size(); ++i) o << (i ? "," : "") << number(breaks[i]);
        o << "],\"pieces\":[";
        for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
            const double h = breaks[i + 1] - breaks[i];
            double a[3], da[3], b[3], db[3], c1[3], c2[3];
            jet(breaks[i], a, da);
            jet(breaks[i + 1] == 1.0 && closed ? 0.0 : breaks[i + 1], b, db);
            for (int k = 0; k < d; ++k) c1[k] = a[k] + h * da[k] / 3, c2[k] = b[k] - h * db[k] / 3;
            o << (i ? "," : "") << "[" << point(a, d) << "," << point(c1, d) << "," << point(c2, d) << ","
              << point(b, d) << "]";
        }
        o << "]}";
        return o.str();
    } catch (const alglib::ap_error& e) {
        return error_line("ALGLIB: " + e.msg);
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::string(argv[1]) == "--version") {
        std::cout << "alglib " << ALGLIB_VERSION << "\n";
        return 0;
    }
    std::string word, configuration, closedness;
    int n = 0, d = 0;
    while (std::cin >> word >> configuration >> closedness >> n >> d) {
        if (word != "curve" || n < 1 || n > 10'000'000 || d < 2 || d > 3) {
            std::cerr << "alglib adapter: a request \"" << word << " " << configuration << "\" of " << n
                      << " points of dimension " << d << "\n";
            return 2;
        }
        std::vector<double> p(static_cast<std::size_t>(n * d));
        for (double& v : p)
            if (!(std::cin >> v)) {
                std::cerr << "alglib adapter: a request ends before its " << n << " points\n";
                return 2;
            }
        std::cout << answer(configuration, closedness == "closed", n, d, p) << "\n";
    }
    std::cout.flush();
    return std::cout ? 0 : 1;
}
