// pseudo_energy section 6: the space pseudo-spline the paper proposes and leaves unbuilt
// (fairness/space_pseudo_spline.hpp). The paper prints no numbers for it; the claims are ours
// (reference/pseudo_energy/space_pseudo_spline.csv): the planar reduction, similarity invariance,
// a circle in space; measured, not claimed: a circular helix with n = 4 … 16 points per turn (length,
// curvature and torsion against the helix's), and a trefoil knot drawn by every 3-D method.
// Oracles: J(θ) from the 36-node reference tables (as the planar experiments), spans by the space
// minimiser at their exact angles; the planar comparisons use the same J(θ) with exact planar spans.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/fairness/space_pseudo_spline.hpp"
#include "cagd/methods/method_registry.hpp"
#include "cagd/repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::fairness;

namespace {

constexpr double kPi = std::numbers::pi;

// Largest distance between two curves at 64 parameters per span (same parameter), over `scale`.
double curve_gap(const Curve& a, const Curve& b, double scale, const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity(), const Eigen::Vector3d& shift = Eigen::Vector3d::Zero(),
                 double factor = 1.0) {
    double gap = 0.0;
    const int samples = 64 * static_cast<int>(std::lround(a.t_max() - a.t_min()));
    for (int k = 0; k <= samples; ++k) {
        const double u = a.t_min() + (a.t_max() - a.t_min()) * k / samples;
        Eigen::Vector3d pa = Eigen::Vector3d::Zero(), pb = Eigen::Vector3d::Zero();
        pa.head(a.dimension()) = a.point(u);
        pb.head(b.dimension()) = b.point(u);
        gap = std::max(gap, (pb - (factor * R * pa + shift)).norm());
    }
    return gap / scale;
}

PointList helix_points(int per_turn, int turns, double pitch) {
    PointList p(per_turn * turns + 1, 3);
    for (int i = 0; i <= per_turn * turns; ++i) {
        const double t = 2 * kPi * i / per_turn;
        p.row(i) << std::cos(t), std::sin(t), pitch * t / (2 * kPi);
    }
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run("pseudo_energy", "space_pseudo_spline", "6",
                           "The space pseudo-spline that section 6 proposes: planar reduction, invariance, a circle and a helix in space, a trefoil (our claims)", argc, argv);
    const PseudoSplineTables tables =
        PseudoSplineTables::from(PseudoEnergyTable::load_or_build(run.cache_path("table36_reference.txt"), {36, NodePlacement::periodic}, TableMethod::reference));
    const TableOracle angles = tables.oracle();
    const ExactSpaceOracle space(angles);
    const ExactSegmentOracle plane(angles);

    // 0. The fast path against the reference (Romberg + Ceres CG) at every orbit of a coarse space
    //    table (6 × 6 × 8 nodes, one per symmetry orbit).
    {
        const SpaceAngleGrid grid{6, 8};
        const long orbits = static_cast<long>(SpacePseudoEnergyTable::orbit_nodes(grid).size());
        const auto fast = SpacePseudoEnergyTable::compute_orbits(grid, TableMethod::fast, 0, orbits, 2);
        const auto reference = SpacePseudoEnergyTable::compute_orbits(grid, TableMethod::reference, 0, orbits, 2);
        double dj = 0.0, dl = 0.0;
        for (std::size_t q = 0; q < fast.size(); ++q) {
            dj = std::max(dj, std::abs(fast[q].pseudo_energy - reference[q].pseudo_energy) / std::max(1.0, reference[q].pseudo_energy));
            dl = std::max(dl, std::abs(fast[q].length - reference[q].length));
        }
        run.validate("sec6.space.fast_vs_reference_J",
                     "space J: fast path vs reference (Romberg + Ceres CG) at all " + std::to_string(orbits) + " orbits of a 6 × 6 × 8 table, max |ΔJ| / max(1, J)", dj, 0.0, 1e-10,
                     "the planar paths' agreement (quadrature ~1e-13, minimiser to |∇J| ≤ 1e-10)");
        run.validate("sec6.space.fast_vs_reference_L", "space L at the same orbits: max |ΔL|", dl, 0.0, 1e-10,
                     "as the planar minimum table's fast-vs-reference check (measured 1.3e-13)");
    }

    // 1. Table 1's points in a tilted plane of space give the planar pseudo-spline, turned.
    const PointList t1 = read_points_csv(run.reference_path("data/table1.csv"));
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
    const Eigen::Vector3d shift(0.5, -2, 3);
    PointList tilted(t1.rows(), 3);
    for (Eigen::Index i = 0; i < t1.rows(); ++i) tilted.row(i) = (R * Eigen::Vector3d(t1(i, 0), t1(i, 1), 0.0) + shift).transpose();
    const double diag = bounding_box_diagonal(t1);
    double gap_none_approx = 0.0, gap_exact = 0.0;
    for (bool closed : {false, true})
        for (TangentOptimization mode : {TangentOptimization::none, TangentOptimization::approximate, TangentOptimization::exact}) {
            const PseudoSpline p2 = pseudo_spline(t1, plane, mode, closed);
            const SpacePseudoSpline p3 = space_pseudo_spline(tilted, space, mode, closed);
            const double g = curve_gap(p2.curve, p3.curve, diag, R, shift);
            (mode == TangentOptimization::exact ? gap_exact : gap_none_approx) = std::max(mode == TangentOptimization::exact ? gap_exact : gap_none_approx, g);
        }
    run.check("sec6.space.planar_reduction", gap_none_approx);
    run.check("sec6.space.planar_reduction_exact", gap_exact);

    // 2. Similarity: a non-planar polygon turned, scaled and moved (approximate and no tangent optimisation).
    PointList wavy = helix_points(6, 2, 1.5);
    for (Eigen::Index i = 0; i < wavy.rows(); ++i) wavy(i, 2) += 0.3 * std::sin(1.7 * static_cast<double>(i));
    PointList moved(wavy.rows(), 3);
    for (Eigen::Index i = 0; i < wavy.rows(); ++i) moved.row(i) = (2.5 * R * wavy.row(i).transpose() + shift).transpose();
    double gap_similarity = 0.0;
    for (TangentOptimization mode : {TangentOptimization::none, TangentOptimization::approximate})
        gap_similarity = std::max(gap_similarity, curve_gap(space_pseudo_spline(wavy, space, mode, false).curve, space_pseudo_spline(moved, space, mode, false).curve,
                                                            2.5 * bounding_box_diagonal(wavy), R, shift, 2.5));
    run.check("sec6.space.similarity", gap_similarity);

    // 3. A circle of 8 points in a tilted plane, closed: the planar closed pseudo-spline, turned.
    PointList circle2(8, 2), circle3(8, 3);
    for (int i = 0; i < 8; ++i) {
        circle2.row(i) << std::cos(2 * kPi * i / 8), std::sin(2 * kPi * i / 8);
        circle3.row(i) = (R * Eigen::Vector3d(circle2(i, 0), circle2(i, 1), 0.0) + shift).transpose();
    }
    run.check("sec6.space.circle_closed", curve_gap(pseudo_spline(circle2, plane, TangentOptimization::approximate, true).curve,
                                                    space_pseudo_spline(circle3, space, TangentOptimization::approximate, true).curve, 2.0, R, shift));

    // 4. A circular helix (radius 1, pitch 1.5 per turn, 2 turns) through n points per turn:
    // measured, not claimed (see the note): length against the helix's, κ and τ over the middle turn
    // against its constants, for the bisector tangents (mode none) and the exact optimisation.
    const double pitch = 1.5, c = pitch / (2 * kPi);
    const double kappa = 1.0 / (1.0 + c * c), tau = c / (1.0 + c * c), turn_length = 2 * kPi * std::sqrt(1.0 + c * c);
    CsvWriter h = run.table("space_helix.csv", {"mode", "points_per_turn", "length_error", "polygon_length_error", "max_curvature_deviation", "max_torsion_deviation"});
    CsvWriter prof = run.table("space_helix_profile.csv", {"points_per_turn", "s", "curvature", "torsion", "helix_curvature", "helix_torsion"});
    std::string summary, trends;
    for (TangentOptimization mode : {TangentOptimization::none, TangentOptimization::exact}) {
        summary += std::string(summary.empty() ? "" : "; ") + to_string(mode) + ":";
        std::vector<double> errs, kds, tds;
        double tau_ratio = 0.0;  // mean τ over the middle turn / the helix's, at the largest n
        for (int n : {4, 6, 8, 12, 16}) {
            const PointList p = helix_points(n, 2, pitch);
            const SpacePseudoSpline s = space_pseudo_spline(p, space, mode, false);
            const double L = analysis::accurate_arc_length(s.curve).value;
            double polygon = 0.0;
            for (Eigen::Index i = 0; i + 1 < p.rows(); ++i) polygon += (p.row(i + 1) - p.row(i)).norm();
            const bool profile = mode == TangentOptimization::none && (n == 6 || n == 16);
            double kd = 0.0, td = 0.0, tau_sum = 0.0;
            for (int k = 0; k <= 40 * n; ++k) {
                const double u = n / 2.0 + n * static_cast<double>(k) / (40.0 * n);
                const double ku = analysis::curvature(s.curve, u), tu = analysis::torsion(s.curve, u);
                kd = std::max(kd, std::abs(ku / kappa - 1.0));
                td = std::max(td, std::abs(tu / tau - 1.0));
                tau_sum += tu;
                if (profile) prof.row({double(n), analysis::arc_length(s.curve, 0.0, u), ku, tu, kappa, tau});
            }
            if (profile) {
                prof.end_scan();
                prof.end_scan();
            }
            const double e = std::abs(L - 2 * turn_length) / (2 * turn_length);
            h.row_text({to_string(mode), std::to_string(n), format_number(e, 6), format_number(std::abs(polygon - 2 * turn_length) / (2 * turn_length), 6), format_number(kd, 4),
                        format_number(td, 4)});
            summary += " n = " + std::to_string(n) + ": length " + format_number(e, 2) + ", κ " + format_number(kd, 2) + ", τ " + format_number(td, 2) + ";";
            errs.push_back(e);
            kds.push_back(kd);
            tds.push_back(td);
            tau_ratio = tau_sum / (40 * n + 1) / tau;
        }
        const auto falls = [](const std::vector<double>& v) { return std::is_sorted(v.rbegin(), v.rend()) ? "falls" : "does not fall monotonically"; };
        trends += std::string(trends.empty() ? "" : "; ") + "mode " + to_string(mode) + ": the length error " + falls(errs) + ", the κ deviation " + falls(kds) +
                  ", the τ deviation " + falls(tds) + " with n, and at n = 16 the mean torsion is " + format_number(tau_ratio, 3) + " times the helix's";
    }
    run.note("Helix (radius 1, pitch 1.5, 2 turns), relative length error and largest relative deviations of κ and τ over the middle turn (space_helix.csv) — " + summary +
             " From these numbers: " + trends +
             ". Measured, not claimed: the claims first stated for the helix (length error decreasing with n under exact optimisation; curvature and torsion converging "
             "to the helix's) do not all hold. Our reading, still to be analysed (issue 26): the exact optimisation on the tables' J(θ) leaves the bisector (as in "
             "erratum pseudo_energy-E4), and the torsion rests on the out-of-plane part of the third derivative, which the minimising magnitudes r0, r1 of G1 cubic "
             "spans do not match to that order.");
    run.figure("fig_space_helix",
               "The space pseudo-spline (bisector tangents) through a circular helix with 6 and 16 points per turn: curvature and torsion against arc length, "
               "with the helix's constants.");

    // 5. A trefoil knot, 24 points, closed: every 3-D method of the registry.
    PointList knot(24, 3);
    for (int i = 0; i < 24; ++i) {
        const double t = 2 * kPi * i / 24;
        knot.row(i) << std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t);
    }
    CsvWriter kc = run.table("space_trefoil.csv", {"method", "u", "x", "y", "z", "s", "curvature", "torsion"});
    std::string methods;
    int index = 0;
    CsvWriter names = run.table("space_trefoil_methods.csv", {"index", "method"});
    for (const methods::Configuration& cfg : methods::configurations()) {
        if (cfg.claims.max_dimension < 3 || !cfg.claims.supports_closed) continue;
        const methods::InterpolationResult r = methods::interpolate(cfg, knot, true);
        if (!r.outcome.ok()) continue;
        const Curve& curve = *r.interpolant->curve;
        methods += (methods.empty() ? "" : ", ") + std::to_string(index) + " " + cfg.name;
        names.row_text({std::to_string(index), cfg.name});
        double s = 0.0, prev_u = curve.t_min();
        for (int k = 0; k <= 24 * 16; ++k) {
            const double u = curve.t_min() + (curve.t_max() - curve.t_min()) * k / (24 * 16);
            s += k ? analysis::arc_length(curve, prev_u, u, 1) : 0.0;
            prev_u = u;
            const Eigen::VectorXd x = curve.point(u);
            kc.row_text({std::to_string(index), format_number(u), format_number(x(0)), format_number(x(1)), format_number(x(2)), format_number(s),
                         format_number(analysis::curvature(curve, u)), format_number(analysis::torsion(curve, u))});
        }
        kc.end_scan();
        kc.end_scan();
        ++index;
    }
    run.note("Trefoil (sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t), 24 points, closed; methods by index in space_trefoil.csv: " + methods + ".");
    run.figure("fig_space_trefoil", "A trefoil knot through 24 points by every closed 3-D method: the curves, curvature and torsion against arc length.");
    return run.finish();
}
