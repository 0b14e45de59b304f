#pragma once
// Every interpolating curve of the library behind one name, for `cagd compare`, the property
// tests and the fuzz targets: interpolate(name, points, closed) → the curve, the parameter of each
// data point on it, and what the method claims (continuity, invariance) so that a test can measure
// the claim instead of trusting it.
//
//   name                     source                                              claims
//   pseudo-spline-none       pseudo_energy eq (4)–(12), 36-node table, no eq (12)   G1
//   pseudo-spline-exact      … with the exact minimisation of eq (12)               G1
//   pseudo-spline-approx     … with the 3-point approximation (Table 4)             G1
//   cubic-a, cubic-b         C2 cubic spline, uniform / chord-length τ (sec 4.2)    C2 in τ
//   hermite-a, hermite-b     Hermite curves A and B (sec 4.2)                       G1
//   s-spline-m1, -m2, -m4    sb2_locality eq (12), locality m, natural ends         C2 in u
//   b2-spline-m1, -m2, -m4   the same, B2 form                                      C2 in u
//   hosaka-c2-chord          hosaka eq (18)–(20), k_i = |A_i|/|A_i+1| (eq 19)       C2 in τ, dτ = |A_i| dt
//   hosaka-c2-unit           hosaka eq (20) with k_i = 1                            C2 in u
//   curvature-profile        curvature_profile sec 2–4: every span free (ψ          C2 in arc length (G2)
//                            quadratic, κ linear: a clothoid spline), κ = 0 at open ends
//   boost-pchip, boost-makima   Boost.Math pchip / makima on x(τ), y(τ), τ chord    C1 in τ (tangent may vanish)
//   boost-catmull-rom        Boost.Math centripetal Catmull–Rom (α = 1/2)           C1 in τ = Σ|ΔP|^½
//
// "C^k in τ": the derivatives of orders ≤ k with respect to the method's own parameter τ agree
// at every interior data point; on span k (between data points k and k + 1) τ is an affine
// function of the curve's parameter u with dτ/du = dtau_du[k], so d/dτ = (1/dtau_du[k]) d/du. "G^k": the unit tangent (k ≥ 1) and curvature vector (k = 2)
// agree. Invariance: every method commutes with translations, rotations and uniform scalings
// (similarity) except Boost's pchip and makima, which act on x and y separately (translation and
// scaling only), and the pseudo-spline with exact tangent optimisation: Brent's minimiser stops at
// a relative tolerance of 2^−26 (Boost's limit, half the digits: a smooth minimum cannot be located
// closer in double precision), so rounding-level changes of w under a similarity move α_i within that tolerance and
// the curve by up to ~2e-8 of the data diagonal (measured; test_compare bounds it by 1e-7). The
// approximate mode is invariant up to rounding since its non-convex case is decided against
// rounding (fairness/pseudo_spline.hpp); before that it moved by up to 3.5e-3 of the diagonal.
// Methods linear in the points with a fixed parameter (cubic-a, the S-/B2-splines,
// hosaka-c2-unit) also commute with every affine map.
//
// Boost's interpolants are converted, exactly, into our piecewise cubic Hermite form (values and
// τ-derivatives at the nodes, times the span's τ-length), so one evaluator serves every curve.
//
// Preconditions (InvalidInput naming the point): finite coordinates; at least min_points (open) or
// min_points_closed; no two consecutive points equal (closed: also last and first); dimension
// 2 (or 3 where `max_dimension` allows). A method that does not support closed curves throws when
// asked for one. Outcomes: the curvature-profile Newton can fail for valid points (returned, not
// thrown); every other method always returns a curve.
#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/curve.hpp"
#include "core/errors.hpp"
#include "core/points.hpp"

namespace cagd::compare {

enum class Invariance { none, translation_scale, similarity, affine };
const char* to_string(Invariance i);

struct MethodInfo {
    std::string name;
    std::string source;             // paper id and equations, or the Boost.Math class
    int parametric_continuity;      // k of "C^k in τ" (0: not claimed)
    int geometric_continuity;       // k of "G^k" (0: not claimed)
    std::string parameter;          // what τ is
    Invariance invariance;
    bool supports_closed;
    int min_points, min_points_closed;
    int max_dimension;              // 2 or 3
};

// Every method, in the order of the tables.
const std::vector<MethodInfo>& interpolation_methods();
// Throws InvalidInput listing the known names.
const MethodInfo& method_info(const std::string& name);

struct Interpolant {
    std::shared_ptr<const Curve> curve;
    std::vector<double> node_parameters;   // u of each data point (closed: n + 1 values, the last = t_max)
    std::vector<double> dtau_du;           // one per span (see above)
};

struct InterpolationResult {
    Outcome outcome;
    std::optional<Interpolant> interpolant;   // present when outcome.ok()
};

InterpolationResult interpolate(const std::string& method, const PointList& points, bool closed);

}  // namespace cagd::compare
