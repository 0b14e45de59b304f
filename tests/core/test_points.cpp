// core/points: point-list helpers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/pchip.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/core/random_walk.hpp"
#include "cagd/methods/method_registry.hpp"

using std::isnan;
using namespace cagd;
using namespace cagd::compare;
using namespace cagd::methods;

TEST(Points, BoundingBoxDiagonal) {
    PointList p(3, 2);
    p << 1, 2, 4, -2, 2, 0;  // box [1, 4] × [−2, 2]: diagonal 5
    EXPECT_DOUBLE_EQ(bounding_box_diagonal(p), 5.0);
    EXPECT_DOUBLE_EQ(bounding_box_diagonal(p.topRows(1)), 0.0);
    EXPECT_DOUBLE_EQ(bounding_box_diagonal(PointList(0, 2)), 0.0);
}
