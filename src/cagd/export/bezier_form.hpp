#pragma once
/// @file
/// A curve as Bézier pieces: exact for polynomial curves, a verified approximation otherwise.
/// (Namespace cagd::exports: `export` is a C++ keyword.)
///
/// Exact form. A curve whose pieces are polynomials of degree ≤ p (Curve::polynomial_degree) is,
/// on each piece [a, b] (s = (t − a)/(b − a)), r(t) = Σ_{k=0}^{p} B_{k,p}(s) b_k, and the control
/// points follow from its one-sided derivatives at the two ends (spline/bezier.hpp,
/// bezier_from_end_jets; r^(j)(b⁻) from Curve::jet_from_left): the form agrees with the curve to
/// rounding (the tests hold it to 1e-12 of the curve's scale, with derivatives at the joins).
///
/// Approximation. A curve that is not polynomial (the curvature-profile spline, log-aesthetic
/// curves) is approximated piece by piece by the Hermite interpolant of its jets at the piece's ends:
/// degree 3 matches position and first derivative (C1 joins, error O(h⁴)), degree 5 also the second
/// derivative (C2 joins, so curvature is continuous and exact at every join; error O(h⁶)). A piece
/// is accepted when its error bound is at most the tolerance, else it is halved; the curve's own
/// breakpoints are always joins. The bound of a piece: with e(t) = r(t) − b(t) sampled at N = 32
/// equally spaced interior parameters (spacing δ),
///     max |e| ≤ max_j |e(t_j)| + δ²/8 · 2 max_j |e''(t_j)|,
/// the error of linear interpolation between samples, with the sampled |e''| doubled for the
/// variation of e'' between samples (an estimate, not a proof: a feature narrower than δ could
/// escape it). |e| is the distance at the same parameter, which bounds the distance between the
/// two curves. Tolerance: relative × the bounding-box diagonal of the curve (default 1e-6).
///
/// Outcome: no_convergence when the tolerance is not met within max_pieces pieces or at a piece
/// shorter than 1e-12 of the parameter range (a cusp, an infinite curvature).
#include <Eigen/Dense>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/spline/bezier.hpp"

namespace cagd::exports {

/// Piecewise Bézier form: piece i on [breaks[i], breaks[i+1]] has control points
/// control.middleRows(i (degree + 1), degree + 1).
struct BezierPieces {
    int degree = 0;              ///< p, the same for every piece
    std::vector<double> breaks;  ///< a_0 < a_1 < … < a_K, the pieces' parameter intervals
    Eigen::MatrixXd control;     ///< K (p + 1) rows, one control point each, dimension columns
    /// K.
    int pieces() const { return static_cast<int>(breaks.size()) - 1; }
    /// 2 or 3.
    int dimension() const { return static_cast<int>(control.cols()); }
    /// Piece i's p + 1 control points.
    Eigen::MatrixXd piece(int i) const {
        return control.middleRows(static_cast<Eigen::Index>(i) * (degree + 1), degree + 1);
    }
};

/// What to_bezier gives: the pieces, and how far they may be from the curve.
struct BezierForm {
    Outcome outcome;      ///< ok, or no_convergence (approximations only; see above)
    BezierPieces pieces;  ///< the Bézier pieces, in the curve's own parameter
    bool exact = false;   ///< the curve's own polynomial pieces (rounding only)
    /// 0 when exact; else the largest error bound of the pieces (see above), ≤ tolerance when ok.
    double max_distance = 0.0;
    double tolerance = 0.0;  ///< the absolute tolerance asked for (0 when exact)
};

/// How a curve that is not polynomial of a wanted degree is approximated.
struct ApproximationOptions {
    int degree = 3;  ///< 3 (C1 Hermite pieces) or 5 (C2 Hermite pieces)
    /// Largest distance, as a fraction of the curve's bounding-box diagonal; 1e-14 ≤ relative ≤ 0.1.
    double relative_tolerance = 1e-6;
    int max_pieces = 1'000'000;  ///< the approximation stops (no_convergence) beyond this many pieces
};

/// The curve's exact Bézier pieces when it is polynomial (degree = Curve::polynomial_degree),
/// else its approximation (see above). InvalidInput for options outside their ranges.
BezierForm to_bezier(const Curve& curve, const ApproximationOptions& options = {});
/// The same with every piece of degree exactly `degree` (1 ≤ degree ≤ 5): an exact form of lower
/// degree is raised (exactly); one of higher degree, or a curve that is not polynomial, is
/// approximated by Hermite pieces of this degree (3 or 5; the degree reduction of SVG's cubics).
BezierForm to_bezier_of_degree(const Curve& curve, int degree, const ApproximationOptions& options = {});

/// The exact pieces of a polynomial curve; InvalidInput when polynomial_degree() < 0.
BezierPieces exact_bezier_pieces(const Curve& curve);
/// The same pieces raised to degree q ≥ p (each raise: b'_i = i/(p+1) b_{i−1} + (1 − i/(p+1)) b_i).
BezierPieces elevate_degree(const BezierPieces& pieces, int degree);
/// Piece i as a BezierCurve on its interval (the evaluator of BezierPieces).
BezierCurve piece_curve(const BezierPieces& pieces, int i);
/// Piecewise polynomials in the local power basis, as scipy.interpolate.PPoly holds them: piece i
/// on [x_i, x_{i+1}] is Σ_k coefficients[i](k, ·) (t − x_i)^(p − k), highest power first.
struct PowerPieces {
    int degree = 0;                             ///< p
    std::vector<double> breaks;                 ///< x_0 < … < x_K
    std::vector<Eigen::MatrixXd> coefficients;  ///< K matrices of p + 1 rows (highest power first) × dimension
};
/// The same pieces in Bézier form (exact conversion: with h = x_{i+1} − x_i, the monomial
/// coefficients of s = (t − x_i)/h are a_j h^j, then bernstein_from_monomial). InvalidInput for
/// breaks that do not increase, a piece count that differs from the breaks', or non-finite values.
BezierPieces bezier_pieces_from_power(const PowerPieces& power);
/// Bézier pieces in the local power basis (monomial_from_bernstein, then a_j / h^j).
PowerPieces power_pieces(const BezierPieces& pieces);

/// The bounding-box diagonal of the curve, from 33 samples per piece (the scale of the tolerances).
double sampled_diagonal(const Curve& curve);

}  // namespace cagd::exports
