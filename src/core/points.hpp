#pragma once
// Point lists: one point per row of an Eigen matrix (rows = points, cols = dimension
// 1, 2 or 3). Validation shared by every constructor that takes data points.
#include <Eigen/Dense>
#include <string>

namespace cagd {

using PointList = Eigen::MatrixXd;   // n × dim, one point per row

// Throws InvalidInput unless: rows ≥ min_count, 1 ≤ cols ≤ 3, every coordinate finite,
// and (if distinct_consecutive) no two consecutive points coincide (for closed lists
// also last vs first). Messages name `who`, the row index and the value.
void require_valid_points(const PointList& points, Eigen::Index min_count,
                          bool distinct_consecutive, bool closed, const std::string& who);

}  // namespace cagd
