// typical_curves sections 2–3 and appendix A: Bernstein polynomials, stable Bézier evaluation,
// the LCG, log-aesthetic curves, class A matrices, typical polygons, cubic B-spline monotonicity.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <boost/math/quadrature/gauss_kronrod.hpp>

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
            for (int k = 0; k <= 3; ++k) EXPECT_LT((a.row(k) - b.row(k)).norm(), 1e-11 * std::pow(degree, k) + 1e-13) << degree << " " << t << " " << k;
        }
        double sum = 0.0;
        for (double v : bernstein_basis_values(degree, 0.37)) sum += v;
        EXPECT_NEAR(sum, 1.0, 1e-14);
    }
    // The power basis is exact for low degree and useless at degree 99.
    Eigen::MatrixXd cp(4, 2);
    cp << 0, 0, 1, 2, 3, 2, 4, 0;
    EXPECT_LT((BezierCurve(cp, 0, 1, BezierEvaluation::power_basis).jet(0.3, 3) - BezierCurve(cp).jet(0.3, 3)).norm(), 1e-12);
    const TypicalPolygon poly = scale_one_typical_polygon(-0.5, 1.5, 99);
    const double err = (BezierCurve(poly.points, 0, 1, BezierEvaluation::power_basis).point(0.5) - BezierCurve(poly.points).point(0.5)).norm();
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
                const long double exact = binom * std::pow(static_cast<long double>(t), i) * std::pow(1.0L - static_cast<long double>(t), d - i);
                const double tol = 4.0 * (d + 1) * std::numeric_limits<double>::epsilon() * static_cast<double>(exact) + 1e-300;
                EXPECT_NEAR(b[static_cast<std::size_t>(i)], static_cast<double>(exact), tol) << "d " << d << " t " << t << " i " << i;
                EXPECT_EQ(into[static_cast<std::size_t>(i)], b[static_cast<std::size_t>(i)]) << "d " << d << " t " << t << " i " << i;
            }
        }
    }
    std::vector<double> wrong(3);
    EXPECT_THROW(bernstein_basis_values(3, 0.5, wrong), InvalidInput);
    EXPECT_THROW(bernstein_basis_values(3, 1.5), InvalidInput);
}

TEST(CurvatureMonotonicity, NumeratorHasTheSignOfTheCurvatureDerivative) {
    Eigen::MatrixXd cp(6, 2);
    cp << 0, 0, 1, 0.2, 2, 0.8, 2.6, 1.9, 2.8, 3.1, 2.5, 4.0;
    const BezierCurve c(cp);
    const BernsteinPolynomial h = analysis::curvature_derivative_numerator(c);
    const BernsteinPolynomial q = analysis::squared_curvature_derivative_numerator(c);
    for (double t = 0.05; t < 0.96; t += 0.05) {
        const double e = 1e-6;
        const double dk = (analysis::signed_curvature(c, t + e) - analysis::signed_curvature(c, t - e)) / (2 * e);
        const double g = c.jet(t, 1).row(1).squaredNorm();
        EXPECT_NEAR(h(t) / std::pow(g, 2.5), dk, 1e-5 * (1 + std::abs(dk)));
        const double k = analysis::signed_curvature(c, t);
        EXPECT_NEAR(q(t) / std::pow(g, 4), 2 * k * dk, 1e-5 * (1 + std::abs(k * dk)));
    }
    Eigen::MatrixXd sp(5, 3);
    sp << 0, 0, 0, 1, 0, 0.1, 2, 1, 0.3, 2.2, 2, 1, 1.5, 3, 1.4;
    const BezierCurve s(sp);
    const BernsteinPolynomial tn = analysis::torsion_derivative_numerator(s);
    auto torsion = [&](double t) {
        const Eigen::MatrixXd j = s.jet(t, 3);
        const Eigen::Vector3d a = j.row(1), b = j.row(2), d = j.row(3);
        return a.cross(b).dot(d) / a.cross(b).squaredNorm();
    };
    for (double t = 0.1; t < 0.95; t += 0.1) {
        const double e = 1e-6;
        const Eigen::MatrixXd j = s.jet(t, 2);
        const double qq = Eigen::Vector3d(j.row(1)).cross(Eigen::Vector3d(j.row(2))).squaredNorm();
        const double dt = (torsion(t + e) - torsion(t - e)) / (2 * e);
        EXPECT_NEAR(tn(t) / (qq * qq), dt, 1e-5 * (1 + std::abs(dt)));
    }
}

