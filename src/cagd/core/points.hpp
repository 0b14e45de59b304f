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
void require_valid_points(const PointList& points, Eigen::Index min_count, bool distinct_consecutive, bool closed,
                          const std::string& who);

/// What a construction checks of its points besides require_valid_points: the largest |coordinate|
/// and the smallest squared chord length (the squares summed as in chord_lengths; the closing
/// chord included when closed).
struct PointExtent {
    double largest_abs_coordinate = 0.0;  ///< max |x_{i,k}|
    double shortest_squared_chord = 0.0;  ///< min over the chords of |P_{k+1} − P_k|², +∞ without chords
};
/// require_valid_points(points, min_count, true, closed, who), with the same messages, and the
/// extent above, in one pass over the points by blocks that stay in cache.
PointExtent require_valid_points_with_extent(const PointList& points, Eigen::Index min_count, bool closed,
                                             const std::string& who);

/// Points that have passed require_valid_points(points, min_count, true, closed, …): the proof a
/// construction takes so that the points are validated once (the registry validates them, and
/// the construction it calls does not again: at 10^6 points a second pass cost 7–8 % of a Hermite,
/// cubic or S/B2-spline construction). Made only by validate_points. It refers to the points: they
/// must outlive it, unchanged. A construction needing more points than min_count(), or the other
/// closedness, checks them itself as it would a PointList.
class ValidPoints {
public:
    const PointList& points() const { return points_; }    ///< the points
    Eigen::Index min_count() const { return min_count_; }  ///< the least number of points checked for
    bool closed() const { return closed_; }                ///< whether the closing chord was checked (a closed curve)
    const PointExtent& extent() const { return extent_; }  ///< what require_valid_points_with_extent found
    /// Whether these checks are those a construction of a curve, closed or not as `closed`, through
    /// at least `count` points needs.
    bool cover(Eigen::Index count, bool closed) const { return count <= min_count_ && closed == closed_; }
    /// The same proof for a construction through at least `count` points: InvalidInput naming `who`
    /// unless the list has that many (its other checks do not depend on the count, so nothing is
    /// checked again).
    ValidPoints at_least(Eigen::Index count, const std::string& who) const;

private:
    ValidPoints(const PointList& points, Eigen::Index min_count, bool closed, PointExtent extent)
        : points_(points), min_count_(min_count), closed_(closed), extent_(extent) {}
    friend ValidPoints validate_points(const PointList& points, Eigen::Index min_count, bool closed,
                                       const std::string& who);
    const PointList& points_;
    Eigen::Index min_count_;
    bool closed_;
    PointExtent extent_;
};
/// require_valid_points_with_extent(points, min_count, closed, who), its proof kept.
ValidPoints validate_points(const PointList& points, Eigen::Index min_count, bool closed, const std::string& who);
/// Not for a temporary (or an Eigen expression made into one): the proof would outlive its points.
ValidPoints validate_points(PointList&& points, Eigen::Index min_count, bool closed, const std::string& who) = delete;

/// The lengths |P_{k+1} − P_k| of the chords, k = 0 … n − 2, and for a closed list also
/// |P_0 − P_{n−1}| last. Each is the square root of the squared coordinate differences summed in
/// coordinate order, as Eigen's `(row(k + 1) − row(k)).norm()` sums them: the same values bit for
/// bit, computed over contiguous columns (vectorised).
std::vector<double> chord_lengths(const PointList& points, bool closed);

/// The first chord k (numbered as in chord_lengths) whose squared length is not ≥ shortest², or −1
/// if every chord is at least that long; one vectorised pass, no allocation. Precondition:
/// shortest² is a normal double (shortest ≥ 1.5e-154).
Eigen::Index first_chord_shorter_than(const PointList& points, bool closed, double shortest);

/// Throws InvalidInput unless `values` has at least min_count entries, all finite and strictly
/// increasing (abscissae of y(x) data, grid lines). `name` ("x", "y") appears in the message with
/// the index and the offending value.
void require_increasing(const std::vector<double>& values, std::size_t min_count, const std::string& name,
                        const std::string& who);

/// The diagonal of the points' axis-aligned bounding box: the length scale against which distances
/// between curves, overshoot and tolerances are measured. 0 for a single point or an empty list.
double bounding_box_diagonal(const PointList& points);

}  // namespace cagd
