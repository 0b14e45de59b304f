// The methods of pseudo_energy (Inoue, Shibata, Kanatani): the pseudo-spline (eq 4-12, sections
// 3-4; on 3-D points the space pseudo-spline of section 6, extended) and the four comparison
// curves of section 4.2 (cubic splines A and B, Hermite curves A and B).
#include "cagd/methods/detail/registration.hpp"

#include "cagd/fairness/pseudo_spline.hpp"
#include "cagd/fairness/space_pseudo_spline.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace cagd::methods::detail {

namespace {

const fairness::PseudoSplineTables& default_pseudo_spline_tables() {
    // The 36-node fast table: from the user's cache, built there once,
    // or in memory once per process when the cache is off.
    static const fairness::PseudoSplineTables tables = fairness::PseudoSplineTables::from(
        fairness::PseudoEnergyTable::user_cached({36, fairness::NodePlacement::periodic}, fairness::TableMethod::fast));
    return tables;
}

const fairness::SpacePseudoEnergyTable& default_space_table() {
    // The 36 x 36 x 72 fast space table: from the user's cache, built there once.
    static const fairness::SpacePseudoEnergyTable table =
        fairness::SpacePseudoEnergyTable::user_cached({36, 72}, fairness::TableMethod::fast);
    return table;
}

// Space points (pseudo_energy section 6, extended to space): the space pseudo-spline, tangents by the planar tables'
// J(θ), spans from a space table (the default one, or --space-table) or by the space minimiser at the exact angles
// (--space-spans exact).
InterpolationResult build_space_pseudo_spline(const PointList& points, bool closed, const ParameterValues& v,
                                              const fairness::PseudoSplineTables& planar) {
    const auto mode = fairness::parse_tangent_optimization(v.text("optimize"));
    const fairness::TableOracle planar_oracle = planar.oracle();
    const bool exact = v.text("space-spans") == "exact";
    if (exact && v.has("space-table"))
        fail_input("cagd::methods(pseudo-spline)",
                   "--space-table gives the spans' table; --space-spans exact computes them without one");
    fairness::SpacePseudoSpline ps = [&] {
        if (exact)
            return fairness::space_pseudo_spline(points, fairness::ExactSpaceOracle(planar_oracle), mode, closed);
        if (v.has("space-table")) {
            const fairness::SpacePseudoEnergyTable table =
                fairness::SpacePseudoEnergyTable::load(v.text("space-table"));
            return fairness::space_pseudo_spline(points, fairness::TableSpaceOracle(table, planar_oracle), mode,
                                                 closed);
        }
        return fairness::space_pseudo_spline(points, fairness::TableSpaceOracle(default_space_table(), planar_oracle),
                                             mode, closed);
    }();
    InterpolationResult r = result_of(unit_span_interpolant(std::make_shared<spline::PiecewiseHermiteCurve>(ps.curve),
                                                            node_count(points, closed), unit_lengths(points, closed)));
    r.quantities = {{"length_from_tables", ps.length_from_tables()}};
    return r;
}

InterpolationResult build_pseudo_spline(const ValidPoints& valid, const ParameterValues& v) {
    const PointList& points = valid.points();
    const bool closed = valid.closed();
    const auto mode = fairness::parse_tangent_optimization(v.text("optimize"));
    if (points.cols() == 3)
        return v.has("table")
                   ? build_space_pseudo_spline(
                         points, closed, v,
                         fairness::PseudoSplineTables::from(fairness::PseudoEnergyTable::load(v.text("table"))))
                   : build_space_pseudo_spline(points, closed, v, default_pseudo_spline_tables());
    if (v.has("space-table"))
        fail_input("cagd::methods(pseudo-spline)", "--space-table is for 3-D points; these have 2 coordinates");
    if (v.text("space-spans") != "table")
        fail_input("cagd::methods(pseudo-spline)", "--space-spans is for 3-D points; these have 2 coordinates");
    const auto make = [&](const fairness::PseudoSplineTables& t) {
        return fairness::pseudo_spline_curve(valid, t.oracle(), mode);
    };
    fairness::PseudoSplineCurve ps =
        v.has("table") ? make(fairness::PseudoSplineTables::from(fairness::PseudoEnergyTable::load(v.text("table"))))
                       : make(default_pseudo_spline_tables());
    const std::vector<std::pair<std::string, double>> quantities = {
        {"length_from_tables", ps.length_from_tables},
        {"area_from_tables", ps.area_from_tables},
        {"pseudo_energy_from_tables", ps.pseudo_energy_from_tables}};
    // The curve moves into the interpolant (no copy).
    InterpolationResult r =
        result_of(unit_span_interpolant(std::make_shared<spline::PiecewiseHermiteCurve>(std::move(ps.curve)),
                                        node_count(points, closed), unit_lengths(points, closed)));
    r.quantities = quantities;
    return r;
}

InterpolationResult build_cubic(const ValidPoints& valid, spline::ParameterSpacing spacing) {
    const PointList& points = valid.points();
    const bool closed = valid.closed();
    auto c = std::make_shared<spline::PiecewiseHermiteCurve>(spline::cubic_spline_interpolant(valid, spacing));
    // dτ/du on span k: the chord the spline itself scales by (its h_k, chord_lengths' values), or 1.
    std::vector<double> dtau_du = spacing == spline::ParameterSpacing::chord_length ? chord_lengths(points, closed)
                                                                                    : unit_lengths(points, closed);
    return result_of(unit_span_interpolant(std::move(c), node_count(points, closed), std::move(dtau_du)));
}

InterpolationResult build_hermite(const ValidPoints& valid, spline::TangentRule rule) {
    auto c = std::make_shared<spline::PiecewiseHermiteCurve>(spline::hermite_spline(valid, rule));
    return result_of(unit_span_interpolant(std::move(c), node_count(valid.points(), valid.closed()),
                                           unit_lengths(valid.points(), valid.closed())));
}

}  // namespace

