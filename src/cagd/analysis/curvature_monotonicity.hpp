#pragma once
/// @file
/// Exact-up-to-rounding sign of curvature and torsion derivatives of a Bézier curve, as
/// polynomials in Bernstein form (typical_curves appendix A.1, eq 38–40, for any degree).
///
/// Planar, signed curvature κ = f/g^{3/2} with f = x'y'' − y'x'' (degree 2n−3 or less), g = |r'|²:
///   dκ/dt = (f'g − (3/2) f g') / g^{5/2},   h = f'g − (3/2) f g'               (eq 39–40 corrected:
/// the paper prints 2/3 and f^{3/2}; see ERRATA typical_curves-E6).
/// Any dimension, unsigned curvature: d(κ²)/dt = (q'g − 3 q g')/g⁴ with q = |r' × r''|².
/// Space curves, torsion τ = d/q with d = det(r', r'', r'''): dτ/dt = (d'q − d q')/q².
/// The numerators are products of the hodographs' Bernstein polynomials (no rounding beyond the
/// products themselves); their sign on [0, 1] is decided by core/sign_on_unit_interval.
/// Preconditions: degree ≥ 2 (≥ 3 for torsion), dimension 2 (signed) / 2–3 / 3 (InvalidInput).
#include "cagd/core/bernstein_polynomial.hpp"
#include "cagd/spline/bezier.hpp"

namespace cagd::analysis {

/// f = x'y'' − y'x'' (degree 2n − 4) and g = |r'|² (degree 2n − 2) of a planar Bézier curve.
struct PlanarCurvatureParts {
    BernsteinPolynomial f;  ///< f = x'y'' − y'x''
    BernsteinPolynomial g;  ///< g = |r'|²
};
/// f and g of a planar Bézier curve, in Bernstein form.
PlanarCurvatureParts planar_curvature_parts(const BezierCurve& c);
BernsteinPolynomial curvature_derivative_numerator(const BezierCurve& c);          ///< h (planar)
BernsteinPolynomial squared_curvature_derivative_numerator(const BezierCurve& c);  ///< q'g − 3qg'
BernsteinPolynomial torsion_derivative_numerator(const BezierCurve& c);            ///< d'q − dq'

/// Sign of the derivative in the curve's own parameter direction, as a monotonicity verdict.
enum class Trend { increasing, decreasing, constant, not_monotone, undetermined };
/// The name of a trend ("increasing", …).
const char* to_string(Trend t);
/// Strict: positive/negative numerator; non-strict (touching zero) counts as monotone.
Trend trend_of(const SignAnalysis& s);

}  // namespace cagd::analysis
