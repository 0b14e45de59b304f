#include "cagd/core/points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cagd/core/errors.hpp"
#include "cagd/core/finite.hpp"

namespace cagd {

namespace {

// Whether two consecutive rows of finite points are equal: where Σ_k |x_{i+1,k} − x_{i,k}| = 0 (a
// difference of distinct doubles is never 0). By blocks on the stack: the sums in one loop over
// the contiguous columns and their minimum in Eigen's, both vectorised, no branch per point.
template <int D>
bool any_consecutive_rows_equal_of_dimension(const PointList& points) {
    const Eigen::Index n = points.rows();
    const double* c[3] = {points.col(0).data(), D > 1 ? points.col(1).data() : nullptr,
                          D > 2 ? points.col(2).data() : nullptr};
    constexpr Eigen::Index kBlock = 1024;
    double sums[kBlock];
    for (Eigen::Index a = 0; a + 1 < n; a += kBlock) {
        const Eigen::Index count = std::min(kBlock, n - 1 - a);
        for (Eigen::Index i = 0; i < count; ++i) {
            double sum = std::abs(c[0][a + i + 1] - c[0][a + i]);
            if constexpr (D > 1) sum += std::abs(c[1][a + i + 1] - c[1][a + i]);
            if constexpr (D > 2) sum += std::abs(c[2][a + i + 1] - c[2][a + i]);
            sums[i] = sum;
        }
        if (Eigen::Map<const Eigen::ArrayXd>(sums, count).minCoeff() == 0.0) return true;
    }
    return false;
}

bool any_consecutive_rows_equal(const PointList& points) {
    switch (points.cols()) {
        case 1: return any_consecutive_rows_equal_of_dimension<1>(points);
        case 2: return any_consecutive_rows_equal_of_dimension<2>(points);
        default: return any_consecutive_rows_equal_of_dimension<3>(points);
    }
}

}  // namespace

void require_valid_points(const PointList& points, Eigen::Index min_count, bool distinct_consecutive, bool closed,
                          const std::string& who) {
    const Eigen::Index n = points.rows();
    if (n < min_count)
        fail_input(who, "needs at least " + std::to_string(min_count) + " points, got " + std::to_string(n));
    if (points.cols() < 1 || points.cols() > 3)
        fail_input(who, "points must have 1, 2 or 3 coordinates, got " + std::to_string(points.cols()));
    if (!all_finite(points))  // one vectorised pass; the search for the first culprit only on failure
        for (Eigen::Index i = 0; i < n; ++i)
            for (Eigen::Index k = 0; k < points.cols(); ++k)
                if (!std::isfinite(points(i, k)))
                    fail_input(who, point_label(i) + " coordinate " + "xyz"[k] + " is " + full_precision(points(i, k)) +
                                        "; coordinates must be finite");
    if (!distinct_consecutive) return;
    const bool open_pairs_distinct = !any_consecutive_rows_equal(points);
    if (open_pairs_distinct && !(closed && n > 0 && points.row(n - 1) == points.row(0))) return;
    const Eigen::Index pairs = closed ? n : n - 1;
    for (Eigen::Index i = 0; i < pairs; ++i) {
        const Eigen::Index j = i + 1 == n ? 0 : i + 1;  // (no modulo per point: an integer division)
        if (points.row(i) == points.row(j))
            fail_input(who, point_label(i) + " and " + point_label(j) +
                                " coincide (zero-length chord); consecutive points must differ");
    }
}

namespace {

// Visits chord k = 0 … spans − 1 with its squared length, the D squared coordinate differences
// summed in coordinate order (as Eigen's squaredNorm of a row sums them), from contiguous columns;
// the closing chord (k = n − 1) last. No square root here: a libm sqrt call (errno) keeps a loop
// scalar. Written so the loop over k vectorises.
template <int D, class Visit>
void visit_squared_chords(const PointList& points, bool closed, Visit&& visit) {
    const Eigen::Index n = points.rows();
    const double* c[3] = {points.col(0).data(), D > 1 ? points.col(1).data() : nullptr,
                          D > 2 ? points.col(2).data() : nullptr};
    const auto squared = [&](Eigen::Index a, Eigen::Index b) {
        double sum = (c[0][b] - c[0][a]) * (c[0][b] - c[0][a]);
        if constexpr (D > 1) sum = sum + (c[1][b] - c[1][a]) * (c[1][b] - c[1][a]);
        if constexpr (D > 2) sum = sum + (c[2][b] - c[2][a]) * (c[2][b] - c[2][a]);
        return sum;
    };
    for (Eigen::Index k = 0; k + 1 < n; ++k) visit(k, squared(k, k + 1));
    if (closed && n > 0) visit(n - 1, squared(n - 1, 0));
}

template <class Visit>
void visit_squared_chords(const PointList& points, bool closed, Visit&& visit) {
    switch (points.cols()) {
        case 1: return visit_squared_chords<1>(points, closed, visit);
        case 2: return visit_squared_chords<2>(points, closed, visit);
        case 3: return visit_squared_chords<3>(points, closed, visit);
        default:
            for (Eigen::Index k = 0; k + 1 < points.rows() || (closed && k < points.rows()); ++k)
                visit(k, (points.row(k + 1 == points.rows() ? 0 : k + 1) - points.row(k)).squaredNorm());
    }
}

}  // namespace

namespace {

// The pass of require_valid_points_with_extent for D coordinates: per block of kBlock chords, on
// the stack, the sums Σ_k |Δx_k| (0 only for coinciding points) and the squared lengths, their
// minima and the block's largest |coordinate| by Eigen's vectorised reductions, and the finiteness
// of the block's coordinates. The closing chord is the caller's.
template <int D>
void survey_of_dimension(const PointList& points, bool& finite, bool& coincident, PointExtent& extent) {
    const Eigen::Index n = points.rows();
    const double* c[3] = {points.col(0).data(), D > 1 ? points.col(1).data() : nullptr,
                          D > 2 ? points.col(2).data() : nullptr};
    constexpr Eigen::Index kBlock = 1024;
    double sums[kBlock], squares[kBlock];
    double smallest_sum = std::numeric_limits<double>::infinity();
    for (Eigen::Index a = 0; a < n; a += kBlock) {
        const Eigen::Index rows = std::min(kBlock, n - a), chords = std::min(kBlock, n - 1 - a);
        for (int k = 0; k < D; ++k) {
            finite = finite && all_finite(c[k] + a, static_cast<std::size_t>(rows));
            extent.largest_abs_coordinate = std::max(extent.largest_abs_coordinate,
                                                     Eigen::Map<const Eigen::ArrayXd>(c[k] + a, rows).abs().maxCoeff());
        }
        if (chords <= 0) continue;
        for (Eigen::Index i = 0; i < chords; ++i) {
            const double d0 = c[0][a + i + 1] - c[0][a + i];
            double sum = std::abs(d0), square = d0 * d0;
            if constexpr (D > 1) {
                const double d1 = c[1][a + i + 1] - c[1][a + i];
                sum += std::abs(d1), square = square + d1 * d1;
            }
            if constexpr (D > 2) {
                const double d2 = c[2][a + i + 1] - c[2][a + i];
                sum += std::abs(d2), square = square + d2 * d2;
            }
            sums[i] = sum, squares[i] = square;
        }
        smallest_sum = std::min(smallest_sum, Eigen::Map<const Eigen::ArrayXd>(sums, chords).minCoeff());
        extent.shortest_squared_chord =
            std::min(extent.shortest_squared_chord, Eigen::Map<const Eigen::ArrayXd>(squares, chords).minCoeff());
    }
    coincident = smallest_sum == 0.0;
}

}  // namespace

PointExtent require_valid_points_with_extent(const PointList& points, Eigen::Index min_count, bool closed,
                                             const std::string& who) {
    const Eigen::Index n = points.rows();
    if (n < min_count || points.cols() < 1 || points.cols() > 3 || n == 0) {
        require_valid_points(points, min_count, true, closed, who);  // throws, or accepts an empty list
        return {0.0, std::numeric_limits<double>::infinity()};
    }
    PointExtent extent{0.0, std::numeric_limits<double>::infinity()};
    bool finite = true, coincident = false;
    switch (points.cols()) {
        case 1: survey_of_dimension<1>(points, finite, coincident, extent); break;
        case 2: survey_of_dimension<2>(points, finite, coincident, extent); break;
        default: survey_of_dimension<3>(points, finite, coincident, extent); break;
    }
    if (closed) {
        coincident = coincident || points.row(n - 1) == points.row(0);
        double square = 0.0;  // the closing chord, summed as visit_squared_chords sums it
        for (Eigen::Index k = 0; k < points.cols(); ++k) {
            const double d = points(0, k) - points(n - 1, k);
            square = k == 0 ? d * d : square + d * d;
        }
        extent.shortest_squared_chord = std::min(extent.shortest_squared_chord, square);
    }
    if (!finite || coincident)
        require_valid_points(points, min_count, true, closed, who);  // names the culprit and throws
    return extent;
}

ValidPoints validate_points(const PointList& points, Eigen::Index min_count, bool closed, const std::string& who) {
    return {points, min_count, closed, require_valid_points_with_extent(points, min_count, closed, who)};
}

ValidPoints ValidPoints::at_least(Eigen::Index count, const std::string& who) const {
    if (points_.rows() < count)
        fail_input(who, "needs at least " + std::to_string(count) + " points, got " + std::to_string(points_.rows()));
    return {points_, std::max(count, min_count_), closed_, extent_};
}

std::vector<double> chord_lengths(const PointList& points, bool closed) {
    const Eigen::Index n = points.rows(), spans = std::max<Eigen::Index>(closed ? n : n - 1, 0);
    std::vector<double> h(static_cast<std::size_t>(spans));
    double* out = h.data();
    visit_squared_chords(points, closed, [out](Eigen::Index k, double squared) { out[k] = squared; });
    Eigen::Map<Eigen::ArrayXd> lengths(out, spans);
    lengths = lengths.sqrt();  // Eigen's packet sqrt: correctly rounded, as std::sqrt
    return h;
}

Eigen::Index first_chord_shorter_than(const PointList& points, bool closed, double shortest) {
    const double limit = shortest * shortest;
    bool any = false;  // an OR over all chords (vectorises), then the search only on failure
    visit_squared_chords(points, closed, [&](Eigen::Index, double squared) { any |= !(squared >= limit); });
    if (!any) return -1;
    Eigen::Index first = -1;
    visit_squared_chords(points, closed, [&](Eigen::Index k, double squared) {
        if (first < 0 && !(squared >= limit)) first = k;
    });
    return first;
}

void require_increasing(const std::vector<double>& values, std::size_t min_count, const std::string& name,
                        const std::string& who) {
    if (values.size() < min_count)
        fail_input(who, "needs at least " + std::to_string(min_count) + " values of " + name + ", got " +
                            std::to_string(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i]))
            fail_input(who,
                       name + "[" + std::to_string(i) + "] is " + full_precision(values[i]) + "; it must be finite");
        if (i > 0 && !(values[i] > values[i - 1]))
            fail_input(who, name + " must increase strictly: " + name + "[" + std::to_string(i) +
                                "] = " + full_precision(values[i]) + " after " + full_precision(values[i - 1]));
    }
}

double bounding_box_diagonal(const PointList& points) {
    if (points.rows() == 0) return 0.0;
    return (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
}

}  // namespace cagd
