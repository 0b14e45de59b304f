#pragma once
/// @file
/// Piecewise cubic Hermite curves and the classic interpolants built from them
/// (pseudo_energy section 4.2: "cubic spline A/B", "Hermite curve A/B").
///
/// PiecewiseHermiteCurve: span k (k = 0..K−1) runs from p_k to p_{k+1} on u ∈ [k, k+1] with local
/// t = u − k and
///     r(t) = H0(t) p_k + H1(t) p_{k+1} + H2(t) d0_k + H3(t) d1_k                       (pseudo_energy eq 4)
///     H0 = 2t³ − 3t² + 1, H1 = −2t³ + 3t², H2 = t³ − 2t² + t, H3 = t³ − t²,
/// so r(0) = p_k, r(1) = p_{k+1}, r'(0) = d0_k, r'(1) = d1_k. The end derivatives belong to the
/// span, so a curve is only G1 where d1_{k−1} ∥ d0_k with different lengths (the pseudo-spline),
/// and C1 where they are equal. Closed curves repeat p_0 as p_K.
/// One storage form: the derivative pairs d0_k, d1_k. A curve whose pairs come from one slope per
/// node (the C2 cubic splines, Boost's pchip, makima and Catmull–Rom) is built by from_node_slopes,
/// which forms d0_k = h_k m_k and d1_k = h_k m_{k+1} once.
///
/// Interpolants (points P_0..P_n, open, or P_0..P_{n−1} closed):
///   cubic_spline_interpolant   C2 cubic spline in a parameter τ: uniform (τ_k = k, "spline A") or
///                              chord length (τ_{k+1} − τ_k = |P_{k+1} − P_k|, "spline B"). Unknown
///                              node derivatives m_k = dr/dτ from the tridiagonal system
///                                h_k m_{k−1} + 2(h_{k−1} + h_k) m_k + h_{k−1} m_{k+1}
///                                  = 3 (h_k Δ_{k−1}/h_{k−1} + h_{k−1} Δ_k/h_k),  Δ_k = P_{k+1} − P_k,
///                              natural ends (r''(τ) = 0 at P_0, P_n: 2m_0 + m_1 = 3Δ_0/h_0 and
///                              m_{n−1} + 2m_n = 3Δ_{n−1}/h_{n−1}) or periodic (closed); span k has
///                              d0 = h_k m_k, d1 = h_k m_{k+1}. The paper cites [5] and states no
///                              end condition; natural ends are our choice. Solved in O(n) by the
///                              Thomas algorithm (cyclic: Sherman–Morrison), numeric/tridiagonal.
///   hermite_tangent_directions unit tangent directions per point:
///     chord_of_neighbours ("Hermite A"): t_i ∥ P_{i+1} − P_{i−1}; at an open end the chord to the
///                              adjacent point, t_0 ∥ P_1 − P_0, t_n ∥ P_n − P_{n−1}.
///     circle ("Hermite B"): t_i is the tangent at P_i of the circle through P_{i−1}, P_i, P_{i+1},
///                              t_i ∥ (|b|/|a|) a + (|a|/|b|) b, a = P_i − P_{i−1}, b = P_{i+1} − P_i
///                              (the inscribed-angle theorem; a straight line when collinear). At an
///                              open end the circle through P_0, P_1, P_2: t_0 = 2(t_1·â)â − t_1, the
///                              reflection of t_1 in the perpendicular bisector of P_0P_1 (and
///                              likewise at P_n with P_{n−2}, P_{n−1}, P_n).
///   hermite_interpolant        span k gets d0_k = l_k t_k, d1_k = l_k t_{k+1}, l_k = |P_{k+1} − P_k|
///                              ("the tangent magnitude equals the distance between the two points").
///
/// Preconditions (InvalidInput): finite coordinates, 1–3 columns, no coincident consecutive points
/// (closed: also last/first); at least 2 points for splines and Hermite A, 3 for Hermite B and for
/// any closed curve. Hermite A: P_{i−1} = P_{i+1} (an exact reversal) leaves no direction and throws;
/// Hermite B: a turn of exactly π at P_i (a, b antiparallel) likewise.
#include <Eigen/Dense>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/core/points.hpp"

