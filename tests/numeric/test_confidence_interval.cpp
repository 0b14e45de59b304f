// numeric/confidence_interval: the order-statistic interval of a quantile and the Clopper–Pearson
// interval of a rate, against their textbook values and by their coverage.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/numeric/confidence_interval.hpp"

using cagd::numeric::quantile_estimate;
using cagd::numeric::rate_estimate;

TEST(ConfidenceInterval, MedianOfAHundredIsBetweenTheFortiethAndSixtyFirst) {
    // For m = 100, P(40 ≤ B ≤ 60) = 0.9648 with B ~ Binomial(100, 1/2), and no narrower pair of
    // ranks reaches 0.95: the interval is [x_(40), x_(61)] (Conover, Practical Nonparametric
    // Statistics, table A3), the estimate x_(50).
    std::vector<double> v;
    for (int i = 100; i >= 1; --i) v.push_back(i);  // unsorted on purpose
    const auto e = quantile_estimate(v, 0.5);
    EXPECT_EQ(e.value, 50.0);
    EXPECT_EQ(e.low, 40.0);
    EXPECT_EQ(e.high, 61.0);
}

TEST(ConfidenceInterval, QuantileIntervalsCoverTheirQuantileAtLeastAsOftenAsPromised) {
    // Uniform draws on [0, 1]: ξ_q = q. 4000 samples of 60 draws each, for q = 0.5 and 0.95.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (double q : {0.5, 0.95}) {
        int covered = 0;
        const int trials = 4000;
        for (int t = 0; t < trials; ++t) {
            std::vector<double> v(60);
            for (double& x : v) x = u(rng);
            const auto e = quantile_estimate(v, q);
            covered += e.low <= q && q <= e.high;
        }
        // At least 95 %, less three standard errors of the simulation (0.0034 each).
        EXPECT_GE(covered / static_cast<double>(trials), 0.95 - 3 * 0.0034) << "q = " << q;
    }
}

TEST(ConfidenceInterval, RateIntervalsAreClopperPearsons) {
    // No event in m trials: the upper end solves (1 − p)^m = 0.025; all m: the lower solves p^m = 0.025.
    const auto none = rate_estimate(0, 100);
    EXPECT_EQ(none.value, 0.0);
    EXPECT_EQ(none.low, 0.0);
    EXPECT_NEAR(none.high, 1.0 - std::pow(0.025, 1.0 / 100), 1e-12);
    const auto all = rate_estimate(100, 100);
    EXPECT_NEAR(all.low, std::pow(0.025, 1.0 / 100), 1e-12);
    EXPECT_EQ(all.high, 1.0);
    const auto half = rate_estimate(50, 100);
    EXPECT_EQ(half.value, 0.5);
    EXPECT_NEAR(half.low, 0.3983, 5e-5);  // the tabulated exact interval of 50 in 100
    EXPECT_NEAR(half.high, 0.6017, 5e-5);
}

TEST(ConfidenceInterval, BadInputIsRefusedNamingTheValue) {
    const auto message = [](auto f) {
        try {
            f();
        } catch (const cagd::InvalidInput& e) {
            return std::string(e.what());
        }
        return std::string("no exception");
    };
    EXPECT_NE(message([] { quantile_estimate({}, 0.5); }).find("at least one value"), std::string::npos);
    EXPECT_NE(message([] { quantile_estimate({1.0, NAN}, 0.5); }).find("nan"), std::string::npos);
    EXPECT_NE(message([] { quantile_estimate({1.0}, 1.0); }).find("q = 1"), std::string::npos);
    EXPECT_NE(message([] { rate_estimate(3, 2); }).find("3 events in 2 trials"), std::string::npos);
    EXPECT_NE(message([] { rate_estimate(0, 1, 1.5); }).find("confidence 1.5"), std::string::npos);
}
