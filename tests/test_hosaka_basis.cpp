// hosaka section 2: exact rational polynomials and the generalised Hermite basis (eq 1–14).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/errors.hpp"
#include "core/rational_polynomial.hpp"
#include "spline/hosaka_basis.hpp"

using namespace cagd;

TEST(RationalPolynomial, ArithmeticDerivativeAndReflectionAreExact) {
    const RationalPolynomial one_plus_t = RationalPolynomial::linear(1, 1);
    const RationalPolynomial cube = one_plus_t.power(3);
    ASSERT_EQ(cube.degree(), 3);
    EXPECT_EQ(cube.coefficient(0), 1);
    EXPECT_EQ(cube.coefficient(1), 3);
    EXPECT_EQ(cube.coefficient(2), 3);
    EXPECT_EQ(cube.coefficient(3), 1);
    EXPECT_EQ(cube.derivative(2), RationalPolynomial({6, 6}));   // 6(1 + t)
    EXPECT_TRUE(cube.derivative(4).is_zero());
    EXPECT_EQ(cube(Rational(1, 2)), Rational(27, 8));
    // p(1 − t) for p = t²: 1 − 2t + t².
    EXPECT_EQ(RationalPolynomial::monomial(2).compose_one_minus(), RationalPolynomial({1, -2, 1}));
    EXPECT_EQ((cube - cube).degree(), -1);
    EXPECT_EQ(binomial(11, 4), 330);
    EXPECT_EQ(binomial(3, 5), 0);
    EXPECT_EQ(factorial(11), 39916800);
    EXPECT_THROW(factorial(-1), InvalidInput);
    EXPECT_EQ(RationalPolynomial({0, Rational(3), Rational(-2)}).to_string(), "3 t - 2 t^2");
}

TEST(HosakaBasis, CardinalEndDerivativesHoldExactlyForHigherM) {
    // m = 6, 7 (beyond the experiment's m ≤ 5): p_i^(k)(0) = δ_ik, q_i^(k)(1) = δ_ik, the others 0.
    for (int m : {6, 7})
        for (int i = 0; i <= m; ++i) {
            const RationalPolynomial p = spline::hosaka_p(m, i), q = spline::hosaka_q(m, i);
            EXPECT_EQ(p.degree(), 2 * m + 1);
            for (int k = 0; k <= m; ++k) {
                EXPECT_EQ(p.derivative(k)(0), i == k ? 1 : 0) << "m " << m << " i " << i << " k " << k;
                EXPECT_EQ(q.derivative(k)(1), i == k ? 1 : 0);
                EXPECT_EQ(p.derivative(k)(1), 0);
                EXPECT_EQ(q.derivative(k)(0), 0);
            }
        }
}

TEST(HosakaBasis, DoubleEvaluationMatchesTheExactBasisAndInterpolatesAQuintic) {
    const spline::HosakaBasis b(2);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        const double t = u(rng);
        for (int i = 0; i <= 2; ++i)
            for (int k = 0; k <= 5; ++k) {
                EXPECT_NEAR(b.p(i, t, k), spline::hosaka_p(2, i).derivative(k).value(t), 1e-10);
                EXPECT_NEAR(b.q(i, t, k), spline::hosaka_q(2, i).derivative(k).value(t), 1e-10);
            }
    }
    // eq (1) with m = 2 reproduces the quintic φ(t) = 1 + 2t − t³ + 0.5 t⁵ from its end data.
    const auto phi = [](double t, int k) {
        switch (k) {
            case 0: return 1 + 2 * t - t * t * t + 0.5 * std::pow(t, 5);
            case 1: return 2 - 3 * t * t + 2.5 * std::pow(t, 4);
            default: return -6 * t + 10 * t * t * t;
        }
    };
    for (double t : {0.1, 0.37, 0.8}) {
        double v = 0;
        for (int i = 0; i <= 2; ++i) v += phi(0, i) * b.p(i, t) + phi(1, i) * b.q(i, t);
        EXPECT_NEAR(v, phi(t, 0), 1e-14);
    }
    EXPECT_EQ(b.p(0, 0.3, 6), 0.0) << "derivatives above 2m+1 vanish";
}

TEST(HosakaBasis, BadIndicesAreRejected) {
    EXPECT_THROW(spline::hosaka_p(-1, 0), InvalidInput);
    EXPECT_THROW(spline::hosaka_q(2, 3), InvalidInput);
    EXPECT_THROW(spline::HosakaBasis(-2), InvalidInput);
    const spline::HosakaBasis b(1);
    EXPECT_THROW(b.p(2, 0.5), InvalidInput);
    EXPECT_THROW(b.q(0, 0.5, -1), InvalidInput);
}
