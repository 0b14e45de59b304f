#include "cagd/numeric/confidence_interval.hpp"

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

namespace {

void check_confidence(const char* who, double confidence) {
    if (!(confidence > 0.0 && confidence < 1.0))
        fail_input(who, "confidence " + full_precision(confidence) + " must lie in (0, 1)");
}

}  // namespace

Estimate quantile_estimate(std::vector<double> values, double q, double confidence) {
    const char* who = "cagd::numeric::quantile_estimate";
    check_confidence(who, confidence);
    if (!(q > 0.0 && q < 1.0)) fail_input(who, "q = " + full_precision(q) + " must lie in (0, 1)");
    if (values.empty()) fail_input(who, "needs at least one value");
    for (double v : values)
        if (!std::isfinite(v)) fail_input(who, "value " + full_precision(v) + " is not finite");
    std::sort(values.begin(), values.end());
    const long m = static_cast<long>(values.size());
    const double tail = 0.5 * (1.0 - confidence);
    const boost::math::binomial_distribution<double> below(static_cast<double>(m), q);
    // l: the largest rank with P(B ≤ l − 1) ≤ tail; u: the smallest with P(B ≥ u) = 1 − P(B ≤ u − 1) ≤ tail.
    long l = 1;
    while (l < m && boost::math::cdf(below, static_cast<double>(l)) <= tail) ++l;
    long u = m;
    while (u > l && 1.0 - boost::math::cdf(below, static_cast<double>(u - 2)) <= tail) --u;
    const long rank = std::clamp(static_cast<long>(std::ceil(q * static_cast<double>(m))), 1L, m);
    return {values[static_cast<std::size_t>(rank - 1)], values[static_cast<std::size_t>(l - 1)],
            values[static_cast<std::size_t>(u - 1)]};
}

Estimate rate_estimate(long events, long trials, double confidence) {
    const char* who = "cagd::numeric::rate_estimate";
    check_confidence(who, confidence);
    if (trials < 1 || events < 0 || events > trials)
        fail_input(who, std::to_string(events) + " events in " + std::to_string(trials) +
                            " trials; needs 0 ≤ events ≤ trials and trials ≥ 1");
    using B = boost::math::binomial_distribution<double>;
    const double tail = 0.5 * (1.0 - confidence), n = static_cast<double>(trials), k = static_cast<double>(events);
    return {k / n, B::find_lower_bound_on_p(n, k, tail), B::find_upper_bound_on_p(n, k, tail)};
}

}  // namespace cagd::numeric
