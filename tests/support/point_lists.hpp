#pragma once
// Point lists the tests share: a list from (x, y) pairs, the data of pseudo_energy Table 1 (after
// Newbery and Garrett), and the direction angle of a planar vector.
#include <Eigen/Dense>
#include <cmath>
#include <initializer_list>
#include <utility>

#include "cagd/core/points.hpp"

namespace cagd::test {

inline PointList points(std::initializer_list<std::pair<double, double>> xy) {
    PointList p(static_cast<Eigen::Index>(xy.size()), 2);
    Eigen::Index i = 0;
    for (const auto& [x, y] : xy) p.row(i++) << x, y;
    return p;
}

// pseudo_energy Table 1 (reference/pseudo_energy/data/table1.csv).
inline const PointList kNewberyGarrett = points({{0.0, 5.0},
                                                 {0.3, 2.5},
                                                 {1.5, 1.5},
                                                 {2.3, 1.25},
                                                 {2.5, 2.5},
                                                 {3.0, 3.5},
                                                 {5.0, 3.75},
                                                 {5.5, 3.3},
                                                 {5.75, 1.0},
                                                 {7.0, 1.0},
                                                 {8.0, 0.75},
                                                 {9.0, 3.5},
                                                 {10.0, 3.75}});

inline double angle_of(const Eigen::RowVectorXd& v) { return std::atan2(v(1), v(0)); }

}  // namespace cagd::test
