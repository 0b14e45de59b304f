// pseudo_energy section 4.2, Figs. 10–24: the five curves of section 4.2 through the data of
// Tables 1–3, their curvature profiles, measured fairness, corners on the knot data, locality.
// Tables: the 36-node reference table (Romberg + CG, as the paper) and J(θ), θ1(θ) derived from it
// as section 4.1 describes. The pseudo-spline of the figures uses the exact tangent optimisation.
// The five curves are built by the method registry, as `cagd interpolate --method M` builds them.
#include <cmath>
#include <cstdlib>
#include <map>
#include <numbers>
#include <string>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/fairness/pseudo_spline.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "cagd/methods/method_registry.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::fairness;

namespace {

// The five curves of section 4.2, by their registry names, in the order of the figures.
const std::vector<std::string> kMethods = {"cubic-a", "cubic-b", "hermite-a", "hermite-b", "pseudo-spline"};

// Largest distance between two curves over the spans in [first, last] (same parameter).
double span_distance(const Curve& a, const Curve& b, int first, int last) {
    double d = 0.0;
    for (int k = first; k <= last; ++k) d = std::max(d, analysis::max_distance_same_parameter(a, b, k, k + 1, 257));
    return d;
}

}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run("pseudo_energy", "spline_curves", "4.2",
                           "Pseudo-splines and the four comparison curves (Figs. 10-24)", argc, argv);
    const PseudoSplineTables tables = PseudoSplineTables::from(PseudoEnergyTable::load_or_build(
        run.cache_path("table36_reference.txt"), {36, NodePlacement::periodic}, TableMethod::reference));
    const TableOracle oracle = tables.oracle();
    // The registry's pseudo-spline reads the same table file, with exact tangent optimisation.
    const methods::ParameterText pseudo_spline_parameters = {{"table", run.cache_path("table36_reference.txt")},
                                                             {"optimize", "exact"}};
    const auto section42 = [&](const PointList& points, const std::string& method) -> methods::Interpolant {
        methods::InterpolationResult r = methods::interpolate(
            method, points, false, method == "pseudo-spline" ? pseudo_spline_parameters : methods::ParameterText{});
        if (!r.outcome
                 .ok()) {  // not for these methods on valid points: recorded as a failed validation, then the run ends
            run.validate("sec42.registry_builds." + method, method + " through the registry: " + r.outcome.message, 1.0,
                         0.0, 0.0, "every section 4.2 method returns a curve");
            std::exit(run.finish());
        }
        return std::move(*r.interpolant);
    };
    const auto spans_of = [](const methods::Interpolant& i) { return static_cast<int>(i.node_parameters.size()) - 1; };

    struct DataSet {
        std::string name, figure, caption;
        PointList points;
        double a;
    };
    std::vector<DataSet> sets;
    const PointList t1 = read_points_csv(run.reference_path("data/table1.csv"));
    const PointList t2 = read_points_csv(run.reference_path("data/table2.csv"));
    const PointList t3 = read_points_csv(run.reference_path("data/table3.csv"));
    sets.push_back({"table1", "fig10_14", "", t1, NAN});
    for (int a = 0; a <= 5; ++a) {
        PointList p = t2;
        p(4, 1) = a;
        sets.push_back({"table2", "fig15_19", "", p, double(a)});
    }
    sets.push_back({"table3", "fig20_24", "", t3, NAN});

    CsvWriter measures = run.table("measures.csv", {"data", "a", "method", "mode", "length", "bending_energy",
                                                    "pseudo_energy", "curvature_sign_changes", "max_abs_curvature",
                                                    "overshoot", "max_spike", "corners", "self_intersections"});
    CsvWriter fig1 = run.table("fig10_14.csv", {"method", "u", "x", "y", "s", "kappa"});
    CsvWriter fig2 = run.table("fig15_19.csv", {"method", "a", "u", "x", "y", "s", "kappa"});
    CsvWriter fig3 = run.table("fig20_24.csv", {"method", "u", "x", "y", "s", "kappa"});
    const auto measure_row = [&](const DataSet& d, const std::string& method, const std::string& mode, const Curve& c) {
        const analysis::FairnessMeasures f = analysis::fairness_measures(c, d.points);
        const int crossings = analysis::self_intersections(c);
        measures.row_text({d.name, std::isnan(d.a) ? "" : format_number(d.a), method, mode, format_number(f.length, 10),
                           format_number(f.bending_energy, 10), format_number(f.pseudo_energy, 10),
                           std::to_string(f.curvature_sign_changes), format_number(f.max_abs_curvature, 10),
                           format_number(f.overshoot, 6), format_number(f.max_spike, 6), std::to_string(f.corners),
                           std::to_string(crossings)});
        return std::make_pair(f, crossings);
    };

    int table3_pseudo_corners = -1, table3_pseudo_crossings = -1;
    int table3_corner_a = -1, table3_corner_b = -1;
    double table3_spike_pseudo = 0, table3_spike_a = 0, table3_spike_b = 0;  // max over spans of |κ|·chord
    std::map<std::string, double> interior_max, ends_max;
    for (const DataSet& d : sets) {
        for (std::size_t mi = 0; mi < std::size(kMethods); ++mi) {
            const std::string& m = kMethods[mi];
            const methods::Interpolant interpolant = section42(d.points, m);
            const Curve& c = *interpolant.curve;
            const auto [f, crossings] = measure_row(d, m, m == "pseudo-spline" ? "exact" : "", c);
            for (const analysis::CurvatureSample& s : analysis::curvature_profile(c, 64)) {
                const Eigen::VectorXd p = c.point(s.u);
                if (d.figure == "fig10_14")
                    fig1.row({double(mi + 1), s.u, p.x(), p.y(), s.s, s.kappa});
                else if (d.figure == "fig15_19")
                    fig2.row({double(mi + 1), d.a, s.u, p.x(), p.y(), s.s, s.kappa});
                else
                    fig3.row({double(mi + 1), s.u, p.x(), p.y(), s.s, s.kappa});
            }
            if (d.name == "table3") {
                if (m == "pseudo-spline") {
                    table3_pseudo_corners = f.corners;
                    table3_pseudo_crossings = crossings;
                    table3_spike_pseudo = f.max_spike;
                }
                if (m == "hermite-a") table3_corner_a = f.corners, table3_spike_a = f.max_spike;
                if (m == "hermite-b") table3_corner_b = f.corners, table3_spike_b = f.max_spike;
            }
        }
        // The pseudo-spline without and with approximate optimisation; with/without optimisation compared.
        const PseudoSpline exact = pseudo_spline(d.points, oracle, TangentOptimization::exact, false);
        const PseudoSpline none = pseudo_spline(d.points, oracle, TangentOptimization::none, false);
        const PseudoSpline approx = pseudo_spline(d.points, oracle, TangentOptimization::approximate, false);
        const auto fn = measure_row(d, "pseudo-spline", "none", none.curve).first;
        measure_row(d, "pseudo-spline", "approx", approx.curve);
        if (d.name == "table3")
            run.note("Table 3 data: the pseudo-spline in mode none (no minimisation of eq 12) has " +
                     std::to_string(fn.corners) + " span(s) with a corner.");
        const int spans = exact.curve.spans();
        if (d.name != "table3" && spans >= 3) {
            // "Without optimisation" read as Hermite curves A and B (our stated reading), and as the
            // pseudo-spline whose tangents are not optimised (mode none: Table 4's 「最適化しない場合」).
            for (const std::string m : {"hermite-a", "hermite-b", "pseudo-spline-none"}) {
                const methods::Interpolant hermite =
                    m == "pseudo-spline-none" ? methods::Interpolant{} : section42(d.points, m);
                const Curve& h = m == "pseudo-spline-none" ? static_cast<const Curve&>(none.curve) : *hermite.curve;
                const double interior = span_distance(exact.curve, h, 1, spans - 2) / bounding_box_diagonal(d.points);
                const double ends =
                    std::max(span_distance(exact.curve, h, 0, 0), span_distance(exact.curve, h, spans - 1, spans - 1)) /
                    bounding_box_diagonal(d.points);
                std::string key = d.name + "." + m;
                interior_max[key] = std::max(interior_max[key], interior);
                ends_max[key] = std::max(ends_max[key], ends);
                run.note(d.name + (std::isnan(d.a) ? "" : " (a = " + format_number(d.a) + ")") + ": pseudo-spline vs " +
                         m + " — largest distance on interior spans " + format_number(100 * interior, 3) +
                         " % of the data diagonal, on the end spans " + format_number(100 * ends, 3) + " %.");
            }
        }
    }
    // "Nearly the same except at the ends" (section 4.2, Tables 1 and 2): visibly the same means
    // within 1 % of the data diagonal (our threshold, as in sb2_locality).
    CsvWriter comparison =
        run.table("optimisation_comparison.csv",
                  {"data", "non_optimised", "interior_spans_percent_of_diagonal", "end_spans_percent_of_diagonal"});
    for (const char* data : {"table1", "table2"})
        for (const char* m : {"hermite-a", "hermite-b", "pseudo-spline-none"}) {
            const std::string key = std::string(data) + "." + m;
            comparison.row_text(
                {data, m, format_number(100 * interior_max[key], 4), format_number(100 * ends_max[key], 4)});
            const std::string claim = "sec42." + key;  // sec42.<table1|table2>.<hermite-a|hermite-b>.*
            // "Nearly the same": the reference row's threshold (1 % of the diagonal, stated before the
            // measurement); its other thresholds are notes.
            run.check_threshold(claim + ".interior_same", interior_max[key], "interior distance / diagonal");
            // On Table 2 the end spans join collinear points and are straight in every method, so
            // "except at both ends" says nothing there: that claim is not checked (reference file).
            if (std::string(data) == "table1")
                run.check(claim + ".ends_differ_more", ends_max[key] > interior_max[key] ? 1.0 : 0.0);
        }
    // A corner is our |κ|·chord > 100 (radius below 1 % of the chord); also checked at 30 and 300.
    // Under another threshold the pseudo-spline's count is given as 0 or 1 (= at least one span).
    std::vector<repro::ChoiceValue> pseudo_corner, corner_a, corner_b;
    for (double thr : {30.0, 300.0}) {
        const std::string label = "corner = |κ|·chord > " + format_number(thr);
        pseudo_corner.push_back({label, table3_spike_pseudo > thr ? 1.0 : 0.0});
        corner_a.push_back({label, table3_spike_a > thr ? 1.0 : 0.0});
        corner_b.push_back({label, table3_spike_b > thr ? 1.0 : 0.0});
    }
    const std::string corner_stated = "corner = |κ|·chord > " + format_number(analysis::kCornerThreshold);
    run.check_over_choices("sec42.table3.pseudo_spline_corners", table3_pseudo_corners, corner_stated, pseudo_corner);
    run.check_over_choices("sec42.table3.hermite_a_corner", table3_corner_a > 0 ? 1.0 : 0.0, corner_stated, corner_a);
    run.check_over_choices("sec42.table3.hermite_b_corner", table3_corner_b > 0 ? 1.0 : 0.0, corner_stated, corner_b);
    run.note("Table 3 data, largest |κ|·chord over the spans: pseudo-spline " + format_number(table3_spike_pseudo, 4) +
             ", Hermite A " + format_number(table3_spike_a, 4) + ", Hermite B " + format_number(table3_spike_b, 4) +
             ".");
    run.check("sec42.table3.knot", table3_pseudo_crossings);

    // Locality (section 6: "the curve keeps locality"): move one interior point by 1 % of the
    // diagonal and count the spans that move by more than 1e-12 × diagonal.
    CsvWriter loc = run.table("locality.csv", {"data", "method", "moved_point", "spans", "spans_moved"});
    int pseudo_worst = 0;
    for (const DataSet* d : {&sets[0], &sets[4]}) {
        const Eigen::Index n = d->points.rows();
        for (std::size_t mi = 0; mi < std::size(kMethods); ++mi) {
            int worst = 0;
            for (Eigen::Index j = 2; j + 2 < n; ++j) {
                PointList moved = d->points;
                moved(j, 1) += 0.01 * bounding_box_diagonal(d->points);
                const methods::Interpolant a = section42(d->points, kMethods[mi]);
                const methods::Interpolant b = section42(moved, kMethods[mi]);
                int count = 0;
                for (int k = 0; k < spans_of(a); ++k)
                    if (analysis::max_distance_same_parameter(*a.curve, *b.curve, k, k + 1, 65) >
                        1e-12 * bounding_box_diagonal(d->points))
                        ++count;
                worst = std::max(worst, count);
                loc.row_text({d->name + (std::isnan(d->a) ? "" : " a=" + format_number(d->a)), kMethods[mi],
                              std::to_string(j), std::to_string(spans_of(a)), std::to_string(count)});
            }
            if (kMethods[mi] == "pseudo-spline") pseudo_worst = std::max(pseudo_worst, worst);
        }
    }
    run.check("sec6.locality.pseudo_spline_spans_moved", pseudo_worst);

    // Length and area from the L and S tables (eq 16, 19, 21) against adaptive integration of the
    // curve the tables draw. They differ by the tables' interpolation error: L and S are
    // interpolated at (θ0, θ1) while the curve uses interpolated r0, r1.
    CsvWriter tvi = run.table("tables_vs_integration.csv",
                              {"data", "length_tables", "length_integrated", "length_rel_diff", "area_tables",
                               "area_integrated", "area_abs_diff_over_diagonal_squared"});
    double worst_length = 0.0;
    for (const DataSet* d : {&sets[0], &sets[4], &sets[6], &sets[7]}) {
        const PseudoSpline ps = pseudo_spline(d->points, oracle, TangentOptimization::exact, false);
        const Eigen::MatrixXd& n = ps.curve.nodes();
        const double closing = 0.5 * (n(n.rows() - 1, 0) * n(0, 1) - n(n.rows() - 1, 1) * n(0, 0));
        const double L = analysis::adaptive_arc_length(ps.curve, 1e-12),
                     S = analysis::enclosed_area(ps.curve) + closing;
        const double dl = std::abs(ps.length_from_tables() - L) / L, diag = bounding_box_diagonal(d->points);
        worst_length = std::max(worst_length, dl);
        tvi.row_text({d->name + (std::isnan(d->a) ? "" : " a=" + format_number(d->a)),
                      format_number(ps.length_from_tables(), 10), format_number(L, 10), format_number(dl, 3),
                      format_number(ps.area_from_tables(), 10), format_number(S, 10),
                      format_number(std::abs(ps.area_from_tables() - S) / (diag * diag), 3)});
    }
    run.note(
        "Length and area from the tables (eq 16–21) against adaptive integration of the drawn curve: largest relative "
        "length difference " +
        format_number(100 * worst_length, 3) +
        " % (table interpolation error; with exact segments they agree to 1e-11, experiment circle_length_area) — "
        "[tables_vs_integration.csv](pseudo_energy/tables_vs_integration.csv).");
    run.note(
        "Measured fairness of every curve (length, ∫κ² ds, pseudo-energy, curvature sign changes, max |κ|, overshoot "
        "beyond the data's box, corners, self-crossings): "
        "[measures.csv](pseudo_energy/measures.csv); spans moved when one point moves, per method: "
        "[locality.csv](pseudo_energy/locality.csv); with/without optimisation "
        "distances: [optimisation_comparison.csv](pseudo_energy/optimisation_comparison.csv).");

    // Independent check of cubic spline A: the natural uniform cubic B-spline interpolant of
    // sb2_locality eq (10) (B-spline form, SparseLU) is the same curve.
    {
        const methods::Interpolant a = section42(t1, "cubic-a");
        const BSplineCurve b = locality::cubic_bspline_interpolant(t1, false);
        run.validate("sec42.cubic_spline_a_vs_bspline",
                     "cubic spline A (Hermite form, tridiagonal) vs the B-spline interpolant of sb2_locality eq (10), "
                     "Table 1 data: max distance",
                     analysis::max_distance_same_parameter(*a.curve, b), 0.0, 1e-12 * bounding_box_diagonal(t1),
                     "rounding (1e-12 × data diagonal)");
    }

    run.figure("fig10_14",
               "Figs. 10–14 — Table 1 (Newbery–Garrett) data: cubic spline A, cubic spline B, Hermite A, Hermite B, "
               "pseudo-spline (top), and the curvature κ(s) of each (bottom).");
    run.figure(
        "fig15_19",
        "Figs. 15–19 — Table 2 (spike) data for a = 0..5, the five methods (top) and their curvature κ(s) (bottom).");
    run.figure("fig20_24",
               "Figs. 20–24 — Table 3 (knot) data, the five methods (top) and κ(s) (bottom); the Hermite curves and "
               "the cubic splines have curvature spikes (corners), the "
               "pseudo-spline has none.");
    run.note(
        "Angle convention: chord-angle differences are wrapped to (−180°, 180°], so at both interior points of Table 3 "
        "the data turn clockwise by " +
        format_number(180.0 - std::atan2(0.1, 2.0) * 180.0 / std::numbers::pi, 6) +
        "° and the pseudo-spline is a loop that crosses its first span (claim sec42.table3.knot counts the "
        "crossings).");
    run.note("Corner: a span whose largest |κ|·l (l the span's chord) exceeds " +
             format_number(analysis::kCornerThreshold) +
             ", i.e. a radius of curvature below 1 % of the chord — our definition; at a cusp |κ| is unbounded. Cubic "
             "splines A and B use natural end conditions (our choice; the "
             "paper cites [5]).");
    run.note(
        "Tangent optimisation 'none' (Table 4; the Table 3 corner note above): α_i along P_{i−1}P_{i+1} (Hermite A's "
        "direction), magnitudes from the table and ends by eq (13) — "
        "the method without the minimisation of eq (12).");
    return run.finish();
}
