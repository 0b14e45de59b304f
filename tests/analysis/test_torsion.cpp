// analysis::torsion and the flatness policy: τ is NaN where the curve is straight to rounding
// (κ · extent ≤ kFlatCurvature), as at the natural ends of a space spline, and the closed form
// det(r', r'', r''')/|r' × r''|² elsewhere.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/methods/method_registry.hpp"

namespace {

TEST(Torsion, IsNaNAtTheNaturalEndsOfASpaceSplineAndFiniteInside) {
    // A helix of radius 1 and pitch 2π·0.3 sampled at 9 points: its torsion is 0.3/(1 + 0.09).
    cagd::PointList p(9, 3);
    for (int i = 0; i < 9; ++i) p.row(i) << std::cos(0.7 * i), std::sin(0.7 * i), 0.3 * 0.7 * i;
    for (const char* method : {"cubic-b", "cubic-a"}) {
        const cagd::methods::InterpolationResult r = cagd::methods::interpolate(method, p, false);
        ASSERT_TRUE(r.outcome.ok()) << method;
        const cagd::Curve& c = *r.interpolant->curve;
        const double extent = cagd::analysis::curve_extent(c);
        EXPECT_NEAR(extent, (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm(), 0.5)
            << "the breakpoints are the points";
        for (double t : {c.t_min(), c.t_max()}) {
            ASSERT_LE(cagd::analysis::curvature(c, t) * extent, cagd::analysis::kFlatCurvature)
                << method << ": a natural end is straight, t = " << t;
            EXPECT_TRUE(std::isnan(cagd::analysis::torsion(c, t)))
                << method << ": τ at a natural end is undefined, not rounding noise, t = " << t;
        }
        const double middle = 0.5 * (c.t_min() + c.t_max());
        EXPECT_NEAR(cagd::analysis::torsion(c, middle), 0.3 / 1.09, 0.05)
            << method << ": the helix's torsion in the middle";
    }
}

TEST(Torsion, EqualsTheClosedFormWhereTheCurveBends) {
    // r(t) = (t, t², t³): τ = 3/(1 + 9t² + 9t⁴) … exactly det(r', r'', r''')/|r' × r''|² = 12/|(6t², −6t, 2)|².
    cagd::PointList p(7, 3);
    for (int i = 0; i < 7; ++i) {
        const double t = -0.6 + 0.2 * i;
        p.row(i) << t, t * t, t * t * t;
    }
    const auto r = cagd::methods::interpolate("eigen-spline-3", p, false);
    ASSERT_TRUE(r.outcome.ok());
    const cagd::Curve& c = *r.interpolant->curve;
    const double t = 0.5 * (c.t_min() + c.t_max());
    const Eigen::MatrixXd j = c.jet(t, 3);
    const Eigen::Vector3d d1 = j.row(1).transpose(), d2 = j.row(2).transpose(), d3 = j.row(3).transpose();
    EXPECT_DOUBLE_EQ(cagd::analysis::torsion(c, t), d1.cross(d2).dot(d3) / d1.cross(d2).squaredNorm());
}

}  // namespace
