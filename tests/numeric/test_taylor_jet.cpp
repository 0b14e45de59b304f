// numeric/taylor_jet: runtime-order Taylor arithmetic against known series.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "cagd/core/errors.hpp"
#include "cagd/numeric/taylor_jet.hpp"
#include "cagd/surface/boundary_surface.hpp"
#include "cagd/surface/hosaka_patch.hpp"

using namespace cagd;
using namespace cagd::surface;
using numeric::TaylorJet;

TEST(TaylorJet, ArithmeticMatchesKnownSeries) {
    // 1/(1 − x) at 0: all coefficients 1.
    const TaylorJet x = TaylorJet::variable(6, 0.0);
    const TaylorJet geometric = numeric::reciprocal(TaylorJet(6, 1.0) - x);
    for (int k = 0; k <= 6; ++k) EXPECT_DOUBLE_EQ(geometric.coefficient(k), 1.0);
    // sin·cos = sin(2x)/2 at x0 = 0.7, derivatives to order 5.
    const auto s = sinusoid(1, 1, 0), c = sinusoid(1, 1, std::numbers::pi / 2), s2 = sinusoid(0.5, 2, 0);
    const TaylorJet a = TaylorJet::from_derivatives({s(0.7, 0), s(0.7, 1), s(0.7, 2), s(0.7, 3), s(0.7, 4), s(0.7, 5)});
    const TaylorJet b = TaylorJet::from_derivatives({c(0.7, 0), c(0.7, 1), c(0.7, 2), c(0.7, 3), c(0.7, 4), c(0.7, 5)});
    const TaylorJet p = a * b;
    for (int k = 0; k <= 5; ++k) EXPECT_NEAR(p.derivative(k), s2(0.7, k), 1e-13) << k;
    // (x²)∘(1 + 2x) = 1 + 4x + 4x²; power(−2) of (1 + x) has coefficients (k+1)(−1)^k.
    const TaylorJet inner = TaylorJet(3, 1.0) + 2.0 * TaylorJet::variable(3, 0.0);
    const TaylorJet sq = numeric::compose({1.0, 2.0, 2.0}, inner);  // g = t² at t = 1: g, g', g''
    EXPECT_DOUBLE_EQ(sq.coefficient(1), 4.0);
    EXPECT_DOUBLE_EQ(sq.coefficient(2), 4.0);
    EXPECT_DOUBLE_EQ(sq.coefficient(3), 0.0);
    const TaylorJet inv2 = numeric::power(TaylorJet(4, 1.0) + x, -2);
    for (int k = 0; k <= 4; ++k) EXPECT_NEAR(inv2.coefficient(k), (k + 1) * (k % 2 ? -1.0 : 1.0), 1e-14);
    EXPECT_EQ(p.differentiated().order(), 4);
    EXPECT_THROW(numeric::reciprocal(TaylorJet(2, 0.0)), InvalidInput);
    EXPECT_THROW(TaylorJet(-1), InvalidInput);
}
