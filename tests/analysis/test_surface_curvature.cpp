// analysis: the torsion rate of a curve and the Gaussian and mean curvature of a surface.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cagd/aesthetic/log_aesthetic_space_curve.hpp"
#include "cagd/aesthetic/space_typical_bezier.hpp"
#include "cagd/aesthetic/typical_surface.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/analysis/surface_curvature.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/numeric/alexa_product.hpp"
#include "cagd/spline/bezier.hpp"
#include "cagd/surface/bezier_patch.hpp"

using namespace cagd;
using namespace cagd::aesthetic;

TEST(Torsion, RateMatchesDifferencesOfTorsion) {
    Eigen::MatrixXd cp(6, 3);
    cp << 0, 0, 0, 1, 0.2, 0, 2, 1, 0.3, 2.5, 2, 1, 2, 3, 2.2, 1, 3.5, 3;
    const BezierCurve c(cp);
    const double h = 1e-5;
    for (double t : {0.1, 0.4, 0.77}) {
        const double speed = c.jet(t, 1).row(1).norm();
        const double fd = (analysis::torsion(c, t + h) - analysis::torsion(c, t - h)) / (2 * h) / speed;
        EXPECT_NEAR(analysis::torsion_arc_derivative(c, t), fd, 1e-6 * std::max(1.0, std::abs(fd))) << "t = " << t;
    }
    Eigen::MatrixXd planar(4, 2);
    planar << 0, 0, 1, 1, 2, 0, 3, 1;
    EXPECT_THROW(analysis::torsion(BezierCurve(planar), 0.5), InvalidInput);
    // A planar curve embedded in 3-D has no torsion: every LTG sample is skipped.
    Eigen::MatrixXd flat(4, 3);
    flat << 0, 0, 0, 1, 1, 0, 2, 0, 0, 3, 1, 0;
    EXPECT_EQ(analysis::log_torsion_graph(BezierCurve(flat), 0.0, 1.0, 10).skipped, 10);
    EXPECT_THROW(analysis::ltg_slope(BezierCurve(flat), 0.0, 1.0, 10), InvalidInput);
}

TEST(SurfaceCurvature, RejectsSingularPoints) {
    analysis::SurfaceJet2 j;
    j.s = j.suu = j.suv = j.svv = Eigen::Vector3d::Zero();
    j.su = Eigen::Vector3d::UnitX();
    j.sv = 2.0 * Eigen::Vector3d::UnitX();
    EXPECT_THROW(analysis::surface_curvatures(j), InvalidInput);
}
