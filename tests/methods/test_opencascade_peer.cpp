// The occt-interpolate peer (methods/register_opencascade.cpp): what OpenCASCADE's
// GeomAPI_Interpolate computes, measured. Open curves are C2 cubics with a knot at every chord-length
// parameter; closed curves are C2 at their interior points and only C1 where they close.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <string>

#include "cagd/methods/method_registry.hpp"
#include "cagd/spline/bspline.hpp"

using namespace cagd;
using namespace cagd::methods;

namespace {

bool has_opencascade_peer() {
    const auto names = method_names();
    return std::find(names.begin(), names.end(), "occt-interpolate") != names.end();
}

PointList wavy_points(int n, bool space) {
    PointList p(n, space ? 3 : 2);
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n, r = 1.0 + 0.3 * (i % 2);
        p(i, 0) = r * std::cos(a);
        p(i, 1) = r * std::sin(a);
        if (space) p(i, 2) = 0.2 * i;
    }
    return p;
}

// |f^(k)(u+) − f^(k)(u−)| relative to |f^(k)| there.
double jump(const Curve& c, double u, int k) {
    const Eigen::MatrixXd right = c.jet(u, k), left = c.jet_from_left(u, k);
    return (right.row(k) - left.row(k)).norm() / std::max(right.row(k).norm(), 1e-300);
}

}  // namespace

TEST(OpenCascadePeer, OpenCurveIsAC2CubicThroughThePointsAtChordLength) {
    if (!has_opencascade_peer()) GTEST_SKIP() << "a library without OpenCASCADE";
    for (bool space : {false, true}) {
        const PointList p = wavy_points(9, space);
        const InterpolationResult r = interpolate("occt-interpolate", p, false);
        ASSERT_TRUE(r.outcome.ok()) << r.outcome.message;
        const Curve& c = *r.interpolant->curve;
        EXPECT_EQ(c.polynomial_degree(), 3);
        EXPECT_EQ(c.dimension(), p.cols());
        double chord = 0.0;
        for (int i = 0; i < p.rows(); ++i) {
            if (i > 0) chord += (p.row(i) - p.row(i - 1)).norm();
            const double u = r.interpolant->node_parameters[static_cast<std::size_t>(i)];
            EXPECT_NEAR(u, chord, 1e-13 * chord);
            EXPECT_LE((c.point(u) - p.row(i).transpose()).norm(), 1e-12);
            if (i > 0 && i + 1 < p.rows()) {
                EXPECT_LE(jump(c, u, 1), 1e-11) << "C1 at point " << i;
                EXPECT_LE(jump(c, u, 2), 1e-10) << "C2 at point " << i;
                EXPECT_GT(jump(c, u, 3), 1e-6) << "a knot at point " << i << " (the third derivative jumps)";
            }
        }
        EXPECT_EQ(c.t_min(), 0.0);
        EXPECT_NEAR(c.t_max(), chord, 1e-13 * chord);
    }
}

TEST(OpenCascadePeer, ClosedCurveIsC2InsideAndOnlyC1WhereItCloses) {
    if (!has_opencascade_peer()) GTEST_SKIP() << "a library without OpenCASCADE";
    const PointList p = wavy_points(8, false);
    const InterpolationResult r = interpolate("occt-interpolate", p, true);
    ASSERT_TRUE(r.outcome.ok()) << r.outcome.message;
    const Curve& c = *r.interpolant->curve;
    const std::vector<double>& u = r.interpolant->node_parameters;
    ASSERT_EQ(u.size(), 9u);
    EXPECT_LE((c.point(c.t_max()) - c.point(c.t_min())).norm(), 1e-12);
    for (std::size_t i = 1; i + 1 < u.size(); ++i) EXPECT_LE(jump(c, u[i], 2), 1e-10) << "C2 at point " << i;
    // Across the closing point: first derivatives agree, second derivatives do not.
    const Eigen::MatrixXd start = c.jet(c.t_min(), 2), end = c.jet_from_left(c.t_max(), 2);
    EXPECT_LE((start.row(1) - end.row(1)).norm(), 1e-11 * start.row(1).norm());
    EXPECT_GT((start.row(2) - end.row(2)).norm(), 1e-3 * start.row(2).norm())
        << "OpenCASCADE's periodic interpolation is C1 only where it closes";
}

