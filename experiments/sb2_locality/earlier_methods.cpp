// sb2_locality, section 3.4: the earlier extra-point rules I (eq 15), II(a) (eq 16),
// II(b) FMILL (eq 17) against the locality rule (eq 12), and eq (18).
// Data (chosen; the paper gives none): 10 open points of a wavy curve, unevenly spaced.
#include <cmath>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "cagd/numeric/rational.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::locality;

int main(int argc, char** argv) {
    repro::ArtifactRun run("sb2_locality", "earlier_methods", "3.4",
                           "Earlier extra-point rules I, II(a), II(b) and eq (18)", argc, argv);
    PointList p(10, 2);
    p << 0, 0, 1.1, 0.9, 2.0, 1.2, 3.2, 0.4, 4.0, -0.6, 5.3, -0.9, 6.1, 0.1, 7.0, 1.4, 8.4, 1.0, 9.0, 0.2;
    const double diag = bounding_box_diagonal(p);
    run.note(
        "Data: 10 points (0,0) (1.1,0.9) (2,1.2) (3.2,0.4) (4,−0.6) (5.3,−0.9) (6.1,0.1) (7,1.4) (8.4,1) (9,0.2), "
        "open, natural ends.");

    const auto w = extra_point_weights({1, 1});
    const double w0 = w.left(0) + w.right(0), w1 = w.left(1) + w.right(1);  // weights of q_{i,0}, q_{i,1}
    run.check("eq18.w0", w0);
    run.check("eq18.w1", w1);
    run.validate("eq18.closed_form", "eq (12) weight of q_{i,0} at m = 1 vs 1/(1+α)", w0, 1 / (1 + alpha()), 1e-15,
                 "rounding");
    run.check("eq18.w0_denominator", double(numeric::simplest_fraction_within(w0, 5e-4).denominator));
    run.check("eq18.w1_denominator", double(numeric::simplest_fraction_within(w1, 5e-4).denominator));
    run.check("eq16.w0_quarters", std::round(4 * w0) / 4);
    run.check("eq16.w1_quarters", std::round(4 * w1) / 4);

    double i_vs_m0 = 0;
    for (SplineForm f : {SplineForm::b2_spline, SplineForm::s_spline}) {
        Options a, b;
        a.form = b.form = f;
        a.m = {{0, 0}};
        b.rule = ExtraPointRule::method_I;
        i_vs_m0 = std::max(
            i_vs_m0, analysis::max_distance_same_parameter(interpolate(p, a).curve, interpolate(p, b).curve) / diag);
    }
    run.check("eq15.I_equals_m0", i_vs_m0);

    Options m1;
    m1.m = {{1, 1}};
    const auto s1 = interpolate(p, m1);
    const double a = alpha();
    double printed = 0, corrected = 0;
    for (int i = 1; i + 2 < 10; ++i) {
        const Eigen::RowVector2d q0 = 0.5 * (p.row(i) + p.row(i + 1));
        const Eigen::RowVector2d lib = s1.extra_points.row(i + 1);
        const Eigen::RowVector2d pr = q0 + a / (1 + a) * ((p.row(i + 1) - p.row(i)) - (p.row(i + 2) - p.row(i + 1)));
        const Eigen::RowVector2d co =
            q0 + a / (2 * (1 + a)) * ((p.row(i + 2) - p.row(i + 1)) - (p.row(i) - p.row(i - 1)));
        printed = std::max(printed, (pr - lib).norm() / diag);
        corrected = std::max(corrected, (co - lib).norm() / diag);
    }
    run.check("eq18.rearranged", printed, corrected);

    // Straight-line reproduction: uneven points on the line (1, 2) + s (0.6, 0.8).
    PointList line(7, 2);
    const double s[7] = {0, 0.4, 1.5, 1.9, 3.6, 4.0, 6.2};
    for (int i = 0; i < 7; ++i) line.row(i) << 1 + 0.6 * s[i], 2 + 0.8 * s[i];
    const auto off_line = [&](const Options& o) {
        const auto c = interpolate(line, o).curve;
        double worst = 0;
        for (int k = 0; k <= 600; ++k) {
            const Eigen::VectorXd x = c.point(6.0 * k / 600);
            worst = std::max(worst, std::abs(-0.8 * (x(0) - 1) + 0.6 * (x(1) - 2)));
        }
        return worst / 6.2;
    };
    Options fmill;
    fmill.rule = ExtraPointRule::fmill;
    run.check("sec34.m1_reproduces_lines", off_line(m1));
    run.check("sec34.fmill_reproduces_lines", off_line(fmill));
    const double fm_vs_m1 = analysis::max_distance_same_parameter(interpolate(p, fmill).curve, s1.curve) / diag;
    run.check("sec34.fmill_differs_from_m1", fm_vs_m1 > 1e-6 ? 1.0 : 0.0);
    run.note("FMILL vs m = 1 (S-spline): max distance " + format_number(fm_vs_m1, 4) +
             " of the diagonal. Rearranged m = 1 form with the correction of erratum E3: max |Δ| " +
             format_number(corrected, 3) + ".");
    return run.finish();
}
