#pragma once
/// @file
/// Knot structure of the tangent-angle B-spline ψ(s) and its knot-difference list
/// (curvature_profile, section 2 and Fig. 1).
///
/// ψ(s) is a B-spline of degree p in arc length s (the paper: p = 3, curvature κ = dψ/ds of degree 2;
/// p = 2 gives clothoid splines, κ piecewise linear). Its knots, in Farin's notation (no phantom end
/// knots), are v_{−p+1} ≤ … ≤ v_q: the breakpoints w_0 < w_1 < … < w_k, breakpoint g repeated
/// mult(g) times, the ends p times (section 2: "both ends triple knots" for p = 3). Then
///   k segments [w_j, w_{j+1}] of arc length Δw_j ("curve-segment arc lengths"),
///   q + 1 = Σ_g mult(g) − p + 1 de Boor ordinates B_0..B_q, B_i at the Greville abscissa
///     (v_{i−p+1} + … + v_i)/p,
///   n spans (data point to data point), each one or more consecutive segments,
///   l independent lengths S_0..S_{l−1}: segments constrained equal share one (Δw_j = S_{len(j)}).
/// At an interior breakpoint of multiplicity μ, ψ is C^{p−μ}: the curve is G^{p−μ+1} there
/// (μ = p: G1, κ may jump; μ = p − 1: G2; μ = p − 2: G3).
///
/// The knot-difference list writes the differences of all knots v, with the segments of a span
/// of several segments gathered in a sub-list. For Fig. 1 (p = 3):
///   {0, 0, {S0, S0}, 0, S1, {S2, 0, S3}, 0, 0}
/// — two zeros for each triple end knot, span 0 of two equal segments (a simple knot inside), a
/// double knot (one zero) between spans 0 and 1, span 2 of two segments joined at a double knot.
/// Entries: 0 (a repeated knot), a positive number (a segment with its own length), or a name
/// (segments with the same name share one independent length). A list therefore begins and ends
/// with exactly p − 1 zeros; a span's sub-list begins and ends with a segment; no knot may exceed
/// multiplicity p. "…" is not accepted. Fig. 3's printed list has one zero at each end: it is a
/// degree-2 list (reference/curvature_profile/fig3_lines_arcs.csv).
///
/// Failure modes: every violation throws InvalidInput naming the entry (position and text).
#include <optional>
#include <string>
#include <vector>

namespace cagd::intrinsic {

/// The knot structure of ψ: degree p, segments per span, breakpoint multiplicities and which segments share a length
/// (see above).
class KnotLayout {
public:
    /// segments_per_span: n entries ≥ 1; multiplicity: k + 1 entries (k = Σ segments_per_span),
    /// ends = degree, interior in [1, degree]; length_index: k entries, the independent length of
    /// each segment, numbered in order of first appearance (0, 1, …, l − 1). degree ∈ {2, 3, 4}
    /// (4: Spiro's quartic ψ, curvature cubic in arc length).
    KnotLayout(int degree, std::vector<int> segments_per_span, std::vector<int> multiplicity,
               std::vector<int> length_index);

    /// p.
    int degree() const { return degree_; }
    /// n, the spans (data intervals).
    int spans() const { return static_cast<int>(span_first_.size()) - 1; }
    /// k, the segments (polynomial pieces of ψ).
    int segments() const { return static_cast<int>(segment_span_.size()); }
    /// l, the independent segment lengths.
    int independent_lengths() const { return lengths_; }
    int ordinates() const { return ordinates_; }  ///< q + 1, the de Boor ordinates
    /// The length of the Farin knot list (q + p).
    int farin_knot_count() const { return ordinates_ + degree_ - 1; }
    /// The first segment of a span.
    int first_segment(int span) const { return span_first_[static_cast<std::size_t>(span)]; }
    int end_segment(int span) const {
        return span_first_[static_cast<std::size_t>(span) + 1];
    }  ///< one past the last segment of a span
    /// The span a segment belongs to.
    int span_of_segment(int segment) const { return segment_span_[static_cast<std::size_t>(segment)]; }
    /// The multiplicity of breakpoint g (ends: p).
    int multiplicity(int breakpoint) const { return multiplicity_[static_cast<std::size_t>(breakpoint)]; }
    /// The independent length a segment takes.
    int length_index(int segment) const { return length_index_[static_cast<std::size_t>(segment)]; }
    /// Index in the Farin knot list of the last copy of breakpoint g (segment g starts there):
    /// segment j uses knots [last(j) − p + 1, last(j) + p] and ordinates [last(j) − p + 1, last(j) + 1].
    int last_knot_of_breakpoint(int breakpoint) const { return last_knot_[static_cast<std::size_t>(breakpoint)]; }
    /// Breakpoint index of Farin knot i.
    int breakpoint_of_knot(int knot) const { return knot_breakpoint_[static_cast<std::size_t>(knot)]; }
    /// Geometric continuity order at breakpoint g (interior): p − mult(g) + 1.
    int geometric_continuity(int breakpoint) const { return degree_ - multiplicity(breakpoint) + 1; }

    /// The same curve space one degree up: every multiplicity + 1 (p = 2 → 3). A degree-2 spline is
    /// the degree-3 spline on this layout whose segments all have linear curvature.
    KnotLayout elevated() const;

    /// Equal structure: degree, segments, multiplicities and shared lengths.
    bool operator==(const KnotLayout& other) const;

private:
    int degree_, lengths_ = 0, ordinates_ = 0;
    std::vector<int> span_first_, segment_span_, multiplicity_, length_index_, last_knot_, knot_breakpoint_;
};

/// A parsed knot-difference list: its layout and its lengths.
struct KnotDifferenceList {
    KnotLayout layout;  ///< the layout the list describes
    /// Per independent length: its text in the list ("S0", "5.000") and its value if numeric.
    std::vector<std::string> labels;
    std::vector<std::optional<double>> values;  ///< per independent length: its value, if the list gives a number
};

/// Parses a list such as "{0, 5.000, 0, {2.053, 1.806}, 3.430, 2.000, 0}" for degree p.
KnotDifferenceList parse_knot_difference_list(const std::string& text, int degree);

/// The list with segment lengths printed to `decimals` places ("{0, 5.000, 0, …}"); segment_lengths
/// has one entry per segment.
std::string format_knot_difference_list(const KnotLayout& layout, const std::vector<double>& segment_lengths,
                                        int decimals);
/// The symbolic list with independent lengths named S0, S1, … (equal names = equal lengths).
std::string format_knot_difference_list(const KnotLayout& layout);

}  // namespace cagd::intrinsic
