// hosaka section 4, eq (25)–(30): the tensor patch from corner derivatives (eq 27), its edge-curve
// form (eq 28, 29) and Coons' surface (S0 = 0), and the Cartesian patch over a grid (eq 30, Fig. 4).
// The paper prints no data here; ours (stated in the report):
//   corner data  m = 1 and m = 2 over the unit square: S(k, l) = (k, l, z_kl), z = 0, 0.5, 0.2, 1 at
//                (0,0), (1,0), (0,1), (1,1); S^{(1,0)} = (1, 0, 0.3 + 0.2k − 0.1l), S^{(0,1)} =
//                (0, 1, −0.2 + 0.1k + 0.3l); twists S^{(1,1)} = (0, 0, T_kl), T = 1.5, −1, −0.8, 1.2;
//                for m = 2 also S^{(2,0)} = (0, 0, 0.4), S^{(0,2)} = (0, 0, −0.3), the higher mixed
//                derivatives (0, 0, 0.5(i + j) (−1)^{k+l}).
//   grid         x = 0, 0.8, 1.5, 2.6, 3.2, 4; y = 0, 0.6, 1.5, 2.2, 3; heights and derivatives of
//                ζ = 0.5 sin(1.1x) cos(0.9y) at the nodes.
#include <cmath>
#include <numbers>
#include <string>

#include "cagd/surface/boundary_surface.hpp"
#include "cagd/surface/hosaka_patch.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::surface;

namespace {

CornerDerivatives corner_data(int m) {
    CornerDerivatives c(m, 3);
    const double z[2][2] = {{0.0, 0.2}, {0.5, 1.0}}, twist[2][2] = {{1.5, -0.8}, {-1.0, 1.2}};
    for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l) {
            c.at(k, l, 0, 0) = Eigen::Vector3d(k, l, z[k][l]);
            c.at(k, l, 1, 0) = Eigen::Vector3d(1, 0, 0.3 + 0.2 * k - 0.1 * l);
            c.at(k, l, 0, 1) = Eigen::Vector3d(0, 1, -0.2 + 0.1 * k + 0.3 * l);
            c.at(k, l, 1, 1) = Eigen::Vector3d(0, 0, twist[k][l]);
            for (int i = 0; i <= m; ++i)
                for (int j = 0; j <= m; ++j) {
                    if (i + j <= 1 || (i == 1 && j == 1)) continue;
                    if (j == 0)
                        c.at(k, l, i, j) = Eigen::Vector3d(0, 0, 0.4);
                    else if (i == 0)
                        c.at(k, l, i, j) = Eigen::Vector3d(0, 0, -0.3);
                    else
                        c.at(k, l, i, j) = Eigen::Vector3d(0, 0, 0.5 * (i + j) * ((k + l) % 2 ? -1 : 1));
                }
        }
    return c;
}

