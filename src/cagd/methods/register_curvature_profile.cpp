// The method of curvature_profile (Kuroda, Higashi, Saito, Watanabe): the composite interpolant
// whose curvature is piecewise polynomial in arc length (sections 2-4, eq 2-6); and Spiro, its
// degree-4 member (Levien 2009): curvature a cubic polynomial of arc length on every span, G4 at
// every point, solved by the same Newton iteration.
#include "cagd/methods/detail/registration.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cagd/intrinsic/curvature_profile_design.hpp"
#include "cagd/intrinsic/knot_difference_list.hpp"
#include "cagd/intrinsic/spiro.hpp"

namespace cagd::methods::detail {

namespace {

// The registry's result of a solved design: the Newton history, the system's size and rank, the
// knot-difference list, and the curve with a node at the start of every span (moved out of
// sol.curve, which is left empty; the other members stay).
InterpolationResult solved_result(const intrinsic::CurvatureProfileProblem& problem,
                                  intrinsic::CurvatureProfileSolution& sol) {
    using namespace intrinsic;
    const KnotLayout& layout = problem.layout;
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
    r.report.emplace_back("rank", sol.history.size() == 1 ? std::string("not needed (the start met the tolerance)")
                                  : sol.rank < 0          ? std::string("full (sparse LU)")
                                                          : std::to_string(sol.rank));
    if (m < N || (sol.rank >= 0 && sol.rank < N))
        r.report.emplace_back("solution", "minimum-norm Newton steps chose one of several solutions");
    // Four decimals as the paper prints, more where the shortest span needs them to stay nonzero.
    const std::vector<double> lengths = sol.segment_lengths();
    const double shortest = *std::min_element(lengths.begin(), lengths.end());
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(shortest))) + 1, 4, 17);
    if (shortest >= 1e-17)
        r.report.emplace_back("knot_difference_list", format_knot_difference_list(layout, lengths, decimals));
    const std::vector<double>& w = sol.curve->breakpoints();
    std::vector<double> nodes;
    for (int j = 0; j <= layout.spans(); ++j) nodes.push_back(w[static_cast<std::size_t>(layout.first_segment(j))]);
    r.interpolant = Interpolant{std::make_shared<IntrinsicCurve>(std::move(*sol.curve)), std::move(nodes),
                                std::vector<double>(static_cast<std::size_t>(layout.spans()), 1.0)};
    sol.curve.reset();
    return r;
}

// The design problem of the points under the method's parameters (the spans' shapes, a knot list).
intrinsic::CurvatureProfileProblem curvature_profile_problem(const PointList& points, bool closed,
                                                             const ParameterValues& v) {
    using namespace intrinsic;
    const std::string who = "cagd::methods(curvature-profile)";
    const std::string& knots = v.text("knots");
    if (v.has("degree") && knots.empty())
        fail_input(who, "--degree applies to a --knots list; without it the layout is degree 2");
    const int spans = static_cast<int>(points.rows()) - (closed ? 0 : 1);
    const std::vector<SegmentShape> span_shapes =
        v.has("spans") ? parse_span_shapes(v.text("spans"))
                       : std::vector<SegmentShape>(static_cast<std::size_t>(spans), SegmentShape::free);
    if (static_cast<int>(span_shapes.size()) != spans)
        fail_input(who, "--spans gives " + std::to_string(span_shapes.size()) + " shapes but the " +
                            std::to_string(points.rows()) + " points make " + std::to_string(spans) + " spans");
    const KnotLayout layout = knots.empty()
                                  ? span_layout(span_shapes)
                                  : parse_knot_difference_list(knots, v.has("degree") ? v.integer("degree") : 2).layout;
    CurvatureProfileProblem problem{points, layout, segment_shapes(layout, span_shapes), {}, closed, 0};
    add_natural_open_ends(problem);
    require_valid_problem(problem, who);
    return problem;
}

// The solve from `start` (empty: the C2 start of the design), its final iterate kept for a rebuild.
// Continuation from an earlier solution must shrink the residual at least this much per Newton step,
// or it is abandoned for the design's own start. Inside Newton's basin each step shrinks it several
// times (10^5 points from the design's start: ratios 0.25, 0.035, 0.002, …); outside, Newton wanders
// (the same points from the unmoved solution, one point moved by a chord: ratios 0.7 … 2.5).
constexpr double kContinuationContraction = 0.5;

