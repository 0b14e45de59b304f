// numeric/romberg: Romberg integration of several integrands sharing their evaluations, and in
// batches.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <vector>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/fairness/angle_minimum_table.hpp"
#include "cagd/fairness/pseudo_energy_table.hpp"
#include "cagd/fairness/space_pseudo_energy.hpp"
#include "cagd/numeric/romberg.hpp"

using namespace cagd;
using namespace cagd::fairness;

TEST(RombergVector, SharedEvaluationsConvergePerComponent) {
    const auto f = [](double t) { return std::array<double, 3>{std::sin(t), std::cos(t) - std::cos(1.0), t * t}; };
    const auto r = numeric::romberg_vector<3>(f, 0.0, 1.0, 1e-13);
    ASSERT_TRUE(r.outcome.ok());
    EXPECT_NEAR(r.value[0], 1 - std::cos(1.0), 1e-14);
    EXPECT_NEAR(r.value[1], std::sin(1.0) - std::cos(1.0), 1e-14) << "a component near 0 still converges";
    EXPECT_NEAR(r.value[2], 1.0 / 3.0, 1e-15);
}

// The batched form hands a level's points over in batches (16 at a time) and sums them in order:
// the same bits as one point at a time, here on an integrand that needs levels of many batches.
TEST(RombergVector, BatchesSumLikeOnePointAtATime) {
    const auto f = [](double t) { return std::array<double, 2>{1.0 / (1e-3 + t * t), std::exp(-40.0 * t)}; };
    std::vector<double> seen;
    const auto batched = numeric::romberg_vector_batched<2>(
        [&](const double* t, std::size_t m, std::array<double, 2>* out) {
            EXPECT_LE(m, numeric::kRombergBatch);
            for (std::size_t i = 0; i < m; ++i) {
                seen.push_back(t[i]);
                out[i] = f(t[i]);
            }
        },
        -0.3, 1.0, 1e-13);
    // A point-by-point Romberg written out here: trapezoid halvings and Richardson's table.
    double prev_row[31][2] = {}, row[31][2] = {};
    const double a = -0.3, h0 = 1.3;
    for (int c = 0; c < 2; ++c) prev_row[0][c] = 0.5 * h0 * (f(a)[c] + f(1.0)[c]);
    for (int k = 1; k <= batched.levels; ++k) {
        const double h = h0 / static_cast<double>(1L << k);
        double sum[2] = {0, 0};
        for (long i = 0; i < (1L << (k - 1)); ++i)
            for (int c = 0; c < 2; ++c) sum[c] += f(a + static_cast<double>(2 * i + 1) * h)[c];
        double factor = 1.0;
        for (int c = 0; c < 2; ++c) row[0][c] = 0.5 * prev_row[0][c] + h * sum[c];
        for (int j = 1; j <= k; ++j) {
            factor *= 4.0;
            for (int c = 0; c < 2; ++c)
                row[j][c] = row[j - 1][c] + (row[j - 1][c] - prev_row[j - 1][c]) / (factor - 1.0);
        }
        std::copy(&row[0][0], &row[0][0] + 62, &prev_row[0][0]);
    }
    ASSERT_TRUE(batched.outcome.ok());
    ASSERT_GE(batched.levels, 8) << "the integrand must need levels of several batches";
    EXPECT_EQ(batched.value[0], prev_row[batched.levels][0]);
    EXPECT_EQ(batched.value[1], prev_row[batched.levels][1]);
    EXPECT_EQ(static_cast<long>(seen.size()), batched.evaluations) << "the two ends come through the batch too";
}