// ζ = 0.5 sin(1.1x) cos(0.9y) and its derivatives.
double grid_function(double x, double y, int i, int j) {
    return sinusoid(0.5, 1.1, 0.0)(x, i) * sinusoid(1.0, 0.9, std::numbers::pi / 2)(y, j);
}

}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run(
        "hosaka", "patches", "4",
        "Surface patches: tensor form (eq 27), edge-curve form and Coons (eq 28-29), Cartesian patch (eq 30)", argc,
        argv);

    double corner_error = 0, printed_28 = 0, corrected_28 = 0, coons_gap = 0, coons_twist = 0, data_twist = 0, size = 0;
    CsvWriter fig = run.table("fig_patches.csv", {"m", "u", "v", "x", "y", "z_eq27", "z_coons"});
    for (int m = 1; m <= 2; ++m) {
        const HosakaPatch patch(corner_data(m));
        const PatchEdges edges = patch.edges();
        const EdgeFormPatch full(m, edges, patch.corners()), coons(m, edges);
        const spline::HosakaBasis basis(m);
        for (int k = 0; k < 2; ++k)
            for (int l = 0; l < 2; ++l)
                for (int i = 0; i <= m; ++i)
                    for (int j = 0; j <= m; ++j) {
                        const Eigen::VectorXd& want = patch.corners().at(k, l, i, j);
                        size = std::max(size, want.norm());
                        corner_error = std::max(corner_error, (patch.derivative(k, l, i, j) - want).norm());
                        if (i >= 1 && j >= 1) {
                            coons_twist = std::max(coons_twist, coons.derivative(k, l, i, j).norm());
                            data_twist = std::max(data_twist, want.norm());
                        }
                    }
        for (int a = 0; a <= 20; ++a)
            for (int b = 0; b <= 20; ++b) {
                const double u = a / 20.0, v = b / 20.0;
                const Eigen::VectorXd s27 = patch.point(u, v), s28 = full.point(u, v), c = coons.point(u, v);
                // Eq (28) as printed: {R2(v) + R4(v) − R2(v)} f(u) in place of R2(v) + {R4(v) − R2(v)} f(u).
                const Eigen::VectorXd r2 = edges.r2->point(v) - edges.r2->point(0);
                const Eigen::VectorXd printed = s28 - (1 - basis.q(0, u, 0)) * r2;
                corrected_28 = std::max(corrected_28, (s28 - s27).norm());
                printed_28 = std::max(printed_28, (printed - s27).norm());
                coons_gap = std::max(coons_gap, (c - coons_boolean_sum(edges, m, u, v)).norm());
                fig.row({double(m), u, v, s27(0), s27(1), s27(2), c(2)});
                if (b == 20) fig.end_scan();
            }
        fig.end_scan();  // blank-line pair: gnuplot index m − 1
    }
    run.check("eq27.interpolates_corner_derivatives", corner_error / size);
    run.check("eq28.equals_eq27", printed_28 / size, corrected_28 / size);
    run.check("eq28.coons_equivalence", coons_gap / size);
    run.check("eq28.coons_zero_twist", coons_twist / data_twist);

    // Eq (30) over the grid, with exact node derivatives of our ζ (m = 1, 2).
    const std::vector<double> gx{0, 0.8, 1.5, 2.6, 3.2, 4}, gy{0, 0.6, 1.5, 2.2, 3};
    double printed_30 = 0, corrected_30 = 0, z_size = 0, jump = 0, jump_size = 0;
    for (int m = 1; m <= 2; ++m) {
        std::vector<Eigen::MatrixXd> nodes;
        for (double y : gy)
            for (double x : gx) {
                Eigen::MatrixXd n(m + 1, m + 1);
                for (int i = 0; i <= m; ++i)
                    for (int j = 0; j <= m; ++j) n(i, j) = grid_function(x, y, i, j);
                nodes.push_back(n);
            }
        const CartesianSurface s(m, gx, gy, nodes);
        const spline::HosakaBasis basis(m);
        for (int cx = 0; cx + 1 < static_cast<int>(gx.size()); ++cx)
            for (int cy = 0; cy + 1 < static_cast<int>(gy.size()); ++cy) {
                const double lx = gx[static_cast<std::size_t>(cx) + 1] - gx[static_cast<std::size_t>(cx)];
                const double ly = gy[static_cast<std::size_t>(cy) + 1] - gy[static_cast<std::size_t>(cy)];
                for (int k = 0; k < 2; ++k)
                    for (int l = 0; l < 2; ++l) {
                        const Eigen::MatrixXd& want = s.node(cx + k, cy + l);
                        // The printed eq (30) subtracts the ζ_11 terms: it equals ours minus twice them.
                        double z11_terms = 0;
                        for (int i = 0; i <= m; ++i)
                            for (int j = 0; j <= m; ++j)
                                z11_terms += std::pow(lx, i) * std::pow(ly, j) * s.node(cx + 1, cy + 1)(i, j) *
                                             basis.q(i, k, 0) * basis.q(j, l, 0);
                        printed_30 = std::max(
                            printed_30, std::abs(s.derivative_in(cx, cy, k, l, 0, 0) - 2 * z11_terms - want(0, 0)));
                        z_size = std::max(z_size, std::abs(want(0, 0)));
                        for (int i = 0; i <= m; ++i)
                            for (int j = 0; j <= m; ++j)
                                corrected_30 =
                                    std::max(corrected_30, std::abs(s.derivative_in(cx, cy, k, l, i, j) - want(i, j)) /
                                                               (1 + std::abs(want(i, j))));
                    }
                // Continuity across the cell's right edge (x = const) of ζ^{(a,b)}, a ≤ m, b ≤ 2.
                if (cx + 2 < static_cast<int>(gx.size()))
                    for (double v : {0.25, 0.5, 0.9})
                        for (int a = 0; a <= m; ++a)
                            for (int b = 0; b <= 2; ++b) {
                                const double left = s.derivative_in(cx, cy, 1.0, v, a, b),
                                             right = s.derivative_in(cx + 1, cy, 0.0, v, a, b);
                                jump = std::max(jump, std::abs(left - right));
                                jump_size = std::max(jump_size, std::abs(left));
                            }
            }
    }
    run.check("eq30.interpolates_node_derivatives", printed_30 / z_size, corrected_30);
    run.validate(
        "eq30.continuity_across_grid_lines",
        "eq (30): ζ^(a,b), a ≤ m, b ≤ 2, continuous across x = const grid lines (largest jump, relative), m = 1, 2",
        jump / jump_size, 0.0, 1e-12, "rounding");

    // Fig. 4: the m = 1 surface over the grid from heights only (section 7 (iv) node derivatives).
    Eigen::MatrixXd heights(static_cast<Eigen::Index>(gx.size()), static_cast<Eigen::Index>(gy.size()));
    for (std::size_t a = 0; a < gx.size(); ++a)
        for (std::size_t b = 0; b < gy.size(); ++b)
            heights(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = grid_function(gx[a], gy[b], 0, 0);
    const CartesianSurface from_heights = cartesian_spline_surface(gx, gy, heights);
    CsvWriter g = run.table("fig_cartesian.csv", {"x", "y", "z", "z_exact"});
    double worst = 0;
    for (int a = 0; a <= 40; ++a)
        for (int b = 0; b <= 30; ++b) {
            const double x = gx.back() * a / 40.0, y = gy.back() * b / 30.0, z = from_heights.value(x, y),
                         exact = grid_function(x, y, 0, 0);
            worst = std::max(worst, std::abs(z - exact));
            g.row({x, y, z, exact});
            if (b == 30) g.end_scan();
        }
    std::string grid_note = "Fig. 4 analogue: the m = 1 Cartesian surface from the ";
    grid_note += std::to_string(gx.size()) + " × " + std::to_string(gy.size()) +
                 " heights alone (node derivatives from natural splines along the grid lines, section 7 (iv)) differs "
                 "from ζ by at most " +
                 format_number(worst, 3) + " on a 41 × 31 sampling: [fig_cartesian.csv](hosaka/fig_cartesian.csv).";
    run.note(grid_note);
    run.note(
        "The twist of the eq (27) patch at the corners is the data's; Coons' surface (eq 28 with S0 = 0) has every "
        "corner derivative S^(i,j), i, j ≥ 1, "
        "zero (relative size " +
        format_number(coons_twist / data_twist, 3) +
        "), while keeping the edges: [fig_patches.csv](hosaka/fig_patches.csv).");
    run.figure("fig_patches",
               "The m = 1 tensor patch of eq (27) from our corner data (left) and Coons' surface with the same edges "
               "(eq 28 with S0 = 0, right): zero twist flattens the corners.");
    run.figure("fig_cartesian",
               "Fig. 4 analogue: the Cartesian surface of eq (30) (m = 1) over our 6 × 5 grid, node derivatives from "
               "splines along the grid lines.");
    return run.finish();
}
