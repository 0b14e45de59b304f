// core/bernstein_polynomial: Bernstein-form polynomials (products, derivatives, elevation, sign
// analysis) and stable Bernstein basis values at high degree.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <random>

#include "cagd/aesthetic/class_a.hpp"
#include "cagd/aesthetic/cubic_bspline_monotonicity.hpp"
#include "cagd/aesthetic/log_aesthetic_curve.hpp"
#include "cagd/aesthetic/typical_bezier.hpp"
#include "cagd/analysis/curvature_monotonicity.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/core/bernstein_polynomial.hpp"
#include "cagd/core/errors.hpp"

using namespace cagd;
using namespace cagd::aesthetic;

TEST(BernsteinPolynomial, ProductDerivativeAndElevationMatchPointValues) {
    const BernsteinPolynomial a({1.0, -2.0, 0.5, 3.0}), b({-1.0, 4.0, 2.0});
    const BernsteinPolynomial p = a * b, s = a + b, d = a.derivative(), e = b.elevated(6);
    for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
        EXPECT_NEAR(p(t), a(t) * b(t), 1e-13);
        EXPECT_NEAR(s(t), a(t) + b(t), 1e-13);
        EXPECT_NEAR(e(t), b(t), 1e-13);
        const double h = 1e-6;
        if (t > h && t < 1 - h) {
            EXPECT_NEAR(d(t), (a(t + h) - a(t - h)) / (2 * h), 1e-7);
        }
    }
    // Degree reduction inverts elevation exactly (to rounding).
    const BernsteinPolynomial r = a.elevated(5).reduced().reduced();
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.coefficients()[i], a.coefficients()[i], 1e-13);
    EXPECT_THROW(BernsteinPolynomial({2.0}).reduced(), InvalidInput);
    const auto halves = a.subdivide(0.3);
    EXPECT_NEAR(halves.first(0.5), a(0.15), 1e-14);
    EXPECT_NEAR(halves.second(0.5), a(0.65), 1e-14);
}

TEST(BernsteinPolynomial, SignAnalysisFindsCrossingsAndTouches) {
    // (t − 0.3)(t − 0.7) = t² − t + 0.21 → Bernstein: 0.21, 0.21 − 0.5, 0.21 + 1 − 1
    const BernsteinPolynomial crossing({0.21, -0.29, 0.21});
    const SignAnalysis c = sign_on_unit_interval(crossing);
    EXPECT_EQ(c.sign, SignOnInterval::changes_sign);
    EXPECT_LT(crossing(c.t_negative), 0.0);
    EXPECT_GT(crossing(c.t_positive), 0.0);
    // (t − 0.5)² touches zero: 0.25, −0.25, 0.25 in Bernstein form.
    EXPECT_EQ(sign_on_unit_interval(BernsteinPolynomial({0.25, -0.25, 0.25})).sign, SignOnInterval::nonnegative);
    EXPECT_EQ(sign_on_unit_interval(BernsteinPolynomial({-1.0, -0.5, -2.0})).sign, SignOnInterval::negative);
    // Negative coefficients somewhere but a positive polynomial: 1, −0.1, 1 (min 0.45 > 0).
    EXPECT_EQ(sign_on_unit_interval(BernsteinPolynomial({1.0, -0.1, 1.0})).sign, SignOnInterval::positive);
    EXPECT_THROW(BernsteinPolynomial({1.0, NAN}), InvalidInput);
}

TEST(BernsteinBasis, StableValuesAgreeWithDeCasteljauAtHighDegree) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int degree : {5, 99, 400}) {
        Eigen::MatrixXd cp(degree + 1, 2);
        for (int i = 0; i <= degree; ++i) cp.row(i) << u(rng), u(rng);
        const BezierCurve dc(cp), bern(cp, 0.0, 1.0, BezierEvaluation::bernstein);
        for (double t : {0.0, 0.01, 0.37, 0.5, 0.93, 1.0}) {
            const Eigen::MatrixXd a = dc.jet(t, 3), b = bern.jet(t, 3);
            for (int k = 0; k <= 3; ++k)
                EXPECT_LT((a.row(k) - b.row(k)).norm(), 1e-11 * std::pow(degree, k) + 1e-13)
                    << degree << " " << t << " " << k;
        }
        double sum = 0.0;
        for (double v : bernstein_basis_values(degree, 0.37)) sum += v;
        EXPECT_NEAR(sum, 1.0, 1e-14);
    }
    // The power basis is exact for low degree and useless at degree 99.
    Eigen::MatrixXd cp(4, 2);
    cp << 0, 0, 1, 2, 3, 2, 4, 0;
    EXPECT_LT((BezierCurve(cp, 0, 1, BezierEvaluation::power_basis).jet(0.3, 3) - BezierCurve(cp).jet(0.3, 3)).norm(),
              1e-12);
    const TypicalPolygon poly = scale_one_typical_polygon(-0.5, 1.5, 99);
    const double err =
        (BezierCurve(poly.points, 0, 1, BezierEvaluation::power_basis).point(0.5) - BezierCurve(poly.points).point(0.5))
            .norm();
    EXPECT_GT(err, 1e-3);
}

TEST(BernsteinBasis, SmallDegreeTriangleAndRatioPathAgreeWithTheDefinition) {
    // Both sides of kSmallBernsteinDegree against C(d,i) t^i (1−t)^(d−i) in long double; the span
    // overload returns the same values and checks its size.
    for (int d : {0, 1, 3, 5, kSmallBernsteinDegree, kSmallBernsteinDegree + 1, 30}) {
        for (double t : {0.0, 1e-9, 0.2, 0.5, 0.77, 1.0 - 1e-9, 1.0}) {
            const std::vector<double> b = bernstein_basis_values(d, t);
            std::vector<double> into(static_cast<std::size_t>(d) + 1, -1.0);
            bernstein_basis_values(d, t, into);
            ASSERT_EQ(b.size(), static_cast<std::size_t>(d) + 1);
            long double binom = 1.0L;
            for (int i = 0; i <= d; ++i) {
                if (i > 0) binom = binom * (d - i + 1) / i;
                const long double exact = binom * std::pow(static_cast<long double>(t), i) *
                                          std::pow(1.0L - static_cast<long double>(t), d - i);
                const double tol =
                    4.0 * (d + 1) * std::numeric_limits<double>::epsilon() * static_cast<double>(exact) + 1e-300;
                EXPECT_NEAR(b[static_cast<std::size_t>(i)], static_cast<double>(exact), tol)
                    << "d " << d << " t " << t << " i " << i;
                EXPECT_EQ(into[static_cast<std::size_t>(i)], b[static_cast<std::size_t>(i)])
                    << "d " << d << " t " << t << " i " << i;
            }
        }
    }
    std::vector<double> wrong(3);
    EXPECT_THROW(bernstein_basis_values(3, 0.5, wrong), InvalidInput);
    EXPECT_THROW(bernstein_basis_values(3, 1.5), InvalidInput);
}
