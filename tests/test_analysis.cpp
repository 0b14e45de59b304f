// Curvature, arc length, enclosed area through the Curve interface, with known values.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/curve_measures.hpp"
#include "core/errors.hpp"
#include "spline/bezier.hpp"
#include "spline/bspline.hpp"

using namespace cagd;

TEST(Analysis, ParabolaCurvatureAndLength) {
    // y = x² on [0, 1] as a quadratic Bézier: κ(0) = 2, κ(1) = 2/5^{3/2}; L = (2√5 + asinh 2)/4.
    Eigen::MatrixXd b(3, 2);
    b << 0, 0, 0.5, 0, 1, 1;
    const BezierCurve c(b);
    EXPECT_NEAR(analysis::signed_curvature(c, 0.0), 2.0, 1e-14);
    EXPECT_NEAR(analysis::curvature(c, 1.0), 2.0 / std::pow(5.0, 1.5), 1e-14);
    const double L = (2 * std::sqrt(5.0) + std::asinh(2.0)) / 4.0;
    EXPECT_NEAR(analysis::arc_length(c), L, 1e-14);
    const auto r = analysis::romberg_arc_length(c, 1e-13);
    ASSERT_TRUE(r.outcome.ok());
    EXPECT_NEAR(r.value, L, 1e-13);
}

TEST(Analysis, AreaOfClosedPolylineSquareIsOne) {
    Eigen::MatrixXd p(5, 2);
    p << 0, 0, 1, 0, 1, 1, 0, 1, 0, 0;
    const BSplineCurve sq(1, {0, 0, 1, 2, 3, 4, 4}, p);
    EXPECT_NEAR(analysis::enclosed_area(sq), 1.0, 1e-15);
    EXPECT_NEAR(analysis::arc_length(sq), 4.0, 1e-14);
}

TEST(Analysis, SingularPointIsAnError) {
    Eigen::MatrixXd b(3, 2);
    b << 0, 0, 0, 0, 1, 1;   // r'(0) = 0
    EXPECT_THROW(analysis::curvature(BezierCurve(b), 0.0), InvalidInput);
    Eigen::MatrixXd s(2, 3);
    s << 0, 0, 0, 1, 1, 1;
    EXPECT_THROW(analysis::signed_curvature(BezierCurve(s), 0.5), InvalidInput);
}

TEST(Analysis, NormalOffsetIsSignedDistanceAlongLeftNormal) {
    Eigen::MatrixXd a(2, 2), b(2, 2);
    b << 0, 0, 1, 0;    // along +x: left normal is +y
    a << 0, 0.5, 1, 0.5;
    EXPECT_NEAR(analysis::normal_offset(BezierCurve(a), BezierCurve(b), 0.3), 0.5, 1e-15);
    EXPECT_NEAR(analysis::normal_offset(BezierCurve(b), BezierCurve(a), 0.3), -0.5, 1e-15);
}
