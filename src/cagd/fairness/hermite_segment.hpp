#pragma once
/// @file
/// The unit-chord cubic Hermite segment and its pseudo-energy (pseudo_energy, section 2,
/// eq 1–7, 14–15; section 5 for L and S).
///
///   P0 = (0, 0), P1 = (1, 0),  P'0 = r0 (cos θ0, sin θ0),  P'1 = r1 (cos θ1, sin θ1)   (1)–(3)
///   P(t) = b(t) P1 + c(t) P'0 + d(t) P'1,  b = −2t³+3t², c = t³−2t²+t, d = t³−t²,  t ∈ [0,1] (4)–(5)
///   strain energy  E = ∫ k(t)² / |P'(t)|⁵ dt,  k(t) = x''y' − x'y''   (6), (15)
///   length         L = ∫ |P'(t)| dt
///   pseudo-energy  J = L² E                                            (7)
///   signed area    S = ∫ y dx = ∫ y(t) x'(t) dt (area below the chord counts negative, §5.2)
///   type           c if k(0)k(1) ≥ 0, s if k(0)k(1) < 0 (14); x where no value exists.
/// Symbols ↔ names: θ0, θ1 = theta0, theta1; r0, r1 = r0, r1; k(t) = curvature_numerator(t).
/// J, E and L·(1/L) are invariant under scaling, so J is a property of the shape only.
///
/// Domain: θ0, θ1 ∈ [−π, π] (3) — angles outside are rejected, not wrapped (a value in
/// degrees passed by mistake must not pass silently; callers wrap with `wrap_angle`). A
/// slack of 1e-12 admits ±π computed in floating point. r0, r1 > 0 and finite.
///
/// Cusps. P'(t) = A + Bt + Ct² may vanish inside [0, 1]; there k ~ (t−t*)² and |P'| ~ |t−t*|,
/// so the integrand of E behaves like 1/|t−t*| and E = ∞. A near-cusp gives a peak of width
/// δ = |P'(t*)|/|P''(t*)| that a fixed quadrature rule steps over, reporting a false, low E.
/// Both integrators therefore split [0,1] at every local minimum t* of |P'| and grade the
/// pieces geometrically (t* ± δ·2^j), so each piece is smooth on its own scale — likewise towards
/// an end whose tangent is short (δ = r_i / |P''| at t = 0 or 1); an exact cusp
/// (|P'(t*)| ≤ 1e-13·(1 + r0 + r1)) is reported as `cusp` with E = J = +∞ — the integral
/// diverges — never as a finite number.
///
/// Accuracy: reference path (Romberg on every piece, rel 1e-13) with its summed error estimate;
/// fast path (20-point Gauss–Legendre on the same pieces) agrees with it to ~1e-14 relative on
/// smooth segments (tests and the pseudo_energy experiments measure this).
#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/spline/bezier.hpp"

namespace cagd::fairness {

/// The segment type of eq (14): c (curvature of one sign at both ends), s (an inflection) or x (no value).
enum class SegmentType { c, s, x };
/// "c", "s" or "x".
const char* to_string(SegmentType t);

/// Maps any finite angle to (−π, π] (exact 2π periodicity of the tangent direction). Inline: an
/// angle already in range (the common case, on the hot path of eq 12) returns at once; the rest is
/// wrap_angle_out_of_range.
double wrap_angle_out_of_range(double theta);
/// θ wrapped to (−π, π] (θ ± 2πk).
inline double wrap_angle(double theta) {
    return theta > -std::numbers::pi && theta <= std::numbers::pi ? theta : wrap_angle_out_of_range(theta);
}

/// The tangent-angle domain of this module, [−π, π] with a slack of 1e-12 (see above): throws
/// InvalidInput("<who>: <name> must be …") for a non-finite angle or one outside it.
/// Inline: the check is on the hot path of every table lookup; the message is built only on failure.
[[noreturn]] void fail_tangent_angle(const char* who, double theta, const char* name);
/// InvalidInput naming `who` and `name` unless θ is finite and in [−π, π] (slack 1e-12).
inline void require_tangent_angle(const char* who, double theta, const char* name) {
    if (!(std::abs(theta) <= std::numbers::pi + 1e-12)) fail_tangent_angle(who, theta, name);  // also catches NaN
}

/// The unit-chord cubic Hermite segment of eq (1)–(5).
class UnitChordHermite {
public:
    /// Throws InvalidInput for non-finite values, |θ| > π (+1e-12), r ≤ 0.
    UnitChordHermite(double theta0, double theta1, double r0, double r1);

