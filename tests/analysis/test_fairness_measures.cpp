// analysis/fairness_measures: inflections, corners, overshoot and self-crossings.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/fairness/pseudo_spline.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "cagd/spline/hermite_spline.hpp"

#include "../support/point_lists.hpp"

using namespace cagd;
using namespace cagd::test;
using namespace cagd::fairness;
using spline::PiecewiseHermiteCurve;

TEST(FairnessMeasures, CountInflectionsCornersOvershootAndCrossings) {
    // An S-shaped Hermite span (r'(0) = r'(1) = (1, 1)): one inflection, inside the data box.
    Eigen::MatrixXd nodes(2, 2), d0(1, 2), d1(1, 2);
    nodes << 0, 0, 1, 0;
    d0 << 1, 1;
    d1 << 1, 1;
    const PiecewiseHermiteCurve s(nodes, d0, d1);
    const PointList data = points({{0, 0}, {1, 0}, {0.5, 0.5}, {0.5, -0.5}});
    const analysis::FairnessMeasures f = analysis::fairness_measures(s, data);
    EXPECT_EQ(f.curvature_sign_changes, 1);
    EXPECT_EQ(f.overshoot, 0.0);
    EXPECT_EQ(f.corners, 0);
    EXPECT_NEAR(f.length, analysis::arc_length(s, 8), 1e-12);
    EXPECT_NEAR(analysis::adaptive_arc_length(s, 1e-12), analysis::romberg_arc_length(s).value, 1e-11)
        << "two integrators agree";
    EXPECT_NEAR(f.pseudo_energy, f.length * f.length * f.bending_energy, 1e-12) << "one piece: L² E";
    // A near-cusp: tangents reversed against the chord.
    d0 << -1.45, 0.02;
    d1 << -1.45, -0.02;
    const analysis::FairnessMeasures g = analysis::fairness_measures(PiecewiseHermiteCurve(nodes, d0, d1), data);
    EXPECT_EQ(g.corners, 1);
    const PiecewiseHermiteCurve near_cusp(nodes, d0, d1);
    EXPECT_NEAR(analysis::adaptive_arc_length(near_cusp, 1e-12), analysis::romberg_arc_length(near_cusp).value, 1e-10)
        << "adaptive Gauss–Kronrod at a near-cusp";
    EXPECT_GT(g.max_spike, analysis::kCornerThreshold);
    // Overshoot: a span bulging above the box of its data.
    d0 << 0, 4;
    d1 << 0, -4;
    EXPECT_GT(analysis::fairness_measures(PiecewiseHermiteCurve(nodes, d0, d1), points({{0, 0}, {1, 0.1}})).overshoot,
              0.5);
    // A simple closed loop does not cross itself.
    Eigen::MatrixXd loop(5, 2), l0(4, 2), l1(4, 2);
    loop << 0, 0, 1, 1, 0, 2, -1, 1, 0, 0;
    l0 << 1.5, 0, 0, 1.5, -1.5, 0, 0, -1.5;
    l1 << 0, 1.5, -1.5, 0, 0, -1.5, 1.5, 0;
    EXPECT_EQ(analysis::self_intersections(PiecewiseHermiteCurve(loop, l0, l1)), 0);
    // The span from (0,0) to (1,0) with r'(0) = (4, 4), r'(1) = (4, −4) is x = 6t³ − 9t² + 4t,
    // y = 4t(1 − t): it crosses itself once, at t = (3 ∓ √3)/6 (where x = 1/2).
    d0 << 4, 4;
    d1 << 4, -4;
    EXPECT_EQ(analysis::self_intersections(PiecewiseHermiteCurve(nodes, d0, d1)), 1);
}