InterpolationResult curvature_profile_from(const ValidPoints& valid, const ParameterValues& v,
                                           const Eigen::VectorXd& start) {
    const intrinsic::CurvatureProfileProblem problem = curvature_profile_problem(valid.points(), valid.closed(), v);
    // A start of another size is not one of these unknowns (the layout and the conditions depend on
    // the number of points and the parameters only): the design's own start then. So too when
    // Newton from the given start does not contract (the points moved too far for continuation).
    // Where a few points moved, the start is first re-solved around them (continuation_start).
    intrinsic::CurvatureProfileSolution sol;
    if (start.size() == intrinsic::design_unknowns(problem)) {
        intrinsic::NewtonOptions continuation;
        continuation.required_contraction = kContinuationContraction;
        sol = intrinsic::solve_curvature_profile_auto(
            problem, intrinsic::continuation_start(problem, start, continuation), continuation);
    }
    if (!(sol.outcome.ok() && sol.curve)) sol = intrinsic::solve_curvature_profile_auto(problem);
    InterpolationResult r = solved_result(problem, sol);
    if (r.interpolant) r.solver_state = sol.u;
    return r;
}

InterpolationResult build_curvature_profile(const ValidPoints& valid, const ParameterValues& v) {
    return curvature_profile_from(valid, v, {});
}

// Spiro (intrinsic/spiro.hpp): Levien's chordwise Newton polished by the arc-length one; from
// `start` (non-empty), the arc-length Newton alone, continued as the curvature profile's is.
InterpolationResult spiro_from(const ValidPoints& valid, const ParameterValues&, const Eigen::VectorXd& start) {
    const PointList& points = valid.points();
    const bool closed = valid.closed();
    intrinsic::SpiroSolution spiro = start.size() > 0
                                         ? intrinsic::solve_spiro_from(points, closed, start, kContinuationContraction)
                                         : intrinsic::solve_spiro(points, closed);
    InterpolationResult r = solved_result(spiro.problem, spiro.solution);
    r.report.insert(r.report.begin(), {"chordwise_newton_iterations", std::to_string(spiro.chordwise.iterations)});
    if (r.interpolant) r.solver_state = spiro.solution.u;
    return r;
}

InterpolationResult build_spiro(const ValidPoints& valid, const ParameterValues& v) { return spiro_from(valid, v, {}); }

}  // namespace

std::vector<Method> curvature_profile_methods() {
    std::vector<Method> r;
    r.push_back({
        .name = "curvature-profile",
        .paper = "curvature_profile",
        .source = "sec 2-4, eq (2)-(4)",
        .summary =
            "curvature piecewise polynomial in arc length (all spans free: a clothoid spline), natural open ends",
        .parameters =
            {{.name = "spans",
              .type = P::text,
              .help = "one shape per span, free | line | arc | clothoid, e.g. line,free,arc (absent: all free)"},
             {.name = "knots",
              .type = P::text,
              .help =
                  "knot-difference list of psi, e.g. \"{0, S0, 0, {S1, S2}, S3, 0}\" (absent: from --spans, degree 2)"},
             {.name = "degree",
              .type = P::integer,
              .lower = 2,
              .upper = 3,
              .help = "degree of psi for --knots: 2 (clothoid) or 3 (the paper's cubic; absent: 2)"}},
        .claims = fixed({.parametric_continuity = 2,
                         .geometric_continuity = 2,
                         .parameter = "arc length",
                         .invariance = Invariance::similarity}),
        .build = build_curvature_profile,
        .iterative = true,
        .rebuild = curvature_profile_from,
    });
    r.push_back({
        .name = "spiro",
        .paper = "Levien 2009",
        .source = "R. Levien, From Spiral to Spline (PhD thesis, 2009), ch. 8; curvature_profile eq (2)-(6) with a "
                  "quartic psi",
        .summary = "Spiro: curvature a cubic polynomial of arc length per span, G4 at every point (libspiro's 'o' "
                   "points; a peer)",
        .claims = fixed({.parametric_continuity = 4,
                         .geometric_continuity = 4,
                         .parameter = "arc length",
                         .invariance = Invariance::similarity,
                         .always_solves = false}),
        .build = build_spiro,
        .iterative = true,
        .rebuild = spiro_from,
    });
    return r;
}

}  // namespace cagd::methods::detail
