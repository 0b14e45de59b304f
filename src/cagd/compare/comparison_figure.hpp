#pragma once
/// @file
/// The figure data of a comparison (method_comparison.hpp): each method's curve samples, its
/// curvature profile κ(s) (and τ(s) in space) and its curvature comb, as `cagd compare`'s figures,
/// the report's comparisons and the viewer draw them (comparison_tables.hpp writes them).
#include <vector>

#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/points.hpp"

namespace cagd::compare {

/// Figure data (planar; for space points: curves (index, x, y, z), profiles (index, s, κ, τ), no
/// combs). Curve samples (method index, method, x, y), `per_span` per span; the curvature
/// profile (method index, s, κ), `per_span` per span with both ends of every span; the curvature
/// comb (method index, x, y, tooth end x, y), the tooth r − c·κ·n (n the left unit normal), c one
/// scale for every method, such that the 95th percentile of |κ| over all methods' samples draws
/// 10 % of the data diagonal (equal teeth are equal curvature in every panel; a spike shows as a
/// long tooth without flattening the rest). A comb has at most kMaxCombTeeth teeth: every
/// comb_stride-th curve sample of the method (the first and the last always), so that a panel
/// stays readable and cheap to draw however long the input; comb_scale and comb_stride record, per
/// method, the length factor c and that stride (methods.csv prints both).
/// Long inputs: only every `span_stride`-th span is sampled (the arc length s still runs over every
/// span: a span not sampled adds the length the measures integrated, where every node is a
/// breakpoint, else one 20-point Gauss rule's), so a figure of 10^5 spans stays a few MB; figure_sampling(spans,
/// budget) picks per_span (≤ 32) and the stride for at most about `budget` samples per method (a sampled span gives
/// per_span + 1 samples).
struct FigureData {
    std::vector<std::vector<double>> curves;    ///< curve samples (method index, x, y[, z])
    std::vector<std::vector<double>> profiles;  ///< the curvature profiles (method index, s, κ[, τ])
    std::vector<std::vector<double>> combs;     ///< the comb teeth (method index, x, y, tip x, tip y)
    std::vector<double> comb_scale;             ///< per method: c, the tooth length per unit curvature (0: no comb)
    std::vector<int> comb_stride;               ///< per method: a tooth at every comb_stride-th sample (0: no comb)
};
/// The most teeth a method's curvature comb draws.
inline constexpr int kMaxCombTeeth = 1000;
/// How densely the figure data sample a curve.
struct FigureSampling {
    int per_span = 32;    ///< samples per sampled span
    int span_stride = 1;  ///< every span_stride-th span is sampled
    /// How the profiles' arc length s is summed from sample to sample: the 20-point Gauss rule on
    /// each step (quadrature, the figures'), or the trapezoid rule on the samples' own speeds
    /// (trapezoid: no evaluation beyond the samples, a relative error of order (step·κ)²/12, for
    /// interactive drawing; every span must then be sampled, span_stride 1).
    enum class ArcLength { quadrature, trapezoid };
    ArcLength arc_length = ArcLength::quadrature;  ///< the rule for s (see ArcLength)
};
/// per_span and the stride for at most about `budget` samples per method over `spans` spans.
FigureSampling figure_sampling(int spans, int budget);
/// The figure data of a comparison (see above).
FigureData comparison_figure_data(const std::vector<MethodComparison>& c, const PointList& points,
                                  const FigureSampling& sampling);

}  // namespace cagd::compare
