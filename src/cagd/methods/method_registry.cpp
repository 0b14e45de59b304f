#include "cagd/methods/method_registry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cagd/fairness/pseudo_spline.hpp"
#include "cagd/fairness/space_pseudo_spline.hpp"
#include "cagd/intrinsic/curvature_profile_design.hpp"
#include "cagd/intrinsic/knot_difference_list.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "cagd/methods/interpolant_forms.hpp"
#include "cagd/spline/hermite_spline.hpp"
#include "cagd/spline/hosaka_spline.hpp"

namespace cagd::methods {

const char* to_string(Invariance i) {
    switch (i) {
        case Invariance::none: return "none claimed";
        case Invariance::translation_scale: return "translation, uniform scaling";
        case Invariance::similarity: return "similarity (translation, rotation, uniform scaling)";
        case Invariance::affine: return "affine";
    }
    return "?";
}

namespace {

using P = ParameterType;

Eigen::Index node_count(const PointList& p, bool closed) { return closed ? p.rows() + 1 : p.rows(); }

std::vector<double> unit_lengths(const PointList& p, bool closed) { return std::vector<double>(static_cast<std::size_t>(node_count(p, closed) - 1), 1.0); }

InterpolationResult result_of(Interpolant i) {
    InterpolationResult r;
    r.interpolant = std::move(i);
    return r;
}

// End tangents shared by the S-/B2-splines and hosaka: given only with --end tangent, then both.
std::vector<Parameter> tangent_parameters() {
    return {{.name = "start-tangent", .type = P::vector, .help = "tangent at the first point, e.g. 1,0 (with --end tangent)"},
            {.name = "end-tangent", .type = P::vector, .help = "tangent at the last point (with --end tangent)"}};
}

void require_tangent_pair(const std::string& who, const ParameterValues& v) {
    const bool tangent_end = v.text("end") == "tangent";
    for (const char* name : {"start-tangent", "end-tangent"}) {
        if (tangent_end && !v.has(name)) fail_input(who, "--end tangent needs --start-tangent and --end-tangent");
        if (!tangent_end && v.has(name)) fail_input(who, std::string("--") + name + " applies with --end tangent only, the end is " + v.text("end"));
    }
}

// ---- pseudo_energy ------------------------------------------------------------------------

const fairness::PseudoSplineTables& default_pseudo_spline_tables() {
    // The 36-node fast table, built once per process (about 0.2 s on two threads).
    static const fairness::PseudoSplineTables tables =
        fairness::PseudoSplineTables::from(fairness::PseudoEnergyTable::build({36, fairness::NodePlacement::periodic}, fairness::TableMethod::fast));
    return tables;
}

// Space points (pseudo_energy section 6, extended to space): the space pseudo-spline, tangents by the planar tables' J(θ), spans by
// the space minimiser at the exact angles or from a space table (--space-table).
InterpolationResult build_space_pseudo_spline(const PointList& points, bool closed, const ParameterValues& v, const fairness::PseudoSplineTables& planar) {
    const auto mode = fairness::parse_tangent_optimization(v.text("optimize"));
    const fairness::TableOracle planar_oracle = planar.oracle();
    fairness::SpacePseudoSpline ps = [&] {
        if (v.has("space-table")) {
            const fairness::SpacePseudoEnergyTable table = fairness::SpacePseudoEnergyTable::load(v.text("space-table"));
            return fairness::space_pseudo_spline(points, fairness::TableSpaceOracle(table, planar_oracle), mode, closed);
        }
        return fairness::space_pseudo_spline(points, fairness::ExactSpaceOracle(planar_oracle), mode, closed);
    }();
    InterpolationResult r = result_of(unit_span_interpolant(std::make_shared<spline::PiecewiseHermiteCurve>(ps.curve), node_count(points, closed), unit_lengths(points, closed)));
    r.quantities = {{"length_from_tables", ps.length_from_tables()}};
    return r;
}

InterpolationResult build_pseudo_spline(const PointList& points, bool closed, const ParameterValues& v) {
    const auto mode = fairness::parse_tangent_optimization(v.text("optimize"));
    if (points.cols() == 3)
        return v.has("table") ? build_space_pseudo_spline(points, closed, v, fairness::PseudoSplineTables::from(fairness::PseudoEnergyTable::load(v.text("table"))))
                              : build_space_pseudo_spline(points, closed, v, default_pseudo_spline_tables());
    if (v.has("space-table")) fail_input("cagd::methods(pseudo-spline)", "--space-table is for 3-D points; these have 2 coordinates");
    const auto make = [&](const fairness::PseudoSplineTables& t) { return fairness::pseudo_spline_curve(points, t.oracle(), mode, closed); };
    fairness::PseudoSplineCurve ps =
        v.has("table") ? make(fairness::PseudoSplineTables::from(fairness::PseudoEnergyTable::load(v.text("table")))) : make(default_pseudo_spline_tables());
    const std::vector<std::pair<std::string, double>> quantities = {
        {"length_from_tables", ps.length_from_tables}, {"area_from_tables", ps.area_from_tables}, {"pseudo_energy_from_tables", ps.pseudo_energy_from_tables}};
    // The curve moves into the interpolant (a copy was 48 MB at 10^6 points).
    InterpolationResult r =
        result_of(unit_span_interpolant(std::make_shared<spline::PiecewiseHermiteCurve>(std::move(ps.curve)), node_count(points, closed), unit_lengths(points, closed)));
    r.quantities = quantities;
    return r;
}

InterpolationResult build_cubic(const PointList& points, bool closed, spline::ParameterSpacing spacing) {
    auto c = std::make_shared<spline::PiecewiseHermiteCurve>(spline::cubic_spline_interpolant(points, spacing, closed));
    return result_of(unit_span_interpolant(std::move(c), node_count(points, closed),
                                           spacing == spline::ParameterSpacing::chord_length ? chord_lengths(points, closed) : unit_lengths(points, closed)));
}

InterpolationResult build_hermite(const PointList& points, bool closed, spline::TangentRule rule) {
    auto c = std::make_shared<spline::PiecewiseHermiteCurve>(spline::hermite_interpolant(points, spline::hermite_tangent_directions(points, rule, closed), closed));
    return result_of(unit_span_interpolant(std::move(c), node_count(points, closed), unit_lengths(points, closed)));
}

// ---- sb2_locality -------------------------------------------------------------------------

std::vector<Parameter> locality_parameters() {
    std::vector<Parameter> p = {
        {.name = "m",
         .type = P::integer,
         .default_text = "2",
         .lower = 0,
         .upper = locality::kMaxLocality,
         .help = "locality m for every segment (eq 12; m = 4, 5 truncated by eq 13)"},
        {.name = "m-vector", .type = P::text, .help = "one m per segment instead of --m, pairs as l:r, e.g. 1,2,1:3"},
        {.name = "end", .type = P::choice, .default_text = "natural", .choices = {"natural", "tangent", "bessel"}, .help = "end condition (section 3.3)"},
        {.name = "rule",
         .type = P::choice,
         .default_text = "locality",
         .choices = {"locality", "I", "IIa", "fmill"},
         .help = "extra control point: locality (eq 12) | I (eq 15) | IIa (eq 16) | fmill (eq 17)"},
    };
    for (Parameter& t : tangent_parameters()) p.push_back(std::move(t));
    return p;
}

MethodClaims locality_claims(const ParameterValues& v) {
    return {.parametric_continuity = 2,
            .geometric_continuity = 2,
            .parameter = "uniform",
            .invariance = v.text("end") == "tangent" ? Invariance::none : Invariance::affine,
            .max_dimension = 3};
}

InterpolationResult build_locality(const PointList& points, bool closed, const ParameterValues& v, locality::SplineForm form) {
    const std::string who = std::string("cagd::methods(") + (form == locality::SplineForm::s_spline ? "s-spline" : "b2-spline") + ")";
    locality::Options o;
    o.form = form;
    if (v.given("m") && v.has("m-vector")) fail_input(who, "give --m or --m-vector, not both");
    if (v.has("m-vector"))
        o.m = locality::parse_m_vector(v.text("m-vector"));
    else
        o.m = {{v.integer("m"), v.integer("m")}};
    o.closed = closed;
    const std::string& rule = v.text("rule");
    o.rule = rule == "I"       ? locality::ExtraPointRule::method_I
             : rule == "IIa"   ? locality::ExtraPointRule::method_IIa
             : rule == "fmill" ? locality::ExtraPointRule::fmill
                               : locality::ExtraPointRule::locality;
    const std::string& end = v.text("end");
    o.start.kind = o.end.kind = end == "tangent" ? locality::EndKind::tangent : end == "bessel" ? locality::EndKind::bessel : locality::EndKind::natural;
    require_tangent_pair(who, v);
    if (o.start.kind == locality::EndKind::tangent) {
        o.start.tangent = v.vector("start-tangent");
        o.end.tangent = v.vector("end-tangent");
    }
    auto c = std::make_shared<BSplineCurve>(locality::interpolate(points, o).curve);
    return result_of(unit_span_interpolant(std::move(c), node_count(points, closed), unit_lengths(points, closed)));
}

// ---- hosaka -------------------------------------------------------------------------------

// Order 30 takes about 1.4 s on 6 points and order 50 about 10 s (2m unknowns per point):
// 30 keeps a run within seconds.
constexpr int kMaxHosakaOrder = 30;

InterpolationResult build_hosaka(const PointList& points, bool closed, const ParameterValues& v) {
    spline::HosakaSplineOptions o;
    o.scale = v.text("scale") == "unit" ? spline::HosakaScale::unit : spline::HosakaScale::chord;
    o.closed = closed;
    require_tangent_pair("cagd::methods(hosaka)", v);
    if (v.text("end") == "tangent") {
        o.end = spline::HosakaEnd::tangent;
        o.start_tangent = v.vector("start-tangent");
        o.end_tangent = v.vector("end-tangent");
    }
    const int m = v.integer("m");
    auto c = m == 1 ? std::make_shared<spline::HosakaCurve>(spline::hosaka_c2_spline(points, o).curve) : std::make_shared<spline::HosakaCurve>(spline::hosaka_spline(points, m, o));
    return result_of(
        unit_span_interpolant(std::move(c), node_count(points, closed), o.scale == spline::HosakaScale::chord ? chord_lengths(points, closed) : unit_lengths(points, closed)));
}

// ---- curvature_profile --------------------------------------------------------------------

InterpolationResult build_curvature_profile(const PointList& points, bool closed, const ParameterValues& v) {
    using namespace intrinsic;
    const std::string who = "cagd::methods(curvature-profile)";
    const std::string& knots = v.text("knots");
    if (v.has("degree") && knots.empty()) fail_input(who, "--degree applies to a --knots list; without it the layout is degree 2");
    const int spans = static_cast<int>(points.rows()) - (closed ? 0 : 1);
    const std::vector<SegmentShape> span_shapes =
        v.has("spans") ? parse_span_shapes(v.text("spans")) : std::vector<SegmentShape>(static_cast<std::size_t>(spans), SegmentShape::free);
    if (static_cast<int>(span_shapes.size()) != spans)
        fail_input(who,
                   "--spans gives " + std::to_string(span_shapes.size()) + " shapes but the " + std::to_string(points.rows()) + " points make " + std::to_string(spans) + " spans");
    const KnotLayout layout = knots.empty() ? span_layout(span_shapes) : parse_knot_difference_list(knots, v.has("degree") ? v.integer("degree") : 2).layout;
    CurvatureProfileProblem problem{points, layout, segment_shapes(layout, span_shapes), {}, closed, 0};
    add_natural_open_ends(problem);
    require_valid_problem(problem, who);
    const CurvatureProfileSolution sol = solve_curvature_profile_auto(problem);
    InterpolationResult r;
    r.outcome = sol.outcome;
    for (const auto& h : sol.history) {
        std::ostringstream residual;
        residual << h.residual;
        r.report.emplace_back("newton_" + std::to_string(h.iteration) + "_residual", residual.str());
        r.report.emplace_back("newton_" + std::to_string(h.iteration) + "_rank", std::to_string(h.rank));
    }
    if (!sol.outcome.ok() || !sol.curve) return r;
    const int m = design_equations(problem), N = design_unknowns(problem);
    r.report.emplace_back("equations", std::to_string(m));
    r.report.emplace_back("unknowns", std::to_string(N));
    r.report.emplace_back("rank", sol.rank < 0 ? std::string("full (sparse LU)") : std::to_string(sol.rank));
    if (m < N || (sol.rank >= 0 && sol.rank < N)) r.report.emplace_back("solution", "minimum-norm Newton steps chose one of several solutions");
    // Four decimals as the paper prints, more where the shortest span needs them to stay nonzero.
    const std::vector<double> lengths = sol.segment_lengths();
    const double shortest = *std::min_element(lengths.begin(), lengths.end());
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(shortest))) + 1, 4, 17);
    if (shortest >= 1e-17) r.report.emplace_back("knot_difference_list", format_knot_difference_list(layout, lengths, decimals));
    const std::vector<double>& w = sol.curve->breakpoints();
    std::vector<double> nodes;
    for (int j = 0; j <= layout.spans(); ++j) nodes.push_back(w[static_cast<std::size_t>(layout.first_segment(j))]);
    r.interpolant = Interpolant{std::make_shared<IntrinsicCurve>(*sol.curve), nodes, std::vector<double>(static_cast<std::size_t>(layout.spans()), 1.0)};
    return r;
}

