// sb2_locality, section 3.2 (Figs. 3, 4): the blending function of p_0 in the interpolating
// B2- and S-spline (the interpolant of p_i = δ_{i0}) and their difference, measured per span.
#include <cmath>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::locality;

int main(int argc, char** argv) {
    repro::ArtifactRun run("sb2_locality", "interpolating_blending", "3.2",
                           "Interpolating blending functions and their difference (Figs. 3, 4)", argc, argv);
    auto fig3 = run.table("fig3.csv", {"u", "b2_m0", "b2_m1", "b2_m2", "b2_m3", "s_m0", "s_m1", "s_m2", "s_m3"});
    auto fig4 = run.table("fig4.csv", {"u", "diff_m0", "diff_m1", "diff_m2", "diff_m3"});
    auto spans = run.table("span_difference.csv", {"m", "span_start", "max_abs_s_minus_b2"});
    std::vector<BSplineCurve> b2, s;
    for (int m = 0; m <= 6; ++m) {
        b2.push_back(interpolating_blending_function(SplineForm::b2_spline, m));
        s.push_back(interpolating_blending_function(SplineForm::s_spline, m));
    }
    for (int k = -6 * 32; k <= 6 * 32; ++k) {
        const double u = k / 32.0;
        std::vector<double> r3{u}, r4{u};
        for (int m = 0; m <= 3; ++m) {
            const double bb = std::abs(u) <= m + 3 ? b2[m].point(u)(0) : 0.0;
            const double ss = std::abs(u) <= m + 3 ? s[m].point(u)(0) : 0.0;
            r3.insert(r3.begin() + 1 + m, bb);
            r3.push_back(ss);
            r4.push_back(ss - bb);
        }
        fig3.row(r3);
        fig4.row(r4);
    }
    double previous = INFINITY;
    bool shrinking = true;
    for (int m = 0; m <= 6; ++m) {
        double coincide = 0, overall = 0;
        int differing = 0;
        for (int a = -m - 3; a < m + 3; ++a) {
            const double d = analysis::max_distance_same_parameter(s[m], b2[m], a, a + 1, 129);
            spans.row({double(m), double(a), d});
            overall = std::max(overall, d);
            if ((a >= -m && a + 1 <= -1) || (a >= 1 && a + 1 <= m)) coincide = std::max(coincide, d);
            differing += d > 1e-12;
        }
        if (m >= 2 && m <= 5) {
            run.check("sec32.coincide.m" + std::to_string(m), coincide);
            run.check("sec32.differing_spans.m" + std::to_string(m), differing);
        }
        shrinking = shrinking && overall < previous;
        previous = overall;
        run.note("m = " + std::to_string(m) + ": max |S − B2| = " + format_number(overall, 4) + ", " +
                 std::to_string(differing) + " differing spans.");
    }
    run.check("sec32.difference_shrinks", shrinking ? 1.0 : 0.0);
    run.figure("fig3", "Fig. 3 — interpolating blending functions (B2 solid, S dashed), m = 0..3");
    run.figure("fig4", "Fig. 4 — interpolating S-spline blending function minus B2-spline blending function, m = 0..3");
    return run.finish();
}
