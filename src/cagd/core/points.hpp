#pragma once
/// @file
/// Point lists: one point per row of an Eigen matrix (rows = points, cols = dimension
/// 1, 2 or 3). Validation shared by every constructor that takes data points.
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace cagd {

using PointList = Eigen::MatrixXd;  ///< n × dim, one point per row

/// Throws InvalidInput unless: rows ≥ min_count, 1 ≤ cols ≤ 3, every coordinate finite,
/// and (if distinct_consecutive) no two consecutive points coincide (for closed lists
/// also last vs first). Messages name `who`, the row index and the value.
void require_valid_points(const PointList& points, Eigen::Index min_count, bool distinct_consecutive, bool closed, const std::string& who);

/// Throws InvalidInput unless `values` has at least min_count entries, all finite and strictly
/// increasing (abscissae of y(x) data, grid lines). `name` ("x", "y") appears in the message with
/// the index and the offending value.
void require_increasing(const std::vector<double>& values, std::size_t min_count, const std::string& name, const std::string& who);

/// The diagonal of the points' axis-aligned bounding box: the length scale against which distances
/// between curves, overshoot and tolerances are measured. 0 for a single point or an empty list.
double bounding_box_diagonal(const PointList& points);

}  // namespace cagd