// ---- Boost.Math peers ---------------------------------------------------------------------

MethodClaims boost_componentwise_claims(const ParameterValues&) {
    return {.parametric_continuity = 1,
            .parameter = "chord length",
            .invariance = Invariance::translation_scale,
            .supports_closed = false,
            .min_points = 4,
            .min_points_closed = 0,
            .max_dimension = 3};
}

std::vector<Method> make_registry() {
    const auto fixed = [](MethodClaims c) { return [c](const ParameterValues&) { return c; }; };
    std::vector<Method> r;
    r.push_back({
        .name = "pseudo-spline",
        .paper = "pseudo_energy",
        .source = "eq (4)-(12), sec 4.1-4.2",
        .summary = "cubic Hermite spline of minimum pseudo-energy from a J, r0, r1 table; tangents by the 3-point pseudo-elastic rod",
        .parameters = {{.name = "optimize",
                        .type = P::choice,
                        .default_text = "exact",
                        .choices = {"none", "exact", "approx"},
                        .help = "tangent optimisation of eq (12): none, exact (Brent) or approx (3-point parabola, Table 4)"},
                       {.name = "table", .type = P::text, .help = "pseudo-energy table written by cagd energy-table (absent: the 36-node fast table, built in memory)"},
                       {.name = "space-table",
                        .type = P::text,
                        .help = "3-D points: space pseudo-energy table (SpacePseudoEnergyTable, e.g. from cagd_space_table_mpi) for the spans (absent: the space minimiser at "
                                "each span's angles)"}},
        .claims =
            [](const ParameterValues& v) {
                return MethodClaims{.geometric_continuity = 1,
                                    .parameter = "u (unit spans)",
                                    .invariance = v.text("optimize") == "exact" ? Invariance::none : Invariance::similarity,
                                    .max_dimension = 3};
            },
        .build = build_pseudo_spline,
        .presets = {{"pseudo-spline-none", {{"optimize", "none"}}}, {"pseudo-spline-exact", {{"optimize", "exact"}}}, {"pseudo-spline-approx", {{"optimize", "approx"}}}},
    });
    r.push_back({
        .name = "cubic-a",
        .aliases = {"cubic-bspline"},
        .paper = "pseudo_energy",
        .source = "sec 4.2 cubic spline A; = sb2_locality eq (10)",
        .summary = "natural C2 cubic spline, uniform parameter (the conventional interpolating cubic B-spline)",
        .claims = fixed({.parametric_continuity = 2, .geometric_continuity = 2, .parameter = "uniform", .invariance = Invariance::affine, .max_dimension = 3}),
        .build = [](const PointList& p, bool closed, const ParameterValues&) { return build_cubic(p, closed, spline::ParameterSpacing::uniform); },
    });
    r.push_back({
        .name = "cubic-b",
        .paper = "pseudo_energy",
        .source = "sec 4.2 cubic spline B",
        .summary = "natural C2 cubic spline, chord-length parameter",
        .claims = fixed({.parametric_continuity = 2, .geometric_continuity = 2, .parameter = "chord length", .invariance = Invariance::similarity, .max_dimension = 3}),
        .build = [](const PointList& p, bool closed, const ParameterValues&) { return build_cubic(p, closed, spline::ParameterSpacing::chord_length); },
    });
    r.push_back({
        .name = "hermite-a",
        .paper = "pseudo_energy",
        .source = "sec 4.2 Hermite curve A",
        .summary = "cubic Hermite curve, tangents along the chord of the neighbours",
        .claims = fixed({.geometric_continuity = 1, .parameter = "u (unit spans)", .invariance = Invariance::similarity, .max_dimension = 3}),
        .build = [](const PointList& p, bool closed, const ParameterValues&) { return build_hermite(p, closed, spline::TangentRule::chord_of_neighbours); },
    });
    r.push_back({
        .name = "hermite-b",
        .paper = "pseudo_energy",
        .source = "sec 4.2 Hermite curve B",
        .summary = "cubic Hermite curve, tangents of the circle through three neighbours",
        .claims = fixed({.geometric_continuity = 1, .parameter = "u (unit spans)", .invariance = Invariance::similarity, .min_points = 3, .max_dimension = 3}),
        .build = [](const PointList& p, bool closed, const ParameterValues&) { return build_hermite(p, closed, spline::TangentRule::circle); },
    });
    r.push_back({
        .name = "s-spline",
        .paper = "sb2_locality",
        .source = "eq (3), (11)-(13), sec 3.3",
        .summary = "S-spline with controllable locality m",
        .parameters = locality_parameters(),
        .claims = locality_claims,
        .build = [](const PointList& p, bool closed, const ParameterValues& v) { return build_locality(p, closed, v, locality::SplineForm::s_spline); },
        .presets = {{"s-spline-m1", {{"m", "1"}}}, {"s-spline-m2", {{"m", "2"}}}, {"s-spline-m4", {{"m", "4"}}}},
    });
    r.push_back({
        .name = "b2-spline",
        .paper = "sb2_locality",
        .source = "eq (7), (11)-(13), sec 3.3",
        .summary = "B2-spline with controllable locality m",
        .parameters = locality_parameters(),
        .claims = locality_claims,
        .build = [](const PointList& p, bool closed, const ParameterValues& v) { return build_locality(p, closed, v, locality::SplineForm::b2_spline); },
        .presets = {{"b2-spline-m1", {{"m", "1"}}}, {"b2-spline-m2", {{"m", "2"}}}, {"b2-spline-m4", {{"m", "4"}}}},
    });
    std::vector<Parameter> hosaka_parameters = {
        {.name = "m",
         .type = P::integer,
         .default_text = "1",
         .lower = 1,
         .upper = kMaxHosakaOrder,
         .help = "segment order m: segments of degree 2m+1, continuous to order 2m (m = 1: eq 18-20)"},
        {.name = "scale", .type = P::choice, .default_text = "chord", .choices = {"chord", "unit"}, .help = "scale factors: chord (k_i = |A_i|/|A_i+1|, eq 19) or unit (k_i = 1)"},
        {.name = "end", .type = P::choice, .default_text = "natural", .choices = {"natural", "tangent"}, .help = "end condition"},
    };
    for (Parameter& t : tangent_parameters()) hosaka_parameters.push_back(std::move(t));
    r.push_back({
        .name = "hosaka",
        .paper = "hosaka",
        .source = "eq (15), (18)-(20), sec 3",
        .summary = "generalised Hermite spline with scale factors, C2 (order m: C^2m)",
        .parameters = std::move(hosaka_parameters),
        .claims =
            [](const ParameterValues& v) {
                const bool chord = v.text("scale") == "chord";
                return MethodClaims{.parametric_continuity = 2,
                                    .geometric_continuity = 2,
                                    .parameter = chord ? "chord length" : "uniform",
                                    .invariance = v.text("end") == "tangent" ? Invariance::none
                                                  : chord                    ? Invariance::similarity
                                                                             : Invariance::affine,
                                    .max_dimension = 3};
            },
        .build = build_hosaka,
        .presets = {{"hosaka-c2-chord", {{"scale", "chord"}}}, {"hosaka-c2-unit", {{"scale", "unit"}}}},
    });
    r.push_back({
        .name = "curvature-profile",
        .paper = "curvature_profile",
        .source = "sec 2-4, eq (2)-(4)",
        .summary = "curvature piecewise polynomial in arc length (all spans free: a clothoid spline), natural open ends",
        .parameters = {{.name = "spans", .type = P::text, .help = "one shape per span, free | line | arc | clothoid, e.g. line,free,arc (absent: all free)"},
                       {.name = "knots", .type = P::text, .help = "knot-difference list of psi, e.g. \"{0, S0, 0, {S1, S2}, S3, 0}\" (absent: from --spans, degree 2)"},
                       {.name = "degree", .type = P::integer, .lower = 2, .upper = 3, .help = "degree of psi for --knots: 2 (clothoid) or 3 (the paper's cubic; absent: 2)"}},
        .claims = fixed({.parametric_continuity = 2, .geometric_continuity = 2, .parameter = "arc length", .invariance = Invariance::similarity}),
        .build = build_curvature_profile,
        .iterative = true,
    });
    r.push_back({
        .name = "boost-pchip",
        .paper = "Boost.Math",
        .source = "boost::math::interpolators::pchip on x(t), y(t)",
        .summary = "monotone piecewise cubic Hermite per coordinate over chord length (a peer)",
        .claims = boost_componentwise_claims,
        .build = [](const PointList& p, bool, const ParameterValues&) { return result_of(boost_pchip_interpolant(p)); },
    });
    r.push_back({
        .name = "boost-makima",
        .paper = "Boost.Math",
        .source = "boost::math::interpolators::makima on x(t), y(t)",
        .summary = "modified Akima per coordinate over chord length (a peer)",
        .claims = boost_componentwise_claims,
        .build = [](const PointList& p, bool, const ParameterValues&) { return result_of(boost_makima_interpolant(p)); },
    });
    r.push_back({
        .name = "boost-catmull-rom",
        .paper = "Boost.Math",
        .source = "boost::math::catmull_rom, centripetal (alpha = 1/2)",
        .summary = "centripetal Catmull-Rom spline (a peer)",
        .claims = fixed({.parametric_continuity = 1,
                         .parameter = "centripetal (sum of sqrt chord)",
                         .invariance = Invariance::similarity,
                         .min_points = 4,
                         .min_points_closed = 4,
                         .max_dimension = 3}),
        .build = [](const PointList& p, bool closed, const ParameterValues&) { return result_of(boost_catmull_rom_interpolant(p, closed)); },
    });
    return r;
}

}  // namespace

