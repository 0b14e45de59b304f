#pragma once
/// @file
/// Curves with a known answer, for the interpolant benchmark (compare/truth_benchmark.hpp): points
/// are sampled from them, every method interpolates the points, and its curve is measured against
/// the curve the points came from.
///
///   family         curve (parameter t)                                        t range     closed
///   line           (t, t/2)                                                   [0, 4]      no
///   circle         (cos t, sin t)                                             [0, 2π]     yes
///   ellipse        (2 cos t, sin t)                                           [0, 2π]     yes
///   epitrochoid    ((R+r) cos t − d cos((R+r)t/r), (R+r) sin t − d sin((R+r)t/r)),
///                  R = 3, r = 1, d = 1/2 (a three-lobed rose, no self-intersection)  [0, 2π]  yes
///   clothoid       r(s) = ∫_0^s (cos σ²/2, sin σ²/2) dσ, s arc length        [0, 2.5]    no
///   log-aesthetic  ρ^α = c0 s + c1 with α = 2, c0 = c1 = 1 (typical_curves eq 8: κ = (1 + s)^(−1/2),
///                  turning 2(√5 − 1) rad), s arc length                       [0, 4]      no
///   helix          (cos t, sin t, t/4)                                        [0, 3π]     no
///   trefoil        (sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t)               [0, 2π]     yes
///
/// Jets are analytic (order ≤ 3); the clothoid is the tangent-angle spline ψ(s) = s²/2 of
/// intrinsic/ (its position integrals exact to rounding) and the log-aesthetic curve is
/// aesthetic/'s. Arc length, curvature and torsion come from analysis/, as for every curve.
///
/// Sampling (truth_samples): n points at arc lengths s_i = L g(i/N) (open: i = 0..n−1, N = n − 1;
/// closed: i = 0..n−1, N = n), with g(u) = u (uniform in arc length) or
/// g(u) = u − 0.6 sin(2πu)/(2π) (non-uniform: spacing varying fourfold, g' ∈ [0.4, 1.6]); t(s) by
/// analysis/arc_length_parameter. Preconditions (InvalidInput): n ≥ 3 (closed families sampled open
/// take an arc of 3/4 of the curve), a known family name.
#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/core/points.hpp"

namespace cagd::compare {

/// A family of curves with a truth.
struct TruthFamily {
    std::string name;                    ///< "circle", "ellipse", …
    std::string description;             ///< the curve in words and formulae
    int dimension = 2;                   ///< 2 or 3
    bool closed = false;                 ///< a closed curve (sampled closed, or as an open arc of 3/4 of it)
    std::shared_ptr<const Curve> curve;  ///< the curve itself
};
/// Every family, in the order of the header's table.
const std::vector<TruthFamily>& truth_families();
/// The family of this name; InvalidInput naming the known ones if there is none.
const TruthFamily& find_truth_family(const std::string& name);

/// Where the points are placed along the curve.
enum class TruthSpacing { uniform, nonuniform };
/// "uniform" or "nonuniform".
const char* to_string(TruthSpacing spacing);

/// Points on a truth curve and the curve's parameter at each.
struct TruthSample {
    PointList points;            ///< n rows
    std::vector<double> params;  ///< the truth curve's t at each point (closed: n + 1, the last = t_max)
    double t_first = 0.0;        ///< where the stretch of the truth the interpolant should follow starts
    double t_last = 0.0;         ///< where it ends
    double length = 0.0;         ///< its arc length
    bool closed = false;         ///< the points are a closed curve's
};
/// n points on `family`'s curve (closed when `closed` and the family is closed; else an open arc).
TruthSample truth_samples(const TruthFamily& family, int n, TruthSpacing spacing, bool closed);

}  // namespace cagd::compare
