#include "cagd/core/points.hpp"

#include <cmath>

#include "cagd/core/errors.hpp"

namespace cagd {

void require_valid_points(const PointList& points, Eigen::Index min_count, bool distinct_consecutive, bool closed, const std::string& who) {
    const Eigen::Index n = points.rows();
    if (n < min_count) fail_input(who, "needs at least " + std::to_string(min_count) + " points, got " + std::to_string(n));
    if (points.cols() < 1 || points.cols() > 3) fail_input(who, "points must have 1, 2 or 3 coordinates, got " + std::to_string(points.cols()));
    if (!points.allFinite())  // one vectorised pass; the search for the first culprit only on failure
        for (Eigen::Index i = 0; i < n; ++i)
            for (Eigen::Index k = 0; k < points.cols(); ++k)
                if (!std::isfinite(points(i, k)))
                    fail_input(who, "point " + std::to_string(i) + " coordinate " + std::to_string(k) + " is " + full_precision(points(i, k)) + "; coordinates must be finite");
    if (!distinct_consecutive) return;
    const Eigen::Index pairs = closed ? n : n - 1;
    for (Eigen::Index i = 0; i < pairs; ++i) {
        const Eigen::Index j = i + 1 == n ? 0 : i + 1;  // (no modulo per point: an integer division)
        bool same = true;
        for (Eigen::Index k = 0; k < points.cols(); ++k) same = same && points(i, k) == points(j, k);
        if (same) fail_input(who, "points " + std::to_string(i) + " and " + std::to_string(j) + " coincide (zero-length chord); consecutive points must differ");
    }
}

void require_increasing(const std::vector<double>& values, std::size_t min_count, const std::string& name, const std::string& who) {
    if (values.size() < min_count) fail_input(who, "needs at least " + std::to_string(min_count) + " values of " + name + ", got " + std::to_string(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) fail_input(who, name + "[" + std::to_string(i) + "] is " + full_precision(values[i]) + "; it must be finite");
        if (i > 0 && !(values[i] > values[i - 1]))
            fail_input(who, name + " must increase strictly: " + name + "[" + std::to_string(i) + "] = " + full_precision(values[i]) + " after " + full_precision(values[i - 1]));
    }
}

double bounding_box_diagonal(const PointList& points) {
    if (points.rows() == 0) return 0.0;
    return (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
}

}  // namespace cagd
