// pseudo_energy section 5, Tables 5 and 6: length and area of the closed pseudo-spline through n
// equally spaced points on the unit circle (eq 16–21), with "equivalent points".
//   exact  the pseudo-spline with minimisers at the exact angles (no table). For equal chords every
//          point turns by 2π/n and w(α) of eq (12) is symmetric about the bisector; we check that the
//          bisector is its minimum with the exact J(θ), so each span is the segment (−π/n, π/n).
//   table  the paper's procedure: 36-node reference table, J(θ) derived from it, exact tangent
//          optimisation, L and S interpolated (eq 17, 20), same-type rule of section 4.1; also
//          plain bilinear interpolation, and the length/area of the curve the tables draw.
// The claims take the exact values; the table values explain the paper's (erratum pseudo_energy-E4).
#include <cmath>
#include <numbers>
#include <string>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/fairness/pseudo_spline.hpp"
#include "cagd/repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::fairness;

namespace {

PointList circle_points(int n) {
    PointList p(n, 2);
    for (int k = 0; k < n; ++k) p.row(k) << std::cos(2 * std::numbers::pi * k / n), std::sin(2 * std::numbers::pi * k / n);
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run("pseudo_energy", "circle_length_area", "5", "Length and area of the closed pseudo-spline through points on the unit circle (Tables 5, 6)", argc, argv);
    const PseudoSplineTables tables =
        PseudoSplineTables::from(PseudoEnergyTable::load_or_build(run.cache_path("table36_reference.txt"), {36, NodePlacement::periodic}, TableMethod::reference));
    const PseudoEnergyTable& table = tables.energy;
    const TableOracle oracle = tables.oracle();
    const ExactOracle exact_oracle;

    run.check("table5.true_value", 2 * std::numbers::pi);
    run.check("table6.true_value", std::numbers::pi);
    CsvWriter out = run.table("table5_table6.csv", {"n", "length_exact", "length_reference_path", "length_table", "length_table_bilinear", "length_of_table_curve",
                                                    "equivalent_exact", "equivalent_table", "area_exact", "area_reference_path", "area_table", "area_table_bilinear",
                                                    "area_of_table_curve", "area_equivalent_exact", "area_equivalent_table", "alpha_offset_table_deg"});
    double assembly_length = 0, assembly_area = 0, ref_gap = 0, quadrature_error = 0;
    std::string off_bisector;  // the n whose table-procedure tangent leaves the bisector
    int bisector_minimises = 0;
    for (int n = 3; n <= 10; ++n) {
        const PointList p = circle_points(n);
        std::string id = "n";
        id += std::to_string(n);  // (not "n" + to_string: a GCC 12 -Wrestrict false positive)
        // Exact: bisector directions (mode none = direction of P_{i+1} − P_{i−1}, the bisector for equal chords).
        const PseudoSpline ex = pseudo_spline(p, exact_oracle, TangentOptimization::none, true);
        const double L = ex.length_from_tables(), S = ex.area_from_tables();
        // The bisector minimises w with the exact J(θ): w at the bisector and at 1/8, 1/4 of the turn
        // beside it (w is symmetric about the bisector: J(θ) = J(−θ)).
        const double tau = 2 * std::numbers::pi / n, centre = -tau / 2;
        const auto w = [&](double a) { return exact_oracle.angle_minimum(wrap_angle(a + tau)).first + exact_oracle.angle_minimum(a).first; };
        const double wc = w(centre);
        bool ok = true;
        for (double f : {0.125, 0.25}) ok = ok && w(centre + f * tau) >= wc;
        bisector_minimises += ok ? 1 : 0;
        // The same segment from the reference minimiser (Romberg 1e-13, Ceres CG, Newton polish).
        const PseudoEnergyMinimum ref = minimize_pseudo_energy_reference(-std::numbers::pi / n, std::numbers::pi / n);
        const double l = 2 * std::sin(std::numbers::pi / n);
        const double L_ref = n * l * ref.length, S_ref = ex.polygon_area() - n * l * l * ref.area;
        ref_gap = std::max({ref_gap, std::abs(L - L_ref), std::abs(S - S_ref)});
        // eq (17), (20) against direct integration of the same curve.
        // Adaptive Gauss–Kronrod with its error estimate: Romberg to 1e-13 did not converge for n = 4, 5, 7, 8,
        // 10 (its last level, 1.7e7 evaluations per span, differed by up to 1.8e-9) and went unchecked.
        const analysis::ArcLength exact_curve_length = analysis::accurate_arc_length(ex.curve);
        quadrature_error = std::max(quadrature_error, exact_curve_length.error_estimate / exact_curve_length.value);
        assembly_length = std::max(assembly_length, std::abs(L - exact_curve_length.value) / L);
        assembly_area = std::max(assembly_area, std::abs(S - analysis::enclosed_area(ex.curve)) / S);

        // The paper's procedure with tables.
        const PseudoSpline tb = pseudo_spline(p, oracle, TangentOptimization::exact, true);
        double L_bil = 0, S_bil = tb.polygon_area();
        for (std::size_t i = 0; i < tb.spans.size(); ++i) {
            const TableValue v = table.lookup(tb.spans[i].theta0, tb.spans[i].theta1, false);
            L_bil += tb.chord_length[i] * v.length;
            S_bil -= tb.chord_length[i] * tb.chord_length[i] * v.area;
        }
        const double L_tab = tb.length_from_tables(), S_tab = tb.area_from_tables();
        if (std::abs(tb.alpha[0] - centre) * 180 / std::numbers::pi > 0.01) {
            off_bisector += ' ';
            off_bisector += std::to_string(n);
        }
        const std::string table5 = "table5." + id, table6 = "table6." + id;  // table5.n<n>.*, table6.n<n>.*
        run.check(table5 + ".length", L);
        run.check(table5 + ".equivalent", double(equivalent_polygon_points(std::abs(2 * std::numbers::pi - L), CircleMeasure::perimeter)));
        run.check(table6 + ".area", S);
        run.check(table6 + ".equivalent", double(equivalent_polygon_points(std::abs(std::numbers::pi - S), CircleMeasure::area)));
        // The paper's equivalent-points column from its own printed length/area.
        const double printed_L = run.reference().row("pseudo_energy." + table5 + ".length").paper_value;
        const double printed_S = run.reference().row("pseudo_energy." + table6 + ".area").paper_value;
        run.check(table5 + ".equivalent_from_printed", double(equivalent_polygon_points(std::abs(2 * std::numbers::pi - printed_L), CircleMeasure::perimeter)));
        run.check(table6 + ".equivalent_from_printed", double(equivalent_polygon_points(std::abs(std::numbers::pi - printed_S), CircleMeasure::area)));
        const analysis::ArcLength table_curve_length = analysis::accurate_arc_length(tb.curve);
        quadrature_error = std::max(quadrature_error, table_curve_length.error_estimate / table_curve_length.value);
        out.row({double(n), L, L_ref, L_tab, L_bil, table_curve_length.value, double(equivalent_polygon_points(std::abs(2 * std::numbers::pi - L), CircleMeasure::perimeter)),
                 double(equivalent_polygon_points(std::abs(2 * std::numbers::pi - L_tab), CircleMeasure::perimeter)), S, S_ref, S_tab, S_bil, analysis::enclosed_area(tb.curve),
                 double(equivalent_polygon_points(std::abs(std::numbers::pi - S), CircleMeasure::area)),
                 double(equivalent_polygon_points(std::abs(std::numbers::pi - S_tab), CircleMeasure::area)), (tb.alpha[0] - centre) * 180 / std::numbers::pi},
                10);
    }
    run.validate("sec5.bisector_minimises_w", "exact J(θ): the bisector minimises w of eq (12) for n = 3..10 (count of n)", bisector_minimises, 8, 0, "count");
    run.validate("sec5.fast_vs_reference", "exact lengths and areas, fast minimiser vs reference minimiser: max |difference|", ref_gap, 0.0, 1e-10,
                 "minimiser tolerance (|grad J| < 1e-12 in log r) propagated to L and S, with margin");
    run.validate("sec5.eq17_vs_integration", "eq (17): Σ l_i L_i vs the adaptive Gauss–Kronrod arc length of the same curve, max relative difference", assembly_length, 0.0, 1e-11,
                 "quadrature (fast L at about 1e-13, Gauss–Kronrod 1e-12)");
    run.validate("sec5.length_quadrature_error", "Gauss–Kronrod error estimates of the integrated lengths (exact and table curves), max relative", quadrature_error, 0.0, 1e-12,
                 "the requested tolerance: an integration that did not converge fails here");
    run.validate("sec5.eq20_vs_integration", "eq (20)–(21): S_0 − Σ l_i² S_i vs ½∮(x dy − y dx) of the same curve, max relative difference", assembly_area, 0.0, 1e-12,
                 "exact polynomial integrals, rounding");
    run.note(
        "Our 'length' and 'area' are exact (minimisers at the exact angles, no table); the table columns of table5_table6.csv follow the paper's procedure (36-node reference "
        "table, same-type bilinear rule; J(θ) from the table; exact tangent optimisation) and show where the paper's values come from (erratum pseudo_energy-E4).");
    run.note(
        "alpha_offset_table_deg: the tangent direction the table procedure chooses minus the bisector. With J(θ) interpolated linearly, w of eq (12) is piecewise linear and its "
        "minimum can leave the bisector (by more than 0.01° for n =" +
        off_bisector + "), which makes the spans asymmetric.");
    return run.finish();
}
