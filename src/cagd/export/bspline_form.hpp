#pragma once
/// @file
/// Bézier pieces as one B-spline with the fewest knots that keep it exact (for DXF and STEP).
///
/// Pieces of degree p on a_0 < … < a_K join with some continuity: C^c at a_i (derivatives of
/// orders ≤ c agree). The B-spline on the clamped knot vector
///     a_0 (p + 1 times), a_1 (μ_1 times), …, a_{K−1} (μ_{K−1} times), a_K (p + 1 times),
/// with μ_i = p − c_i (1 ≤ μ_i ≤ p), contains the curve, and its control points are blossoms
/// (polar forms) of the pieces (de Boor; Ramshaw):
///     d_j = f_s(t_{j+1}, …, t_{j+p})   for every non-empty span s with j ≤ s ≤ j + p,
/// f_s the blossom of the piece on span s, evaluated by de Casteljau's algorithm with one argument
/// per level. Every such span gives the same d_j when the continuity holds, so the spread of the
/// values is the conversion error, measured, never assumed.
///
/// c_i is found by comparing the scaled differences of the control points at the join,
///     h_R^j/h_L^j ∇^j b_{L,p}  and  Δ^j b_{R,0},   j = 0, 1, …,
/// (equal exactly when r^(j) agrees), each to 2^j · tolerance. A knot whose control points then
/// spread by more than the tolerance gets μ_i = p (the two pieces share only their end point). The
/// tolerance is 1e-13 of the control points' bounding-box diagonal: the pieces come from one curve
/// whose continuity holds to rounding, and the tests hold the B-spline to 1e-12 of that diagonal.
///
/// Closed curves are clamped at their first point (the first and last control points coincide);
/// periodic_bspline() gives the unclamped periodic form (DXF writes it) where the curve is C^c
/// across that point too.
#include <vector>

#include "cagd/export/bezier_form.hpp"
#include "cagd/spline/bspline.hpp"

namespace cagd::exports {

/// A curve as one B-spline (see above).
struct BSplineForm {
    BSplineCurve curve;                        ///< clamped, on the pieces' parameter interval
    std::vector<int> interior_multiplicities;  ///< μ_1 … μ_{K−1}
    double conversion_error = 0.0;             ///< largest spread of a control point's blossoms
};

/// The B-spline of the pieces (see above); InvalidInput for pieces without a piece or with
/// non-increasing breaks.
BSplineForm to_bspline(const BezierPieces& pieces);

/// The first piece i ≥ 1 that does not start where piece i − 1 ends, 0 when every piece does: the
/// gap ‖b_{i,0} − b_{i−1,p}‖ exceeds 1e-12 of the control points' extent (the larger of their
/// bounding-box diagonal and their largest absolute coordinate). The pieces of one curve, computed
/// one by one, meet to rounding; a larger gap is a curve that jumps.
int first_unjoined_piece(const BezierPieces& pieces);

/// The pieces as a B-spline with every interior knot of multiplicity p (no conversion, exact):
/// the evaluator of a piecewise Bézier curve. InvalidInput for pieces that do not join
/// (first_unjoined_piece), naming the first.
BSplineCurve bezier_pieces_curve(const BezierPieces& pieces);

/// A closed curve's periodic form: degree p, n distinct control points d_0 … d_{n−1} and the
/// unclamped knots t_0 … t_{n+2p} of the B-spline on d_0 … d_{n−1}, d_0 … d_{p−1} (the first p
/// repeated at the end), domain [t_p, t_{n+p}], when the curve is C^c at its closing point with
/// 1 ≤ p − c (see above). Empty (no knots) when the curve is not continuous enough there.
struct PeriodicBSpline {
    int degree = 0;             ///< p
    std::vector<double> knots;  ///< t_0 … t_{n+2p}
    Eigen::MatrixXd control;    ///< the n distinct control points d_0 … d_{n−1}
};
/// The periodic form of a closed curve's clamped B-spline (first point = last point).
PeriodicBSpline periodic_bspline(const BezierPieces& pieces);

}  // namespace cagd::exports
