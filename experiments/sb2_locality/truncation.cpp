// sb2_locality, section 3.1–3.2: truncating the series (eq 12), its effect on the
// coincidence condition (eq 13, six printed weights, the 0.1 % statement) and eq (14).
// Our weights come from the closed form in the library (truncation_weights); each is
// validated against an independent computation that applies the (1,4,1)/6 stencil to the
// eq (12) weight vectors (truncation_weights_by_stencil).
#include <cmath>

#include "cagd/locality/locality_spline.hpp"
#include "cagd/repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::locality;

int main(int argc, char** argv) {
    repro::ArtifactRun run("sb2_locality", "truncation", "3.1", "Truncated series and its error (eq 12–14)", argc, argv);
    auto tab = run.table("truncation_weights.csv", {"m", "w0", "wm", "wm1", "relative_error"});
    int smallest = -1;
    for (int m = 1; m <= 10; ++m) {
        const Eigen::Vector3d w = truncation_weights(m);
        const auto stencil = truncation_weights_by_stencil(m);
        const double err = std::abs(w(0) - 1) + std::abs(w(1)) + std::abs(w(2));
        tab.row({double(m), w(0), w(1), w(2), err});
        if (smallest < 0 && err < 1e-3) smallest = m;
        if (m == 4 || m == 5) {
            const std::string k = "eq13.m" + std::to_string(m);
            run.check(k + ".w0", w(0));
            run.check(k + ".wm", w(1));
            run.check(k + ".wm1", w(2));
            run.validate(k + ".stencil", "closed form vs (1,4,1)/6 stencil on eq (12) weights (max |Δ|, and no other q_{i,j} left)",
                         std::max((w - stencil.weights).cwiseAbs().maxCoeff(), stencil.largest_other), 0.0, 1e-15, "rounding (a dozen terms)");
        }
        if (m == 5) run.check("eq13.m5_within_0_1_percent", err < 1e-3 ? 1.0 : 0.0);
    }
    run.check("eq13.smallest_m_within_0_1_percent", smallest);
    double sum_dev = 0;
    for (int m = 0; m <= 20; ++m) {
        const auto w = extra_point_weights({m, m});
        sum_dev = std::max(sum_dev, std::abs(w.left.sum() + w.right.sum() - 1.0));
    }
    run.check("eq12.weights_sum_to_one", sum_dev);
    // eq (14): build the interpolant of p_i = (i, δ_{i0}) and read its extra control points.
    double eq14 = 0;
    for (int m = 0; m <= 6; ++m) {
        const int half = m + 3;
        PointList p = PointList::Zero(2 * half + 1, 2);
        for (int i = 0; i <= 2 * half; ++i) p(i, 0) = i - half;
        p(half, 1) = 1.0;
        Options o;
        o.m = {{m, m}};
        const auto s = interpolate(p, o);
        const double K = (1 - alpha()) / (1 - std::pow(alpha(), m + 1));
        for (int i = 0; i <= m + 1; ++i) {
            const double expect = i <= m ? K * std::pow(alpha(), i) / 2 : 0.0;
            // extra_points row r is segment r−1; d_{2i+1} is segment half+i, d_{−2i−1} segment half−i−1.
            eq14 = std::max({eq14, std::abs(s.extra_points(half + i + 1, 1) - expect), std::abs(s.extra_points(half - i, 1) - expect)});
        }
    }
    run.check("eq14.extra_points", eq14);
    run.note("Relative error of eq (9) after truncation, |w0 − 1| + |w_m| + |w_{m+1}|, per m: see truncation_weights.csv.");
    return run.finish();
}