TEST(CubicBsplineMonotonicity, ClosedFormCoefficientsEqualTheProductComputation) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> ang(0.0, 3.0);
    for (int k = 0; k < 200; ++k) {
        const double a = ang(rng), b = ang(rng);
        const auto closed = monotonicity_coefficients(a, b);
        const BernsteinPolynomial h = analysis::curvature_derivative_numerator(BezierCurve(uniform_segment_bezier(unit_edge_polygon(a, b))));
        for (int i = 0; i < 6; ++i) EXPECT_NEAR(closed[i], h.coefficients()[i], 1e-13) << a << " " << b << " C" << i;
    }
    for (double t0 : {0.2, 0.8, 1.5, 2.5}) EXPECT_NEAR(condition29(t0, theta1_bound(t0)), 0.0, 1e-14);
    const CubicPoints p = unit_edge_polygon(0.7, 0.3);
    EXPECT_LT((equivalent_uniform_polygon(uniform_segment_bezier(p)) - p).norm(), 1e-14);
    EXPECT_THROW(monotonicity_coefficients(NAN, 0.1), InvalidInput);
}

TEST(CubicBsplineMonotonicity, EndpointInterpolatingFirstSegmentUsesTwiceTheAngle) {
    // A unit-edge polygon with turns 0.3 at Q1, 0.2, 0.15, … (decreasing).
    Eigen::MatrixXd q(7, 2);
    double dir = 0.0;
    q.row(0) << 0, 0;
    const double turns[] = {0.0, 0.3, 0.2, 0.15, 0.1, 0.08};
    for (int i = 0; i < 6; ++i) {
        dir += turns[i];
        q.row(i + 1) = q.row(i) + Eigen::RowVector2d(std::cos(dir), std::sin(dir));
    }
    const Eigen::MatrixXd p = endpoint_interpolating_polygon(q);
    const MonotonicityReport r = cubic_bspline_curvature_monotonicity(endpoint_interpolating_cubic_bspline(p));
    ASSERT_EQ(r.segments.size(), 4u);
    const SegmentVerdict& first = r.segments[0];
    EXPECT_TRUE(first.equal_edges);
    EXPECT_NEAR(first.turn0, 2 * 0.3, 1e-12);
    EXPECT_NEAR(first.turn1, 0.2, 1e-12);
    EXPECT_TRUE(r.segments[1].equal_edges);
    EXPECT_NEAR(r.segments[1].turn0, 0.2, 1e-12);
    EXPECT_EQ(first.bezier.row(0), p.row(0));
    EXPECT_LT((first.bezier.row(3) - (3 * p.row(1) + 7 * p.row(2) + 2 * p.row(3)) / 12).norm(), 1e-14);
    Eigen::MatrixXd dup = p;
    dup.row(3) = dup.row(2);
    EXPECT_THROW(cubic_bspline_curvature_monotonicity(endpoint_interpolating_cubic_bspline(dup)), InvalidInput);
}

TEST(LogAestheticCurve, TangentAngleClosedFormsAndLcgSlope) {
    struct Case {
        double alpha, c0, c1;
    };
    for (const Case& cs : {Case{-1.5, 1.0, 0.5}, Case{-0.5, 2.0, 0.3}, Case{0.0, 1.2, 0.7}, Case{0.5, 1.0, 1.0}, Case{1.0, 0.8, 0.5}, Case{2.0, 1.0, 0.4}, Case{1.5, -0.2, 1.0}}) {
        LogAestheticParameters p;
        p.alpha = cs.alpha;
        p.c0 = cs.c0;
        p.c1 = cs.c1;
        p.length = 2.0;
        p.start_angle = 0.3;
        const LogAestheticCurve c(p);
        for (double s : {0.5, 1.3, 2.0}) {
            const double integral = boost::math::quadrature::gauss_kronrod<double, 61>::integrate([&](double v) { return c.curvature(v); }, 0.0, s, 15, 1e-14);
            EXPECT_NEAR(c.tangent_angle(s) - 0.3, integral, 1e-12) << cs.alpha;
        }
        const analysis::LineFit fit = analysis::lcg_slope(c, 0.1, 1.9, 30);
        EXPECT_NEAR(fit.slope, cs.alpha, 1e-9) << cs.alpha;
        if (auto closed = c.closed_form_point(1.7)) {
            EXPECT_LT((*closed - c.point(1.7)).norm(), 1e-13) << cs.alpha;
        }
    }
    const LogAestheticCurve n = normalized_log_aesthetic_curve(-0.5, 1.5);
    EXPECT_NEAR(n.tangent_angle(1.2), -0.5 * std::pow(1.2, 3.0), 1e-14);
    EXPECT_THROW(normalized_log_aesthetic_curve(0.5, 1.0), InvalidInput);
    EXPECT_THROW(normalized_log_aesthetic_curve(1.0, 1.0), InvalidInput);
    EXPECT_THROW(normalized_log_aesthetic_curve(-0.5, NAN), InvalidInput);
    LogAestheticParameters bad;
    bad.alpha = 0.5;
    bad.c1 = 0.0;
    EXPECT_THROW(LogAestheticCurve{bad}, InvalidInput);  // turning diverges at s = 0
    bad.alpha = 0.0;
    bad.c0 = -1.0;
    EXPECT_THROW(LogAestheticCurve{bad}, InvalidInput);  // ρ = c0 e^{c1 s} needs c0 > 0
    bad.alpha = -0.5;
    bad.c0 = -1.0;
    bad.c1 = 0.5;  // c0 s + c1 < 0 before s = L = 1
    EXPECT_THROW(LogAestheticCurve{bad}, InvalidInput);
    EXPECT_THROW(n.jet(1.6, 2), InvalidInput);  // outside [0, L]
    EXPECT_THROW(n.jet(0.5, 4), InvalidInput);  // jets up to order 3
    EXPECT_THROW(analysis::fit_line({1.0, 1.0}, {0.0, 2.0}), InvalidInput);
    EXPECT_THROW(analysis::lcg_slope(n, 0.5, 0.4, 10), InvalidInput);
}

