#pragma once
/// @file
/// The parameter at a given arc length: t(s) with ∫_{t_min}^{t(s)} |r'(τ)| dτ = s, the inverse of
/// the arc-length function, for any Curve.
///
/// Method: the arc length of every piece (between consecutive breakpoints) by adaptive
/// Gauss–Kronrod to 1e-13 relative (as accurate_arc_length, curve_measures.hpp), cumulated; for a
/// query s, the piece holding it by binary search, then Newton's method on
/// f(t) = ∫_{t_k}^{t} |r'| − (s − S_k), f'(t) = |r'(t)|, safeguarded by bisection within the piece
/// (Boost.Math's newton_raphson_iterate), each f by 20-point Gauss–Legendre on [t_k, t]
/// (arc_length). Accuracy: |∫_{t_min}^{t(s)} |r'| − s| below about 1e-12 of the length.
/// Preconditions (InvalidInput): 0 ≤ s ≤ L (the curve's length; an s up to 1e-11 L beyond it, the
/// disagreement of two length computations, is L); a curve whose speed vanishes on
/// a whole piece still maps (that piece has length 0 and any of its parameters is returned).
#include <memory>
#include <vector>

#include "cagd/core/curve.hpp"

namespace cagd::analysis {

/// t(s) for one curve, with its pieces' lengths computed once (see above).
class ArcLengthParameter {
public:
    /// Measures `curve` (kept by shared ownership).
    explicit ArcLengthParameter(std::shared_ptr<const Curve> curve);
    /// The curve's length L.
    double length() const { return cumulative_.back(); }
    /// t(s) for 0 ≤ s ≤ L.
    double parameter_at(double s) const;

private:
    std::shared_ptr<const Curve> curve_;
    std::vector<double> breaks_, cumulative_;
};

}  // namespace cagd::analysis
