// sb2_locality, section 3.1: as m → ∞ the S-/B2-spline interpolants tend to the conventional
// interpolating cubic B-spline of eq (10); measured per m, and the limit validated against a
// peer implementation (Boost.Math cardinal_cubic_b_spline) away from the ends, where the two
// end conditions (ours natural, Boost's estimated end derivatives) no longer matter.
// Data (chosen): 61 points p_i = (i + 0.3 sin 0.9i, sin 0.45i + 0.4 cos 1.3i), i = 0..60.
#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <cmath>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::locality;

int main(int argc, char** argv) {
    repro::ArtifactRun run("sb2_locality", "convergence", "3.1",
                           "Convergence to the conventional interpolant as m grows (eq 10)", argc, argv);
    const int n = 61;
    PointList p(n, 2);
    for (int i = 0; i < n; ++i) p.row(i) << i + 0.3 * std::sin(0.9 * i), std::sin(0.45 * i) + 0.4 * std::cos(1.3 * i);
    const double diag = bounding_box_diagonal(p);
    run.note("Data: 61 points p_i = (i + 0.3 sin 0.9i, sin 0.45i + 0.4 cos 1.3i); distances relative to the diagonal " +
             format_number(diag, 6) + ".");
    const BSplineCurve open_ref = cubic_bspline_interpolant(p, false), closed_ref = cubic_bspline_interpolant(p, true);
    auto tab = run.table("fig_convergence.csv", {"m", "s_open", "b2_open", "s_closed", "b2_closed", "alpha_reference"});
    bool monotone = true;
    double prev_s = INFINITY, prev_b2 = INFINITY;
    const auto distance = [&](SplineForm f, int m, bool closed) {
        Options o;
        o.form = f;
        o.m = {{m, m}};
        o.closed = closed;
        return analysis::max_distance_same_parameter(interpolate(p, o).curve, closed ? closed_ref : open_ref, 16) /
               diag;
    };
    for (int m = 0; m <= 12; ++m) {
        const double so = distance(SplineForm::s_spline, m, false), bo = distance(SplineForm::b2_spline, m, false);
        tab.row({double(m), so, bo, distance(SplineForm::s_spline, m, true), distance(SplineForm::b2_spline, m, true),
                 0.1 * std::pow(std::abs(alpha()), m)});
        monotone = monotone && so < prev_s && bo < prev_b2;
        prev_s = so;
        prev_b2 = bo;
        if (m == 5)
            run.note("m = 5: max distance to eq (10) = " + format_number(so, 3) + " (S), " + format_number(bo, 3) +
                     " (B2) of the diagonal.");
    }
    run.check("sec31.monotone_convergence", monotone ? 1.0 : 0.0);
    run.check("sec31.limit_s_open", distance(SplineForm::s_spline, 60, false));
    run.check("sec31.limit_b2_open", distance(SplineForm::b2_spline, 60, false));
    run.check("sec31.limit_s_closed", distance(SplineForm::s_spline, 60, true));
    run.check("sec31.limit_b2_closed", distance(SplineForm::b2_spline, 60, true));

    // Peer: Boost's cardinal cubic B-spline of x(u) and y(u), compared on u ∈ [20, 40].
    std::vector<double> xs(n), ys(n);
    for (int i = 0; i < n; ++i) {
        xs[i] = p(i, 0);
        ys[i] = p(i, 1);
    }
    const boost::math::interpolators::cardinal_cubic_b_spline<double> bx(xs.data(), xs.size(), 0.0, 1.0),
        by(ys.data(), ys.size(), 0.0, 1.0);
    Options o;
    o.m = {{60, 60}};
    const BSplineCurve s60 = interpolate(p, o).curve;
    double peer_eq10 = 0, peer_s60 = 0;
    for (int k = 0; k <= 20 * 16; ++k) {
        const double u = 20.0 + k / 16.0;
        const Eigen::Vector2d boost_point(bx(u), by(u));
        peer_eq10 = std::max(peer_eq10, (open_ref.point(u) - boost_point).norm() / diag);
        peer_s60 = std::max(peer_s60, (s60.point(u) - boost_point).norm() / diag);
    }
    run.validate("sec31.peer_eq10",
                 "eq (10) interpolant vs Boost cardinal_cubic_b_spline on u ∈ [20, 40] (max distance / diag)",
                 peer_eq10, 0.0, 1e-9, "end conditions differ; their influence decays like |α|^20 ≈ 4e-12");
    run.validate("sec31.peer_s_m60",
                 "S-spline m = 60 vs Boost cardinal_cubic_b_spline on u ∈ [20, 40] (max distance / diag)", peer_s60,
                 0.0, 1e-9, "end conditions differ; their influence decays like |α|^20 ≈ 4e-12");
    run.figure("fig_convergence",
               "Max distance to the conventional interpolant (eq 10) against m (log scale), with the reference line "
               "0.1 |α|^m, |α| = " +
                   format_number(std::abs(alpha()), 7));
    return run.finish();
}
