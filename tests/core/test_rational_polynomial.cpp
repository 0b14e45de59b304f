// core/rational_polynomial: exact arithmetic, derivatives and reflection of rational polynomials.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/rational_polynomial.hpp"
#include "cagd/spline/hermite_spline.hpp"
#include "cagd/spline/hosaka_basis.hpp"
#include "cagd/spline/hosaka_spline.hpp"

using namespace cagd;

TEST(RationalPolynomial, ArithmeticDerivativeAndReflectionAreExact) {
    const RationalPolynomial one_plus_t = RationalPolynomial::linear(1, 1);
    const RationalPolynomial cube = one_plus_t.power(3);
    ASSERT_EQ(cube.degree(), 3);
    EXPECT_EQ(cube.coefficient(0), 1);
    EXPECT_EQ(cube.coefficient(1), 3);
    EXPECT_EQ(cube.coefficient(2), 3);
    EXPECT_EQ(cube.coefficient(3), 1);
    EXPECT_EQ(cube.derivative(2), RationalPolynomial({6, 6}));  // 6(1 + t)
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
