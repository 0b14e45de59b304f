// typical_curves sections 3.1–3.3 (eq 16–28): nonstationary typical Bézier control polygons — the
// scale-1 construction, the constant-rotation construction, the log spiral and the clothoid.
// Data (ours; the paper gives none): α = −0.5 and α = 1.5, total length L = 1, degrees 24 … 999;
// log spiral a = 0.2, b = 1, Δθ = 0.1; clothoid θ = a²s²/2 with a = 1.3, Δs = 0.01, Δθ = −0.02.
#include <cmath>

#include "cagd/aesthetic/class_a.hpp"
#include "cagd/aesthetic/log_aesthetic_curve.hpp"
#include "cagd/aesthetic/typical_bezier.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/spline/bezier.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::aesthetic;

int main(int argc, char** argv) {
    repro::ArtifactRun run("typical_curves", "typical_bezier", "3.1",
                           "Nonstationary typical Bézier polygons: scale-1 and constant-rotation constructions, log "
                           "spiral, clothoid (sections 3.1–3.3, eq 16–28)",
                           argc, argv);

    // ---- 3.1: scale 1.
    double worst_printed17 = 0, worst_corrected17 = 0, total_printed = 0, total_corrected = 0;
    for (double alpha : {-0.5, 1.5})
        for (int n : {24, 99}) {
            const double ds = 1.0 / n, e = (alpha - 1) / alpha;
            const TypicalPolygon p = scale_one_typical_polygon(alpha, 1.0, n);
            const PlanarTransitions tr = planar_transitions(p.points);  // measured from the points
            for (std::size_t j = 0; j + 2 < static_cast<std::size_t>(n); ++j) {
                const double jj = static_cast<double>(j);
                const double printed = alpha * std::pow((jj + 2) * ds, e) - alpha * std::pow((jj + 1) * ds, e);
                const double corrected = alpha * std::pow((jj + 1) * ds, e) - alpha * std::pow(jj * ds, e);
                worst_printed17 = std::max(worst_printed17, std::abs(printed - tr.rotations[j]));
                worst_corrected17 = std::max(worst_corrected17, std::abs(corrected - tr.rotations[j]));
            }
            double turned = 0;
            for (double r : tr.rotations) turned += r;
            total_printed = std::max(total_printed, std::abs(std::pow((n - 1) * ds, e) - turned));
            total_corrected = std::max(total_corrected, std::abs(alpha * std::pow((n - 1) * ds, e) - turned));
        }
    run.check("eq17.rotation_of_m_j", worst_printed17, worst_corrected17);
    run.check("sec3.1.total_rotation", total_printed, total_corrected);

    // (18)–(19): first-order rotation; its accuracy depends on j, not on Δs.
    {
        const double alpha = -0.5;
        auto exact = [&](double ds, int j) {
            return alpha * (std::pow((j + 2) * ds, (alpha - 1) / alpha) - std::pow((j + 1) * ds, (alpha - 1) / alpha));
        };
        CsvWriter t = run.table("eq18_accuracy.csv", {"j", "ds", "rel_error_eq18", "rel_error_eq19"});
        double rel18_small_ds = 0, rel18_large_j = 0, rel19_small_ds = 0, rel19_large_j = 0;
        for (double ds : {1e-2, 1e-4, 1e-6})
            for (int j : {0, 1, 10, 100, 1000, 10000}) {
                const double r18 = std::abs(first_order_rotation(alpha, ds, j) - exact(ds, j)) / std::abs(exact(ds, j));
                const double r19 = std::abs(first_order_rotation_ratio(alpha, j) - exact_rotation_ratio(alpha, j)) /
                                   exact_rotation_ratio(alpha, j);
                t.row({static_cast<double>(j), ds, r18, r19});
                if (ds == 1e-6 && j == 0) rel18_small_ds = r18, rel19_small_ds = r19;
                if (ds == 1e-2 && j == 10000) rel18_large_j = r18, rel19_large_j = r19;
            }
        run.check("eq18.small_ds", rel18_small_ds, rel18_large_j);
        run.check("eq19.small_ds", rel19_small_ds, rel19_large_j);
    }

    // ---- 3.2: constant rotation.
    {
        double worst20 = 0, worst22 = 0, worst_rot = 0, worst_len = 0;
        for (double alpha : {-0.5, 1.5, 3.0}) {
            const int n = 49;
            const TypicalPolygon p = constant_rotation_typical_polygon(alpha, 1.0, n);
            const PlanarTransitions tr = planar_transitions(p.points);
            double len = 0;
            for (double l : p.edge_lengths) len += l;
            worst_len = std::max(worst_len, std::abs(len - 1.0));
            const double dtheta = tr.rotations[0];
            for (std::size_t j = 0; j < tr.rotations.size(); ++j) {
                const double jj = static_cast<double>(j);
                worst_rot = std::max(worst_rot, std::abs(tr.rotations[j] - dtheta));
                worst22 = std::max(worst22,
                                   std::abs(tr.scales[j] - constant_rotation_scale_ratio(alpha, static_cast<int>(j))));
                // eq (20) with a = α, evaluated at the edge lengths the polygon has.
                const double ds = p.edge_lengths[j];
                const double rhs = alpha * (alpha - 1) / alpha * std::pow((jj + 1) * ds, -1 / alpha) * ds;
                worst20 = std::max(worst20, std::abs(rhs - dtheta) / std::abs(dtheta));
            }
        }
        run.check("eq21.solves_eq20", worst20);
        run.check("sec3.2.constant_rotation", worst_rot);
        run.check("eq22.scale_ratio", worst22);
        run.validate(
            "constant_rotation_length",
            "the constant-rotation polygon has the requested length L = 1 (Δθ solved in closed form), largest error",
            worst_len, 0.0, 1e-13, "rounding");
    }

    // ---- 3.3.1: the log spiral has a stationary matrix.
    {
        const double a = 0.2, b = 1.0, dtheta = 0.1;
        const TypicalPolygon p = log_spiral_polygon(a, b, dtheta, 30);
        double dev = 0, scale_err = 0;
        for (std::size_t j = 0; j < p.rotations.size(); ++j) {
            dev = std::max({dev, std::abs(p.rotations[j] - p.rotations[0]), std::abs(p.scales[j] - p.scales[0])});
            scale_err = std::max(scale_err, std::abs(p.scales[j] - std::exp(a * dtheta / b)));
        }
        run.check("sec3.3.1.log_spiral_stationary", dev);
        run.check("sec3.3.1.log_spiral_scale", scale_err);
        run.check("sec3.3.1.log_spiral_class_a", typical_matrix_condition(p.rotations[0], p.scales[0]) ? 1.0 : 0.0);
    }

    // ---- 3.3.2: the clothoid, θ = a²s²/2 (κ = a²s: eq 8 with α = −1, c0 = a², c1 = 0).
    {
        const double a = 1.3, ds = 0.01, dtheta = -0.02;
        LogAestheticParameters cp;
        cp.alpha = -1.0;
        cp.c0 = a * a;
        cp.c1 = 0.0;
        cp.length = 2.0;
        const LogAestheticCurve clothoid(cp);
        double e25 = 0, e26_printed = 0, e26_corrected = 0;
        for (int j = 0; j < 100; ++j) {
            const double jj = j;
            e25 = std::max(e25, std::abs(a * a * (jj + 1) * ds * ds - clothoid.curvature((jj + 1) * ds) * ds));
            const double ratio25 = (a * a * (jj + 2) * ds * ds) / (a * a * (jj + 1) * ds * ds);
            e26_printed = std::max(e26_printed, std::abs(std::pow((jj + 2) / (jj + 1), 2) - ratio25));
            e26_corrected = std::max(e26_corrected, std::abs(first_order_rotation_ratio(-1.0, j) - ratio25));
        }
        run.check("eq25.clothoid_rotation", e25);
        run.check("eq26.ratio", e26_printed, e26_corrected);
        // (27) as printed vs (25) solved for Δs_j, and vs eq (21) at α = −1 (a = α = −1, signed Δθ).
        const TypicalPolygon p = constant_rotation_typical_polygon_by_angle(-1.0, dtheta, 20);
        double e27_vs25 = 0, e27_vs21 = 0, e28 = 0;
        for (int j = 0; j < 20; ++j) {
            const double jj = j;
            const double printed_a = std::pow(jj + 1, -0.5) * std::sqrt(std::abs(dtheta) / (2 * a));
            const double from25 = std::pow(jj + 1, -0.5) * std::sqrt(std::abs(dtheta) / (a * a));
            const double printed_alpha = std::pow(jj + 1, -0.5) * std::sqrt(dtheta / (2 * -1.0));
            e27_vs25 = std::max(e27_vs25, std::abs(printed_a - from25) / from25);
            e27_vs21 = std::max(e27_vs21, std::abs(printed_alpha - p.edge_lengths[static_cast<std::size_t>(j)]) /
                                              p.edge_lengths[static_cast<std::size_t>(j)]);
            if (j + 1 < 20)
                e28 = std::max(e28, std::abs(std::sqrt((jj + 1) / (jj + 2)) - p.scales[static_cast<std::size_t>(j)]));
        }
        run.check("eq27.consistent_with_eq25", e27_vs25, e27_vs21);
        run.check("eq28.scale_ratio", e28);
    }

    // ---- The two constructions converge to log-aesthetic curves of slope α, but to different pieces.
    {
        CsvWriter t = run.table("construction_comparison.csv", {"alpha", "degree", "construction", "total_turning",
                                                                "end_x", "end_y", "lcg_slope_interior"});
        for (double alpha : {-0.5, 1.5})
            for (int n : {99, 999}) {
                const TypicalPolygon s1 = scale_one_typical_polygon(alpha, 1.0, n),
                                     cr = constant_rotation_typical_polygon(alpha, 1.0, n);
                for (const auto& [name, poly] :
                     {std::pair<std::string, const TypicalPolygon*>{"scale1", &s1}, {"rotation", &cr}}) {
                    double turned = 0;
                    for (double r : poly->rotations) turned += r;
                    const BezierCurve c(poly->points, 0, 1, BezierEvaluation::bernstein);
                    const double slope = analysis::lcg_slope(c, 0.05, 0.95, 200).slope;
                    const Eigen::RowVectorXd end = poly->points.row(poly->points.rows() - 1);
                    t.row_text({format_number(alpha), std::to_string(n), name, format_number(turned),
                                format_number(end(0)), format_number(end(1)), format_number(slope, 6)});
                }
            }
        const LogAestheticCurve target = normalized_log_aesthetic_curve(-0.5, 1.0);
        run.note("Eq. (15) on [0, 1] with α = −0.5 turns by " + format_number(target.tangent_angle(1.0), 6) +
                 " rad and ends at (" + format_number(target.point(1.0).x(), 6) + ", " +
                 format_number(target.point(1.0).y(), 6) +
                 "); construction_comparison.csv lists both constructions: the scale-1 polygon approaches this piece, "
                 "the constant-rotation polygon another piece of a curve with "
                 "the same α (its eq (20) takes (j+1)Δs_j for the arc length Σ_{k≤j} Δs_k).");
    }
    return run.finish();
}