const std::vector<Method>& registry() {
    static const std::vector<Method> methods = make_registry();
    return methods;
}

std::vector<std::string> method_names() {
    std::vector<std::string> names;
    for (const Method& m : registry()) {
        names.push_back(m.name);
        for (const std::string& a : m.aliases) names.push_back(a);
    }
    return names;
}

const Method& find_method(const std::string& name) {
    for (const Method& m : registry()) {
        if (m.name == name) return m;
        for (const std::string& a : m.aliases)
            if (a == name) return m;
    }
    std::string known;
    for (const std::string& n : method_names()) known += (known.empty() ? "" : ", ") + n;
    fail_input("cagd::methods::find_method", "unknown method '" + name + "'; known: " + known);
}

namespace {

// Squared distances must stay finite and nonzero: coordinates beyond 1e150 overflow them (and the
// methods' products of differences; Boost's centripetal parameter read past its knots at 4e289,
// found by fuzz_interpolate), chords below 1e-150 (relative to the coordinates' size when that
// exceeds 1) underflow them.
constexpr double kLargestCoordinate = 1e150;
constexpr double kShortestChord = 1e-150;

}  // namespace

InterpolationResult interpolate(const Method& method, const PointList& points, bool closed, const ParameterValues& values) {
    const MethodClaims claims = method.claims(values);
    const std::string who = "cagd::methods::interpolate(" + method.name + ")";
    if (closed && !claims.supports_closed) fail_input(who, "draws open curves only (--closed is not supported)");
    require_valid_points(points, closed ? claims.min_points_closed : claims.min_points, true, closed, who);
    if (points.cols() < 2 || points.cols() > claims.max_dimension)
        fail_input(who, "needs points of dimension 2" + std::string(claims.max_dimension == 3 ? " or 3" : "") + ", got " + std::to_string(points.cols()));
    // Valid points whose arithmetic leaves double precision: differences of coordinates near 1e308
    // overflow, and chords below 1e-150 square to 0 (their norm underflows). The result is not
    // representable: an outcome, not bad input.
    const double largest = points.cwiseAbs().maxCoeff();
    if (largest > kLargestCoordinate) {
        InterpolationResult r;
        r.outcome = {Status::not_representable, method.name + ": coordinates up to " + full_precision(largest) +
                                                    " overflow its arithmetic (at most 1e150: squared distances must stay finite); scale the points down"};
        return r;
    }
    for (Eigen::Index i = 0; i + 1 < points.rows() || (closed && i < points.rows()); ++i) {
        const Eigen::Index next = i + 1 == points.rows() ? 0 : i + 1;
        const auto d = points.row(next) - points.row(i);  // an expression: no allocation per point
        const double chord = d.norm();
        if (!(chord >= kShortestChord * std::max(1.0, largest))) {
            InterpolationResult r;
            r.outcome = {Status::not_representable, method.name + ": points " + std::to_string(i) + " and " + std::to_string(next) + " differ by " +
                                                        full_precision(d.cwiseAbs().maxCoeff()) +
                                                        " at most per coordinate: below 1e-150 (times the coordinates' size) the chord's square underflows; scale the points up"};
            return r;
        }
    }
    try {
        return method.build(points, closed, values);
    } catch (const std::domain_error& e) {  // Boost.Math's own precondition checks
        fail_input(who, std::string("Boost.Math refused the points: ") + e.what());
    }
}