namespace cagd::spline {

/// A piecewise cubic Hermite curve of K spans on u ∈ [0, K] (see above).
class PiecewiseHermiteCurve : public Curve {
public:
    /// nodes: K+1 rows (node K = node 0 for a closed curve); d0, d1: K rows each.
    PiecewiseHermiteCurve(Eigen::MatrixXd nodes, Eigen::MatrixXd d0, Eigen::MatrixXd d1);
    /// From one slope per node: nodes K+1 rows; slopes K+1 rows (closed: K rows, m_K = m_0); scales
    /// K values h_k, or none for h_k = 1. Span k gets d0_k = h_k m_k, d1_k = h_k m_{k+1}.
    static PiecewiseHermiteCurve from_node_slopes(Eigen::MatrixXd nodes, Eigen::MatrixXd slopes,
                                                  std::vector<double> scales);

    /// K.
    int spans() const { return static_cast<int>(nodes_.rows()) - 1; }
    /// The K + 1 nodes, one per row.
    const Eigen::MatrixXd& nodes() const { return nodes_; }
    /// The derivative d/du at the start of each span (K rows).
    const Eigen::MatrixXd& start_derivatives() const { return d0_; }
    /// The derivative d/du at the end of each span (K rows).
    const Eigen::MatrixXd& end_derivatives() const { return d1_; }

    int dimension() const override { return static_cast<int>(nodes_.cols()); }
    double t_min() const override { return 0.0; }
    double t_max() const override { return spans(); }
    void evaluate_jet(double u, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const override;
    std::vector<double> breakpoints() const override;
    int polynomial_degree() const override { return 3; }
    /// 0 where both curves evaluate [t0, t1] = [u0, u1] from equal data: another Hermite curve of as many
    /// spans and coordinates whose nodes and end derivatives agree, entry by entry, on every span the
    /// parameters fall in (the one starting at t1 included, which evaluates t1); std::nullopt otherwise.
    std::optional<double> span_offset_bound(const Curve& other, double t0, double t1, double u0,
                                            double u1) const override;

private:
    PiecewiseHermiteCurve() = default;
    Eigen::MatrixXd nodes_, d0_, d1_;
};

/// The parameter of the C2 cubic spline: uniform (cubic spline A) or chord length (cubic spline B).
enum class ParameterSpacing { uniform, chord_length };
/// The tangent direction at a node: along the chord of its neighbours (Hermite A) or of the circle through them
/// (Hermite B).
enum class TangentRule { chord_of_neighbours, circle };

/// The natural C2 cubic spline through the points (closed: periodic) in the given parameter, in Hermite form on unit
/// spans.
PiecewiseHermiteCurve cubic_spline_interpolant(const PointList& points, ParameterSpacing spacing, bool closed);
/// The same through points validated already (closed as they were validated): the same curve, the
/// points not checked again where their checks cover this construction's.
PiecewiseHermiteCurve cubic_spline_interpolant(const ValidPoints& points, ParameterSpacing spacing);
/// One unit direction per point (rows as `points`).
Eigen::MatrixXd hermite_tangent_directions(const PointList& points, TangentRule rule, bool closed);
/// Hermite curve through `points` with the given unit directions, magnitudes the chord lengths.
PiecewiseHermiteCurve hermite_interpolant(const PointList& points, const Eigen::MatrixXd& directions, bool closed);
/// hermite_interpolant(points, hermite_tangent_directions(points, rule, closed), closed) in one pass,
/// without the directions' n × dim temporary: Hermite curve A or B, the same values bit for bit.
PiecewiseHermiteCurve hermite_spline(const PointList& points, TangentRule rule, bool closed);
/// The same through points validated already (closed as they were validated): the same curve, the
/// points not checked again where their checks cover this construction's.
PiecewiseHermiteCurve hermite_spline(const ValidPoints& points, TangentRule rule);

}  // namespace cagd::spline