std::vector<Method> pseudo_energy_methods() {
    std::vector<Method> r;
    r.push_back({
        .name = "pseudo-spline",
        .paper = "pseudo_energy",
        .source = "eq (4)-(12), sec 4.1-4.2",
        .summary = "cubic Hermite spline of minimum pseudo-energy from a J, r0, r1 table; tangents by the 3-point "
                   "pseudo-elastic rod",
        .parameters = {{.name = "optimize",
                        .type = P::choice,
                        .default_text = "exact",
                        .choices = {"none", "exact", "approx"},
                        .help = "tangent optimisation of eq (12): none, exact (the least value of w: every breakpoint "
                                "of the table's piecewise-linear w) or approx (3-point parabola, Table 4)"},
                       {.name = "table",
                        .type = P::text,
                        .help = "pseudo-energy table written by cagd energy-table (absent: the 36-node fast table, "
                                "from the user's cache or built once there)"},
                       {.name = "space-spans",
                        .type = P::choice,
                        .default_text = "table",
                        .choices = {"table", "exact"},
                        .help = "3-D points: the spans from a space pseudo-energy table (table) or by the space "
                                "minimiser at each span's angles (exact, about 500 spans/s)",
                        .space_only = true},
                       {.name = "space-table",
                        .type = P::text,
                        .help = "3-D points: the space table of the spans (SpacePseudoEnergyTable, e.g. from "
                                "cagd_space_table_mpi; absent: the 36 x 36 x 72 fast table, "
                                "from the user's cache or built once there)",
                        .space_only = true}},
        .claims = fixed({.geometric_continuity = 1,
                         .parameter = "u (unit spans)",
                         .invariance = Invariance::similarity,
                         .max_dimension = 3}),
        .build = build_pseudo_spline,
        .presets = {{"pseudo-spline-none", {{"optimize", "none"}}},
                    {"pseudo-spline-exact", {{"optimize", "exact"}}},
                    {"pseudo-spline-approx", {{"optimize", "approx"}}}},
        .prepare =
            [](const ParameterValues& v, int dimension) {
                if (!v.has("table")) default_pseudo_spline_tables();
                if (dimension == 3 && v.text("space-spans") == "table" && !v.has("space-table")) default_space_table();
            },
    });
    r.push_back({
        .name = "cubic-a",
        .aliases = {"cubic-bspline"},
        .paper = "pseudo_energy",
        .source = "sec 4.2 cubic spline A; = sb2_locality eq (10)",
        .summary = "natural C2 cubic spline, uniform parameter (the conventional interpolating cubic B-spline)",
        .claims = fixed({.parametric_continuity = 2,
                         .geometric_continuity = 2,
                         .parameter = "uniform",
                         .invariance = Invariance::affine,
                         .max_dimension = 3}),
        .build = [](const ValidPoints& p,
                    const ParameterValues&) { return build_cubic(p, spline::ParameterSpacing::uniform); },
    });
    r.push_back({
        .name = "cubic-b",
        .paper = "pseudo_energy",
        .source = "sec 4.2 cubic spline B",
        .summary = "natural C2 cubic spline, chord-length parameter",
        .claims = fixed({.parametric_continuity = 2,
                         .geometric_continuity = 2,
                         .parameter = "chord length",
                         .invariance = Invariance::similarity,
                         .max_dimension = 3}),
        .build = [](const ValidPoints& p,
                    const ParameterValues&) { return build_cubic(p, spline::ParameterSpacing::chord_length); },
    });
    r.push_back({
        .name = "hermite-a",
        .paper = "pseudo_energy",
        .source = "sec 4.2 Hermite curve A",
        .summary = "cubic Hermite curve, tangents along the chord of the neighbours",
        .claims = fixed({.geometric_continuity = 1,
                         .parameter = "u (unit spans)",
                         .invariance = Invariance::similarity,
                         .max_dimension = 3}),
        .build = [](const ValidPoints& p,
                    const ParameterValues&) { return build_hermite(p, spline::TangentRule::chord_of_neighbours); },
    });
    r.push_back({
        .name = "hermite-b",
        .paper = "pseudo_energy",
        .source = "sec 4.2 Hermite curve B",
        .summary = "cubic Hermite curve, tangents of the circle through three neighbours",
        .claims = fixed({.geometric_continuity = 1,
                         .parameter = "u (unit spans)",
                         .invariance = Invariance::similarity,
                         .min_points = 3,
                         .max_dimension = 3}),
        .build = [](const ValidPoints& p,
                    const ParameterValues&) { return build_hermite(p, spline::TangentRule::circle); },
    });
    return r;
}

}  // namespace cagd::methods::detail