InterpolationResult interpolate(const std::string& name, const PointList& points, bool closed, const ParameterText& values) {
    for (const Method& m : registry())
        for (const Preset& p : m.presets)
            if (p.name == name) {
                ParameterText merged = values;
                merged.insert(p.values.begin(), p.values.end());  // keeps what `values` gives
                return interpolate(m, points, closed, parse_parameter_values(m.name, m.parameters, merged));
            }
    const Method& m = find_method(name);
    return interpolate(m, points, closed, parse_parameter_values(m.name, m.parameters, values));
}

namespace {

Configuration configure(const Method& m, const std::string& name, const ParameterText& text) {
    Configuration c{name, &m, parse_parameter_values(m.name, m.parameters, text), {}};
    c.claims = m.claims(c.values);
    return c;
}

}  // namespace

const std::vector<Configuration>& configurations() {
    static const std::vector<Configuration> all = [] {
        std::vector<Configuration> out;
        for (const Method& m : registry()) {
            if (m.presets.empty()) out.push_back(configure(m, m.name, {}));
            for (const Preset& p : m.presets) out.push_back(configure(m, p.name, p.values));
        }
        return out;
    }();
    return all;
}

Configuration find_configuration(const std::string& name) {
    for (const Configuration& c : configurations())
        if (c.name == name) return c;
    for (const Method& m : registry()) {
        bool match = m.name == name;
        for (const std::string& a : m.aliases) match = match || a == name;
        if (match) return configure(m, m.name, {});
    }
    std::string known;
    for (const Configuration& c : configurations()) known += (known.empty() ? "" : ", ") + c.name;
    fail_input("cagd::methods::find_configuration", "unknown method '" + name + "'; known: " + known + " (or any method name, with its defaults)");
}

