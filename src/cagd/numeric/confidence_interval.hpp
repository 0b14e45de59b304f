#pragma once
/// @file
/// Two-sided confidence intervals for what independent draws estimate: a quantile of their
/// distribution, or the probability of an event. Distribution-free and exact in their coverage
/// (at least the level asked for), from Boost.Math's binomial distribution.
///
/// Quantile. The q-quantile ξ_q of a continuous distribution, from m draws sorted x_(1) ≤ … ≤ x_(m):
/// the estimate x_(⌈q m⌉), and the interval [x_(l), x_(u)] with B ~ Binomial(m, q) the number of
/// draws below ξ_q: l the largest rank with P(B ≤ l − 1) ≤ α/2, u the smallest with P(B ≥ u) ≤ α/2
/// (l ≥ 1, u ≤ m; where m is too small for that, the interval is the whole sample and its coverage
/// is below 1 − α). P(x_(l) ≤ ξ_q ≤ x_(u)) = P(l ≤ B ≤ u − 1) ≥ 1 − α.
///
/// Rate. The probability p of an event seen k times in m trials: k / m and the Clopper–Pearson
/// interval (boost::math::binomial_distribution::find_lower_bound_on_p / find_upper_bound_on_p with
/// α/2 each): coverage at least 1 − α for every p.
#include <vector>

namespace cagd::numeric {

/// An estimate and its interval.
struct Estimate {
    double value = 0.0;  ///< the estimate
    double low = 0.0;    ///< the interval's lower end
    double high = 0.0;   ///< its upper end
};

/// 1 − α of the intervals below unless asked otherwise: 95 %.
inline constexpr double kConfidence = 0.95;

/// The q-quantile of the distribution `values` are drawn from (see above), 0 < q < 1, with its
/// interval at `confidence` (0 < confidence < 1). InvalidInput for an empty sample, a non-finite value
/// or q, confidence outside (0, 1).
Estimate quantile_estimate(std::vector<double> values, double q, double confidence = kConfidence);
/// The probability of an event seen `events` times in `trials` (0 ≤ events ≤ trials, trials ≥ 1), with
/// its Clopper–Pearson interval at `confidence` (see above). InvalidInput otherwise.
Estimate rate_estimate(long events, long trials, double confidence = kConfidence);

}  // namespace cagd::numeric