TEST(OpenCascadePeer, TinyAndHugeDataGiveTheSameShape) {
    if (!has_opencascade_peer()) GTEST_SKIP() << "a library without OpenCASCADE";
    const PointList p = wavy_points(7, false);
    const InterpolationResult one = interpolate("occt-interpolate", p, false);
    for (double scale : {1e-9, 1e9}) {
        const InterpolationResult s = interpolate("occt-interpolate", PointList(p * scale), false);
        ASSERT_TRUE(s.outcome.ok()) << s.outcome.message;
        for (int k = 0; k <= 20; ++k) {
            const double t = one.interpolant->curve->t_max() * k / 20;
            EXPECT_LE((s.interpolant->curve->point(std::min(t * scale, s.interpolant->curve->t_max())) / scale -
                       one.interpolant->curve->point(t))
                          .norm(),
                      1e-12);
        }
    }
}

// Planar points go through Geom2dAPI_Interpolate (two coordinates per point in OpenCASCADE's arrays,
// not three): the same curve, bit for bit, as GeomAPI_Interpolate on the points with z = 0.
TEST(OpenCascadePeer, PlanarPointsGiveTheCurveOfTheSpacePathBitForBit) {
    if (!has_opencascade_peer()) GTEST_SKIP() << "a library without OpenCASCADE";
    for (bool closed : {false, true}) {
        PointList planar = wavy_points(41, false);
        planar(7, 0) += 1e-3;  // not symmetric
        PointList space(planar.rows(), 3);
        space << planar, Eigen::VectorXd::Zero(planar.rows());
        const InterpolationResult a = interpolate("occt-interpolate", planar, closed),
                                  b = interpolate("occt-interpolate", space, closed);
        ASSERT_TRUE(a.outcome.ok() && b.outcome.ok()) << a.outcome.message << b.outcome.message;
        const auto* ca = dynamic_cast<const BSplineCurve*>(a.interpolant->curve.get());
        const auto* cb = dynamic_cast<const BSplineCurve*>(b.interpolant->curve.get());
        ASSERT_TRUE(ca && cb);
        EXPECT_EQ(ca->knots(), cb->knots()) << "closed " << closed;
        ASSERT_EQ(ca->control_points().rows(), cb->control_points().rows());
        EXPECT_TRUE(ca->control_points() == cb->control_points().leftCols(2)) << "closed " << closed;
        EXPECT_TRUE(cb->control_points().col(2).isZero(0.0)) << "closed " << closed;
        EXPECT_EQ(a.interpolant->node_parameters, b.interpolant->node_parameters);
    }
}

namespace {
// Whether a shared object whose name contains `name` is mapped into this process.
bool mapped(const std::string& name) {
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line))
        if (line.find(name) != std::string::npos) return true;
    return false;
}
}  // namespace

TEST(OpenCascadePeer, OpenCascadeIsLoadedOnlyWhenFirstUsed) {
    if (!has_opencascade_peer()) GTEST_SKIP() << "library built without OpenCASCADE";
    // The test program links the library, not OpenCASCADE: its 30 ms of start-up come with the
    // plugin (core/detail/opencascade_plugin.hpp), on the first interpolation. Checked in a fresh
    // process (the threadsafe death-test style re-executes this program for this test alone): in
    // this one an earlier test may have loaded OpenCASCADE already.
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const auto first_use = [] {
        std::string failed;
        if (mapped("libTKernel")) failed += " OpenCASCADE was loaded before any use;";
        if (mapped("libcagd_occt")) failed += " the plugin was loaded before any use;";
        const InterpolationResult r = interpolate(find_configuration("occt-interpolate"), wavy_points(8, false), false);
        if (!r.outcome.ok()) failed += " the interpolation failed: " + r.outcome.message + ";";
        if (!mapped("libcagd_occt")) failed += " the plugin is not loaded after the interpolation;";
        if (!mapped("libTKernel")) failed += " OpenCASCADE is not loaded after the interpolation;";
        std::fprintf(stderr, "first use:%s\n", failed.empty() ? " as expected" : failed.c_str());
        std::exit(failed.empty() ? 0 : 1);
    };
    EXPECT_EXIT(first_use(), ::testing::ExitedWithCode(0), "first use: as expected");
}