InterpolationResult interpolate(const Configuration& configuration, const PointList& points, bool closed) {
    return interpolate(*configuration.method, points, closed, configuration.values);
}

namespace {

std::string claims_text(const MethodClaims& c) {
    std::string s;
    if (c.parametric_continuity > 0) s += "C" + std::to_string(c.parametric_continuity) + " in τ (" + c.parameter + ")";
    if (c.geometric_continuity > 0) s += (s.empty() ? "" : ", ") + std::string("G") + std::to_string(c.geometric_continuity);
    s += std::string("; invariance: ") + to_string(c.invariance);
    s += "; " + std::string(c.max_dimension == 3 ? "2-D, 3-D" : "2-D");
    s += c.supports_closed ? "; open, closed" : "; open only";
    s += "; points >= " + std::to_string(c.min_points);
    return s;
}

std::string parameters_text(const Method& m, const char* separator) {
    std::string s;
    for (const Parameter& p : m.parameters) s += (s.empty() ? "" : separator) + std::string("--") + p.name + (p.default_text.empty() ? "" : " " + p.default_text);
    return s.empty() ? "none" : s;
}

}  // namespace

std::string registry_markdown() {
    std::string s = "| method | paper | source | what it is | parameters (default) | claims (defaults) | compared as |\n|---|---|---|---|---|---|---|\n";
    for (const Method& m : registry()) {
        std::string presets;
        for (const Preset& p : m.presets) presets += (presets.empty() ? "" : ", ") + std::string("`") + p.name + "`";
        std::string name = "`" + m.name + "`";
        for (const std::string& a : m.aliases) name += " (alias `" + a + "`)";
        s += "| " + name + " | " + m.paper + " | " + m.source + " | " + m.summary + " | " + parameters_text(m, ", ") + " | " +
             claims_text(m.claims(parse_parameter_values(m.name, m.parameters, {}))) + " | " + (presets.empty() ? "`" + m.name + "`" : presets) + " |\n";
    }
    return s;
}

std::string registry_listing() {
    std::string s;
    for (const Method& m : registry()) {
        s += m.name;
        for (const std::string& a : m.aliases) s += " (alias " + a + ")";
        s += "  [" + m.paper + " " + m.source + "]  " + m.summary + "\n";
        s += "    claims: " + claims_text(m.claims(parse_parameter_values(m.name, m.parameters, {}))) + "\n";
        for (const Parameter& p : m.parameters) s += "    --" + p.name + "  " + p.domain() + (p.default_text.empty() ? "" : ", default " + p.default_text) + ": " + p.help + "\n";
    }
    return s;
}

}  // namespace cagd::methods