    /// θ0.
    double theta0() const { return theta0_; }
    /// θ1.
    double theta1() const { return theta1_; }
    /// r0.
    double r0() const { return r0_; }
    /// r1.
    double r1() const { return r1_; }

    Eigen::Vector2d position(double t) const;    ///< P(t)
    Eigen::Vector2d first(double t) const;       ///< P'(t) = A + Bt + Ct²
    Eigen::Vector2d second(double t) const;      ///< P''(t) = B + 2Ct
    double curvature_numerator(double t) const;  ///< k(t) of eq (15), a quadratic in t
    SegmentType type() const;                    ///< eq (14) from k(0)k(1)
    BezierCurve bezier() const;                  ///< the same cubic through the Curve interface

    /// Power-form coefficients of P'(t) = A + B t + C t².
    const Eigen::Vector2d& a() const { return a_; }
    /// B.
    const Eigen::Vector2d& b() const { return b_; }
    /// C.
    const Eigen::Vector2d& c() const { return c_; }
    /// ∂P'/∂r_i = dc_i(t) u_i with u_i the unit tangent; derivative coefficients for the gradient.
    const Eigen::Vector2d& u0() const { return u0_; }
    /// The unit tangent at t = 1.
    const Eigen::Vector2d& u1() const { return u1_; }

private:
    double theta0_, theta1_, r0_, r1_;
    Eigen::Vector2d u0_, u1_, a_, b_, c_;
};

/// The local minima of |P'(t)| inside (0, 1), ascending, with |P'| there.
struct SpeedMinimum {
    double t = 0.0;      ///< t* ∈ (0, 1)
    double speed = 0.0;  ///< |P'(t*)|
    double width = 0.0;  ///< δ = |P'(t*)| / |P''(t*)|
};
/// The local minima of |P'| inside (0, 1), ascending.
std::vector<SpeedMinimum> speed_minima(const UnitChordHermite& seg);

/// True when P' vanishes in [0, 1] (to 1e-13·(1 + r0 + r1)).
bool has_cusp(const UnitChordHermite& seg);

/// Breakpoints 0 = b_0 < … < b_K = 1 graded towards every near-cusp (see above).
std::vector<double> integration_breaks(const UnitChordHermite& seg);

/// E, L, J of a segment, with the gradient and error estimate of the path that computed them.
struct SegmentEnergy {
    double strain_energy = 0.0;  ///< E (6)
    double length = 0.0;         ///< L
    double pseudo_energy = 0.0;  ///< J = L² E (7)
    /// Gradient of J with respect to log r0, log r1 (the minimisers' variables).
    double dj_dlog_r0 = 0.0;      ///< ∂J/∂ log r0
    double dj_dlog_r1 = 0.0;      ///< ∂J/∂ log r1
    double error_estimate = 0.0;  ///< bound on |ΔJ| from the quadrature (reference path)
    long evaluations = 0;         ///< integrand evaluations
    bool cusp = false;            ///< E = J = +∞
    Outcome outcome;              ///< no_convergence if Romberg did not converge
};

/// Reference path: Romberg on every piece of integration_breaks, rel_tol (≤ 1e-12) per integral.
SegmentEnergy segment_energy_reference(const UnitChordHermite& seg, double rel_tol = 1e-13, bool with_gradient = true);
/// Fast path: 20-point Gauss–Legendre on the same pieces. `rule_nodes` ∈ {8, 20}: 8 is a cheap
/// estimate (~1e-6 relative) for scans that only seed a minimiser.
SegmentEnergy segment_energy_fast(const UnitChordHermite& seg, bool with_gradient = true, int rule_nodes = 20);

/// S = ∫ y dx, exact (the integrand is a polynomial of degree 5).
double signed_area(const UnitChordHermite& seg);

/// High-precision spot values (Boost.Multiprecision, 50 decimal digits; Gauss–Kronrod 61 on the
/// same graded pieces to 1e-40): an independent check of both double paths. θ and r are taken as
/// the exact binary values given; cos and sin are evaluated in 50 digits. Slow (~0.1 s).
/// E, L and J of one segment to 40 significant digits, and the same rounded to double.
struct SegmentEnergyDigits {
    std::string strain_energy;       ///< E, 40 digits
    std::string length;              ///< L, 40 digits
    std::string pseudo_energy;       ///< J, 40 digits
    double strain_energy_value = 0;  ///< E rounded
    double length_value = 0;         ///< L rounded
    double pseudo_energy_value = 0;  ///< J rounded
};
/// E, L and J of the segment (θ0, θ1, r0, r1) to 40 digits (see above).
SegmentEnergyDigits segment_energy_high_precision(double theta0, double theta1, double r0, double r1);

}  // namespace cagd::fairness
