// typical_curves sections 2–3 and appendix A: Bernstein polynomials, stable Bézier evaluation,
// the LCG, log-aesthetic curves, class A matrices, typical polygons, cubic B-spline monotonicity.
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

TEST(CubicBsplineMonotonicity, ClosedFormCoefficientsEqualTheProductComputation) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> ang(0.0, 3.0);
    for (int k = 0; k < 200; ++k) {
        const double a = ang(rng), b = ang(rng);
        const auto closed = monotonicity_coefficients(a, b);
        const BernsteinPolynomial h =
            analysis::curvature_derivative_numerator(BezierCurve(uniform_segment_bezier(unit_edge_polygon(a, b))));
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
    for (const Case& cs : {Case{-1.5, 1.0, 0.5}, Case{-0.5, 2.0, 0.3}, Case{0.0, 1.2, 0.7}, Case{0.5, 1.0, 1.0},
                           Case{1.0, 0.8, 0.5}, Case{2.0, 1.0, 0.4}, Case{1.5, -0.2, 1.0}}) {
        LogAestheticParameters p;
        p.alpha = cs.alpha;
        p.c0 = cs.c0;
        p.c1 = cs.c1;
        p.length = 2.0;
        p.start_angle = 0.3;
        const LogAestheticCurve c(p);
        for (double s : {0.5, 1.3, 2.0}) {
            const double integral = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                [&](double v) { return c.curvature(v); }, 0.0, s, 15, 1e-14);
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
    EXPECT_THROW(class_a_control_points(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Matrix2d::Identity(), 0),
                 InvalidInput);
    EXPECT_THROW(class_a_control_points(Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 0), Eigen::Matrix2d::Identity(), 3),
                 InvalidInput);
}

TEST(TypicalPolygon, ConstructionsAndUndefinedAlphas) {
    const TypicalPolygon a = scale_one_typical_polygon(-0.5, 1.5, 24);
    EXPECT_EQ(a.points.rows(), 25);
    for (double l : a.edge_lengths) EXPECT_NEAR(l, 1.5 / 24, 1e-15);
    for (std::size_t j = 0; j < a.rotations.size(); ++j)
        EXPECT_NEAR(a.rotations[j],
                    -0.5 * (std::pow(static_cast<double>(j + 1) * 1.5 / 24, 3) -
                            std::pow(static_cast<double>(j) * 1.5 / 24, 3)),
                    1e-15);
    const TypicalPolygon b = constant_rotation_typical_polygon(-0.5, 1.5, 24);
    double total = 0.0;
    for (double l : b.edge_lengths) total += l;
    EXPECT_NEAR(total, 1.5, 1e-13);
    for (std::size_t j = 0; j < b.scales.size(); ++j)
        EXPECT_NEAR(b.scales[j], constant_rotation_scale_ratio(-0.5, static_cast<int>(j)), 1e-13);
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