TEST(ClassA, TypicalMatrixConditionIsEq2ForScaleAboveOneAndReversedBelow) {
    for (double s : {0.5, 0.9, 1.1, 1.5, 3.0})
        for (double th = 0.01; th < 1.5; th += 0.07) {
            const Eigen::Matrix2d m = typical_matrix(th, s);
            const bool cond4 = typical_matrix_condition(th, s);
            if (s > 1)
                EXPECT_EQ(cond4, class_a_test(m).eq2) << s << " " << th;
            else
                EXPECT_EQ(cond4, class_a_test(m.inverse()).eq2) << s << " " << th;
        }
    EXPECT_THROW(class_a_test(Eigen::MatrixXd::Identity(4, 4)), InvalidInput);
    EXPECT_THROW(class_a_control_points(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Matrix2d::Identity(), 0), InvalidInput);
    EXPECT_THROW(class_a_control_points(Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 0), Eigen::Matrix2d::Identity(), 3), InvalidInput);
}

TEST(TypicalPolygon, ConstructionsAndUndefinedAlphas) {
    const TypicalPolygon a = scale_one_typical_polygon(-0.5, 1.5, 24);
    EXPECT_EQ(a.points.rows(), 25);
    for (double l : a.edge_lengths) EXPECT_NEAR(l, 1.5 / 24, 1e-15);
    for (std::size_t j = 0; j < a.rotations.size(); ++j)
        EXPECT_NEAR(a.rotations[j], -0.5 * (std::pow(static_cast<double>(j + 1) * 1.5 / 24, 3) - std::pow(static_cast<double>(j) * 1.5 / 24, 3)), 1e-15);
    const TypicalPolygon b = constant_rotation_typical_polygon(-0.5, 1.5, 24);
    double total = 0.0;
    for (double l : b.edge_lengths) total += l;
    EXPECT_NEAR(total, 1.5, 1e-13);
    for (std::size_t j = 0; j < b.scales.size(); ++j) EXPECT_NEAR(b.scales[j], constant_rotation_scale_ratio(-0.5, static_cast<int>(j)), 1e-13);
    const TypicalPolygon sp = log_spiral_polygon(0.2, 1.0, 0.1, 20);
    for (std::size_t j = 1; j < sp.scales.size(); ++j) {
        EXPECT_NEAR(sp.scales[j], sp.scales[0], 1e-12);
        EXPECT_NEAR(sp.rotations[j], 0.1, 1e-12);
    }
    for (double bad : {0.0, 0.5, 1.0}) EXPECT_THROW(scale_one_typical_polygon(bad, 1.0, 10), InvalidInput);
    for (double bad : {0.0, 1.0}) EXPECT_THROW(constant_rotation_typical_polygon(bad, 1.0, 10), InvalidInput);
    EXPECT_THROW(scale_one_typical_polygon(-0.5, 1.0, 0), InvalidInput);
    EXPECT_THROW(scale_one_typical_polygon(-0.5, INFINITY, 5), InvalidInput);
}
