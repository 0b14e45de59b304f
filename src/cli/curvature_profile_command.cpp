#include "cli/curvature_profile_command.hpp"

#include <iostream>

#include "cli/curve_output.hpp"
#include "intrinsic/curvature_profile_design.hpp"

namespace cagd::cli {

int run_curvature_profile(const PointList& points, const CurvatureProfileArgs& a) {
    using namespace intrinsic;
    const std::string who = "cagd interpolate --method curvature-profile";
    if (a.degree_given && a.knots.empty()) fail_input(who, "--degree applies to a --knots list; without it the layout is degree 2");
    const int spans = static_cast<int>(points.rows()) - (a.closed ? 0 : 1);
    if (spans < 1) fail_input(who, "needs at least 2 points, got " + std::to_string(points.rows()));
    const std::vector<SegmentShape> span_shapes = a.spans.empty() ? std::vector<SegmentShape>(static_cast<std::size_t>(spans), SegmentShape::free) : parse_span_shapes(a.spans);
    if (static_cast<int>(span_shapes.size()) != spans)
        fail_input(who, "--spans gives " + std::to_string(span_shapes.size()) + " shapes but the " + std::to_string(points.rows()) + " points make " + std::to_string(spans) + " spans");
    const KnotLayout layout = a.knots.empty() ? span_layout(span_shapes) : parse_knot_difference_list(a.knots, a.degree).layout;
    CurvatureProfileProblem problem{points, layout, segment_shapes(layout, span_shapes), {}, a.closed, 0};
    add_natural_open_ends(problem);
    require_valid_problem(problem, who);
    const int m = design_equations(problem), N = design_unknowns(problem);
    const CurvatureProfileSolution sol = solve_curvature_profile_auto(problem);
    for (const auto& h : sol.history) std::cout << "newton," << h.iteration << ",residual," << h.residual << ",rank," << h.rank << "\n";
    if (!sol.outcome.ok()) {
        std::cerr << "cagd: no result: " << sol.outcome.message << "\n";
        return 1;
    }
    std::cout << "equations," << m << ",unknowns," << N << ",rank," << (sol.rank < 0 ? std::string("full (sparse LU)") : std::to_string(sol.rank))
              << (m < N || (sol.rank >= 0 && sol.rank < N) ? ",minimum-norm Newton steps chose one of several solutions" : "") << "\n";
    std::cout << "knot_difference_list,\"" << format_knot_difference_list(layout, sol.segment_lengths(), 4) << "\"\n";
    write_curve(*sol.curve, a.samples, a.out);
    return 0;
}

}  // namespace cagd::cli
