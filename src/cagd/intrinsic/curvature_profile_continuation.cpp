#include "cagd/intrinsic/curvature_profile_design.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "cagd/intrinsic/detail/bezier_extraction.hpp"
#include "cagd/intrinsic/detail/design_system.hpp"

namespace cagd::intrinsic {

Eigen::VectorXd continuation_start(const CurvatureProfileProblem& P, const Eigen::VectorXd& start,
                                   const NewtonOptions& options) {
    require_valid_problem(P, "intrinsic::continuation_start");
    const KnotLayout& L = P.layout;
    const int n = L.spans(), p = L.degree();
    if (P.closed || start.size() != design_unknowns(P) || n < 4 * kContinuationWindowSpans) return start;
    const std::vector<SegmentShape> free(static_cast<std::size_t>(n), SegmentShape::free);
    if (!(L == span_layout(free)) || P.shapes != segment_shapes(L, free)) return start;
    for (const DesignCondition& c : P.conditions)
        if (c.kind == DesignCondition::Kind::segment_length || (c.index != 0 && c.index != n)) return start;
    for (int i = 0; i < L.independent_lengths(); ++i)
        if (!(start(i) > 0) || !std::isfinite(start(i))) return start;
    // The rows start leaves unsatisfied: the interpolation rows of spans i0..i1 only (span i: rows
    // 2i, 2i + 1; one segment per span, its own length and ordinates i..i + p).
    const Eigen::VectorXd f = design_system(P, start, false).f;
    const double tol = options.tolerance;
    int i0 = n, i1 = -1;
    for (Eigen::Index r = 0; r < f.size(); ++r)
        if (!(std::abs(f(r)) <= tol)) {
            if (r >= 2 * n) return start;  // an end condition: not a moved point
            i0 = std::min(i0, static_cast<int>(r / 2)), i1 = std::max(i1, static_cast<int>(r / 2));
        }
    if (i1 < 0) return start;  // already solved
    const int a = std::max(0, i0 - kContinuationWindowSpans), b = std::min(n, i1 + 1 + kContinuationWindowSpans),
              m = b - a;
    if (4 * m > n) return start;
    // start's ψ at the window's ends: the first and last Bézier ordinates of segments a and b − 1.
    std::vector<double> lengths(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) lengths[static_cast<std::size_t>(j)] = start(L.length_index(j));
    const int l = L.independent_lengths();
    const auto psi_at = [&](int segment, bool at_end) {
        double knots[8], bezier[5];
        TangentAngleSpline::local_farin_knots_into(L, lengths, segment, knots);
        detail::bezier_from_de_boor(p, knots, start.data() + l + (L.last_knot_of_breakpoint(segment) - p + 1), bezier);
        return at_end ? bezier[p] : bezier[0];
    };
    const std::vector<SegmentShape> window_free(static_cast<std::size_t>(m), SegmentShape::free);
    CurvatureProfileProblem W{P.points.middleRows(a, m + 1), span_layout(window_free), {}, {}, false, 0};
    W.shapes = segment_shapes(W.layout, window_free);
    const double psi_a = psi_at(a, false);
    if (a > 0) W.conditions.push_back({.kind = DesignCondition::Kind::tangent_angle, .index = 0, .value = psi_a});
    if (b < n)
        W.conditions.push_back(
            {.kind = DesignCondition::Kind::tangent_angle, .index = m, .value = psi_at(b - 1, true)});
    for (DesignCondition c : P.conditions) {
        if (a == 0 && c.index == 0) W.conditions.push_back(c);
        if (b == n && c.index == n) c.index = m, W.conditions.push_back(c);
    }
    // The window's own C2 start, turned by whole turns onto start's branch of ψ.
    Eigen::VectorXd w_start = c2_start(W);
    const int wl = W.layout.independent_lengths();
    w_start.tail(W.layout.ordinates()).array() +=
        2.0 * std::numbers::pi * std::round((psi_a - w_start(wl)) / (2.0 * std::numbers::pi));
    NewtonOptions cold = options;  // the window's own solve starts cold: no contraction required
    cold.required_contraction = 0.0;
    const CurvatureProfileSolution window = solve_curvature_profile_auto(W, w_start, cold);
    if (!(window.outcome.ok() && window.curve)) return start;
    // Set in: every window length; the ordinates whose p knots are the window's interior breakpoints
    // (the same blossom values as in the whole), and at an end of the curve the clamped ones too.
    Eigen::VectorXd u = start;
    for (int j = 0; j < m; ++j) u(L.length_index(a + j)) = window.u(W.layout.length_index(j));
    const int first = a == 0 ? 0 : p, last = b == n ? m + p - 1 : m - 1;
    for (int i = first; i <= last; ++i) u(l + a + i) = window.u(wl + i);
    return u;
}

}  // namespace cagd::intrinsic
