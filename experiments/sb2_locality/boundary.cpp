// sb2_locality, section 3.3: end conditions by virtual points. Each promise is measured at
// the end points; the virtual points are also rebuilt here by hand from the paper's words
// and eq (12) applied to them, as an independent check of the library's extension.
// Data: the 10 points of the earlier-methods experiment (chosen).
#include <cmath>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::locality;

namespace {
double angle(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return std::atan2(std::abs(a(0) * b(1) - a(1) * b(0)), a.dot(b));
}
}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run("sb2_locality", "boundary", "3.3", "Boundary conditions by virtual points (section 3.3)",
                           argc, argv);
    PointList p(10, 2);
    p << 0, 0, 1.1, 0.9, 2.0, 1.2, 3.2, 0.4, 4.0, -0.6, 5.3, -0.9, 6.1, 0.1, 7.0, 1.4, 8.4, 1.0, 9.0, 0.2;
    const double diag = bounding_box_diagonal(p);
    const Eigen::Vector2d t0(1.0, 2.0), t1(1.0, -1.0);
    run.note("Data: the 10 points of `earlier_methods`; given tangents (1, 2) at the start and (1, −1) at the end.");
    auto tab = run.table("boundary.csv", {"form", "m", "kappa_start_natural", "kappa_end_natural",
                                          "angle_start_tangent", "angle_end_tangent", "angle_start_bessel"});
    double kappa = 0, tangent = 0, bessel = 0, eq12 = 0;
    for (SplineForm f : {SplineForm::b2_spline, SplineForm::s_spline})
        for (int m = 0; m <= 4; ++m) {
            Options o;
            o.form = f;
            o.m = {{m, m}};
            const auto nat = interpolate(p, o);
            const double k0 = analysis::curvature(nat.curve, 0.0) * diag,
                         k1 = analysis::curvature(nat.curve, 9.0) * diag;
            o.start.kind = o.end.kind = EndKind::tangent;
            o.start.tangent = t0;
            o.end.tangent = t1;
            const auto tan = interpolate(p, o).curve;
            const double a0 = angle(tan.jet(0.0, 1).row(1).transpose(), t0),
                         a1 = angle(tan.jet(9.0, 1).row(1).transpose(), t1);
            o.start.kind = o.end.kind = EndKind::bessel;
            const auto bes = interpolate(p, o).curve;
            const Eigen::VectorXd tb = bessel_tangent(p);
            const double ab = angle(bes.jet(0.0, 1).row(1).transpose(), tb);
            tab.row_text({f == SplineForm::s_spline ? "S" : "B2", std::to_string(m), format_number(k0),
                          format_number(k1), format_number(a0), format_number(a1), format_number(ab)});
            kappa = std::max({kappa, k0, k1});
            tangent = std::max({tangent, a0, a1});
            bessel = std::max(bessel, ab);
            // Virtual points by hand: p_{−k} = 2p_0 − p_k (natural); segment −1 and 0 extra points by eq (12).
            const auto P = [&](int k) -> Eigen::RowVector2d {
                return k >= 0 ? Eigen::RowVector2d(p.row(k)) : Eigen::RowVector2d(2 * p.row(0) - p.row(-k));
            };
            const double K = (1 - alpha()) / (1 - std::pow(alpha(), m + 1));
            for (int seg : {-1, 0}) {
                Eigen::RowVector2d d = Eigen::RowVector2d::Zero();
                for (int j = 0; j <= m; ++j) d += K * std::pow(alpha(), j) * 0.5 * (P(seg - j) + P(seg + j + 1));
                eq12 = std::max(eq12, (d - nat.extra_points.row(seg + 1)).norm() / diag);
            }
        }
    run.check("sec33.natural_zero_curvature", kappa);
    run.check("sec33.tangent_direction", tangent);
    run.check("sec33.bessel_direction", bessel);
    run.check("sec33.eq12_throughout", eq12);
    return run.finish();
}
