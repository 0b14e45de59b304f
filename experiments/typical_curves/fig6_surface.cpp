// typical_curves section 5, Fig. 6: a nonstationary typical surface — a 25×25 control net with
// fixed edge lengths, each new control point placed by the rotation of its control polygon about the
// diagonal, the boundaries P_{i,0} and P_{0,j} from scale-1 typical polygons of planar log-aesthetic
// curves with α = −0.5 and α = −0.6, 0.01° per polygon — the bi-degree-24 Bézier patch and its
// Gaussian and mean curvature.
// Our choices (the paper gives none): boundary length L = 1 (edges 1/24), P_{i,0} in the x–z plane
// and P_{0,j} in the y–z plane, both leaving the origin along +x and +y and bending towards −z; every
// polygon turned by +0.01° (right-handed about P_{i+1,j} → P_{i,j+1}) from its parallelogram position.
// Curvature maps on a 51×51 grid; H signed with the normal S_u × S_v.
#include <cmath>
#include <numbers>

#include "cagd/aesthetic/typical_surface.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/analysis/surface_curvature.hpp"
#include "cagd/spline/bezier.hpp"
#include "cagd/surface/bezier_patch.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;

int main(int argc, char** argv) {
    repro::ArtifactRun run("typical_curves", "fig6_surface", "5",
                           "Fig. 6: nonstationary typical surface, 25×25 control points, boundaries α = −0.5 (v = 0) "
                           "and −0.6 (u = 0), 0.01° per polygon (section 5)",
                           argc, argv);
    const double alpha_u = -0.5, alpha_v = -0.6, L = 1.0, pi = std::numbers::pi, angle = 0.01 * pi / 180.0;
    const int degree = 24, grid = 51;
    const surface::ControlNet net = aesthetic::log_aesthetic_typical_net(alpha_u, alpha_v, L, degree, angle);
    const surface::BezierPatch patch(net);
    auto p = [&](int i, int j) { return patch.control_point(i, j); };

    // Edge lengths and the two readings of the second condition (ERRATA typical_curves-E15).
    const double ds = L / degree;
    double edge_dev = 0.0, printed_dev = 0.0, corrected_dev = 0.0;
    for (int i = 0; i <= degree; ++i)
        for (int j = 0; j <= degree; ++j) {
            if (i < degree) edge_dev = std::max(edge_dev, std::abs((p(i + 1, j) - p(i, j)).norm() - ds) / ds);
            if (j < degree) edge_dev = std::max(edge_dev, std::abs((p(i, j + 1) - p(i, j)).norm() - ds) / ds);
            if (i < degree && j < degree) {
                const double side = (p(i + 1, j + 1) - p(i + 1, j)).norm();
                printed_dev = std::max(printed_dev, std::abs((p(i + 1, j + 1) - p(i, j)).norm() - side) / ds);
                corrected_dev = std::max(corrected_dev, std::abs((p(i, j + 1) - p(i, j)).norm() - side) / ds);
            }
        }
    run.check("fig6.edge_lengths_fixed", edge_dev);
    run.check("fig6.second_condition_holds", printed_dev <= 1e-12 ? 1.0 : 0.0, corrected_dev <= 1e-12 ? 1.0 : 0.0);
    run.note(
        "Second condition of section 5 over the 576 control polygons, relative to the edge 1/24: as printed, | "
        "|P(i,j)P(i+1,j+1)| − |P(i+1,j)P(i+1,j+1)| | up to " +
        format_number(printed_dev, 3) + "; corrected (|P(i,j)P(i,j+1)| = |P(i+1,j)P(i+1,j+1)|) up to " +
        format_number(corrected_dev, 3) + ".");

    // Evaluation: basis-matrix grid against de Casteljau.
    std::vector<double> ts;
    for (int k = 0; k < grid; ++k) ts.push_back(static_cast<double>(k) / (grid - 1));
    const surface::SurfaceGrid g = patch.evaluate_grid(ts, ts);
    double eval_dev = 0.0;
    for (int a = 0; a < grid; a += 10)
        for (int b = 0; b < grid; b += 10) {
            const analysis::SurfaceJet2 x = g.jet(a, b), y = patch.jet_de_casteljau(ts[static_cast<std::size_t>(a)],
                                                                                    ts[static_cast<std::size_t>(b)]);
            const Eigen::Vector3d* xs[6] = {&x.s, &x.su, &x.sv, &x.suu, &x.suv, &x.svv};
            const Eigen::Vector3d* ys[6] = {&y.s, &y.su, &y.sv, &y.suu, &y.suv, &y.svv};
            for (int k = 0; k < 6; ++k)
                eval_dev = std::max(eval_dev, (*xs[k] - *ys[k]).norm() / std::max(1.0, ys[k]->norm()));
        }
    run.validate("patch_grid_vs_de_casteljau",
                 "bi-24 patch: S and its derivatives to 2nd order by basis matrices against de Casteljau (rows, then "
                 "columns), 36 parameter pairs (largest difference relative to "
                 "max(1, |value|))",
                 eval_dev, 0.0, 1e-11, "rounding, growing with degree² for 2nd derivatives (measured ≤ 1e-12)");

    // Curvature maps; the Weingarten route with differences of the unit normal as the check.
    CsvWriter surf = run.table("fig6_surface.csv", {"u", "v", "x", "y", "z", "gaussian", "mean"});
    double kmin = 1e300, kmax = -1e300, hmin = 1e300, hmax = -1e300, weingarten_dev = 0.0;
    const double h = 1e-5;
    for (int a = 0; a < grid; ++a) {
        for (int b = 0; b < grid; ++b) {
            const analysis::SurfaceJet2 j = g.jet(a, b);
            const analysis::SurfaceCurvatures c = analysis::surface_curvatures(j);
            kmin = std::min(kmin, c.gaussian), kmax = std::max(kmax, c.gaussian), hmin = std::min(hmin, c.mean),
            hmax = std::max(hmax, c.mean);
            surf.row({ts[static_cast<std::size_t>(a)], ts[static_cast<std::size_t>(b)], j.s(0), j.s(1), j.s(2),
                      c.gaussian, c.mean});
            const double u = ts[static_cast<std::size_t>(a)], v = ts[static_cast<std::size_t>(b)];
            if (a % 5 == 0 && b % 5 == 0 && u > h && u < 1 - h && v > h && v < 1 - h) {
                const Eigen::Vector3d nu =
                    (analysis::unit_normal(patch.jet(u + h, v)) - analysis::unit_normal(patch.jet(u - h, v))) / (2 * h);
                const Eigen::Vector3d nv =
                    (analysis::unit_normal(patch.jet(u, v + h)) - analysis::unit_normal(patch.jet(u, v - h))) / (2 * h);
                const analysis::SurfaceCurvatures w = analysis::surface_curvatures_weingarten(j.su, j.sv, nu, nv);
                weingarten_dev =
                    std::max({weingarten_dev, std::abs(w.gaussian - c.gaussian), std::abs(w.mean - c.mean)});
            }
        }
        surf.end_scan();
    }
    run.validate("curvature_weingarten",
                 "K and H from the second fundamental form against the Weingarten route with central differences (h = "
                 "1e-5) of the unit normal, interior grid points (largest "
                 "absolute difference)",
                 weingarten_dev, 0.0, 1e-6,
                 "central differences: O(h²) truncation and O(ε/h) rounding (measured ≤ 1e-8)");
    run.note("On the 51×51 grid: Gaussian curvature K ∈ [" + format_number(kmin, 4) + ", " + format_number(kmax, 4) +
             "], mean curvature H ∈ [" + format_number(hmin, 4) + ", " + format_number(hmax, 4) +
             "] (normal S_u × S_v).");

    // The boundary curves S(u, 0), S(0, v) are the degree-24 Bézier curves of the boundary polygons.
    {
        Eigen::MatrixXd bu(degree + 1, 2), bv(degree + 1, 2);
        for (int i = 0; i <= degree; ++i) {
            bu.row(i) << net[0](i, 0), net[2](i, 0);
            bv.row(i) << net[1](0, i), net[2](0, i);
        }
        const double su = analysis::lcg_slope(BezierCurve(bu), 0.05, 0.95, 400).slope,
                     sv = analysis::lcg_slope(BezierCurve(bv), 0.05, 0.95, 400).slope;
        run.note("LCG slopes of the boundary curves (degree 24, fit t ∈ [0.05, 0.95]): v = 0 (α = −0.5): " +
                 format_number(su, 4) + "; u = 0 (α = −0.6): " + format_number(sv, 4) + ".");
    }

    // Net and the effect of the angle.
    CsvWriter net_csv = run.table("fig6_net.csv", {"i", "j", "x", "y", "z"});
    for (int i = 0; i <= degree; ++i) {
        for (int j = 0; j <= degree; ++j)
            net_csv.row({static_cast<double>(i), static_cast<double>(j), net[0](i, j), net[1](i, j), net[2](i, j)});
        net_csv.end_scan();
    }
    {
        CsvWriter t = run.table("fig6_angle_effect.csv",
                                {"angle_deg", "corner_shift", "gaussian_min", "gaussian_max", "mean_min", "mean_max"});
        const surface::ControlNet flat = aesthetic::log_aesthetic_typical_net(alpha_u, alpha_v, L, degree, 0.0);
        for (double deg : {0.0, 0.01, 0.1, 1.0}) {
            const surface::ControlNet nd =
                aesthetic::log_aesthetic_typical_net(alpha_u, alpha_v, L, degree, deg * pi / 180.0);
            const surface::BezierPatch pd(nd);
            const surface::SurfaceGrid gd = pd.evaluate_grid(ts, ts);
            double k0 = 1e300, k1 = -1e300, h0 = 1e300, h1 = -1e300;
            for (int a = 0; a < grid; ++a)
                for (int b = 0; b < grid; ++b) {
                    const analysis::SurfaceCurvatures c = analysis::surface_curvatures(gd.jet(a, b));
                    k0 = std::min(k0, c.gaussian), k1 = std::max(k1, c.gaussian), h0 = std::min(h0, c.mean),
                    h1 = std::max(h1, c.mean);
                }
            const Eigen::Vector3d shift(nd[0](degree, degree) - flat[0](degree, degree),
                                        nd[1](degree, degree) - flat[1](degree, degree),
                                        nd[2](degree, degree) - flat[2](degree, degree));
            t.row({deg, shift.norm(), k0, k1, h0, h1});
        }
    }
    // Top left of Fig. 6: one control polygon and the circle of its fourth point.
    {
        CsvWriter t = run.table("fig6_diagonal.csv", {"kind", "x", "y", "z"});
        const Eigen::Vector3d p00(0, 0, 0), p10(1, 0, 0.15), p01(0.1, 1, 0.1);
        for (const auto& [kind, q] :
             {std::pair{"given", p00},
              {"given", p10},
              {"given", p01},
              {"parallelogram", aesthetic::rotated_fourth_point(p00, p10, p01, 0.0)},
              {"turned_40deg", aesthetic::rotated_fourth_point(p00, p10, p01, 40.0 * pi / 180.0)}})
            t.row_text({kind, format_number(q(0)), format_number(q(1)), format_number(q(2))});
        for (int k = 0; k <= 72; ++k) {
            const Eigen::Vector3d q = aesthetic::rotated_fourth_point(p00, p10, p01, 2.0 * pi * k / 72);
            t.row_text({"circle", format_number(q(0)), format_number(q(1)), format_number(q(2))});
        }
    }
    run.figure("fig6",
               "Fig. 6 redrawn: one control polygon and the circle on which its fourth point turns about the diagonal "
               "(top left); the 25×25 net and the bi-24 patch (top right); "
               "Gaussian (bottom left) and mean curvature (bottom right) over (u, v).");
    return run.finish();
}
