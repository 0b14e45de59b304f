#pragma once
/// @file
/// The space pseudo-energy that pseudo_energy section 6 proposes: the unit-chord cubic Hermite
/// segment in 3-D and the minimum of J = L²E over its tangent magnitudes (the extension to space that section 6 of
/// pseudo_energy proposes).
///
/// Geometry (our construction; the paper gives none). Rotating about the chord puts the start
/// tangent in the x–y plane, so three angles fix the directions:
///   P0 = (0, 0, 0), P1 = (1, 0, 0),
///   u0 = (cos θ0, sin θ0, 0),  u1 = (cos θ1, sin θ1 cos φ, sin θ1 sin φ),  θ0, θ1 ∈ [0, π], φ ∈ [0, 2π],
///   P'(0) = r0 u0, P'(1) = r1 u1, P(t) = b(t) P1 + c(t) r0 u0 + d(t) r1 u1 as eq (4)–(5).
/// θ0, θ1 are the angles of the tangents with the chord; φ is the dihedral angle between the planes
/// (chord, u0) and (chord, u1). φ = 0 is the planar segment (θ0, θ1) of hermite_segment.hpp, φ = π
/// the planar (θ0, −θ1): J, r0, r1, L agree with the planar ones (tested to 1e-12).
///   strain energy  E = ∫ κ² ds = ∫ |P' × P''|² / |P'|⁵ dt (space curvature)
///   length         L = ∫ |P'| dt,   pseudo-energy J = L² E,   minimised over r0, r1 > 0 as eq (8).
/// Symmetries (tested): reflection in the x–y plane (φ → 2π − φ), and reversal of the segment
/// (θ0, θ1, φ) → (θ1, θ0, φ) with r0 ↔ r1.
///
/// Types. In the plane eq (14) types a segment c (k(0)k(1) ≥ 0: it turns the same way at both ends)
/// or s (an inflection). In space the curvature has no sign; its direction does: with
/// w(t) = P'(t) × P''(t) (along the binormal), the segment is c when w(0)·w(1) ≥ 0 (its osculating
/// planes at the ends turn the same way round) and s otherwise. At φ = 0 and φ = π w is along z and
/// the rule is eq (14) exactly; in between it changes continuously with the geometry, so a table
/// can keep the paper's same-type interpolation.
///
/// Undefined directions: θ0, θ1 ∈ {0, π} (both tangents along the chord; φ then plays no part) —
/// the straight segment or a cusp, as the planar undefined nodes.
///
/// Paths. Fast: the planar fast path's quadrature (20-point Gauss–Legendre on pieces graded towards
/// near-cusps) and minimiser (log-r scan, Newton in log r). Reference: Romberg (rel 1e-13) and Ceres
/// nonlinear CG with a Newton polish, seeded by the scan and by the fast minimum — the planar
/// reference method (fairness/detail/pseudo_energy_descent.hpp holds the shared code).
/// Preconditions: finite angles in the ranges above (1e-12 of slack), r0, r1 finite and > 0;
/// InvalidInput names the value otherwise.
#include <Eigen/Dense>

#include "cagd/core/errors.hpp"
#include "cagd/fairness/hermite_segment.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"

namespace cagd::fairness {

/// The unit-chord cubic Hermite segment in 3-D (see above).
class SpaceUnitChordHermite {
public:
    /// The segment of angles θ0, θ1 ∈ [0, π], φ ∈ [0, 2π] and magnitudes r0, r1 > 0; InvalidInput otherwise.
    SpaceUnitChordHermite(double theta0, double theta1, double phi, double r0, double r1);

    /// θ0.
    double theta0() const { return theta0_; }
    /// θ1.
    double theta1() const { return theta1_; }
    /// φ.
    double phi() const { return phi_; }
    /// r0.
    double r0() const { return r0_; }
    /// r1.
    double r1() const { return r1_; }

    Eigen::Vector3d position(double t) const;         ///< P(t)
    Eigen::Vector3d first(double t) const;            ///< P'(t) = A + Bt + Ct²
    Eigen::Vector3d second(double t) const;           ///< P''(t) = B + 2Ct
    Eigen::Vector3d binormal_vector(double t) const;  ///< w(t) = P'(t) × P''(t)
    SegmentType type() const;                         ///< c when w(0)·w(1) ≥ 0, else s (see above)

    /// A of P'(t) = A + Bt + Ct².
    const Eigen::Vector3d& a() const { return a_; }
    /// B of P'(t) = A + Bt + Ct².
    const Eigen::Vector3d& b() const { return b_; }
    /// C of P'(t) = A + Bt + Ct².
    const Eigen::Vector3d& c() const { return c_; }
    /// The unit tangent u0 at t = 0.
    const Eigen::Vector3d& u0() const { return u0_; }
    /// The unit tangent u1 at t = 1.
    const Eigen::Vector3d& u1() const { return u1_; }

private:
    double theta0_, theta1_, phi_, r0_, r1_;
    Eigen::Vector3d u0_, u1_, a_, b_, c_;
};

/// E, L, J and ∂J/∂log r of the space segment: the reference (Romberg, rel_tol ≤ 1e-12) and fast
/// (Gauss–Legendre, 20 or 8 nodes) paths, as segment_energy_reference / segment_energy_fast.
SegmentEnergy space_segment_energy_reference(const SpaceUnitChordHermite& seg, double rel_tol = 1e-13,
                                             bool with_gradient = true);
/// The fast path (see above).
SegmentEnergy space_segment_energy_fast(const SpaceUnitChordHermite& seg, bool with_gradient = true,
                                        int rule_nodes = 20);

/// True for θ0, θ1 ∈ {0, π} (to 1e-12): no minimum exists (straight segment or cusp).
bool is_undefined_space_direction(double theta0, double theta1);

/// The minimum of J over r0, r1 > 0 at (θ0, θ1, φ), as PseudoEnergyMinimum in the plane.
struct SpacePseudoEnergyMinimum {
    double theta0 = 0.0;                ///< θ0
    double theta1 = 0.0;                ///< θ1
    double phi = 0.0;                   ///< φ
    double pseudo_energy = 0.0;         ///< J(θ0, θ1, φ)
    double r0 = 0.0;                    ///< r0 at the minimum
    double r1 = 0.0;                    ///< r1 at the minimum
    double length = 0.0;                ///< L at the minimum
    double strain_energy = 0.0;         ///< E at the minimum
    SegmentType type = SegmentType::x;  ///< c or s (see above); x where there is no minimum
    double gradient_norm = 0.0;         ///< |∇_ρ J| at the answer
    double error_estimate = 0.0;        ///< quadrature error bound on J (reference path)
    int local_minima = 0;               ///< distinct local minima the descents reached
    double runner_up = 0.0;             ///< second local minimum's J (+∞ if none)
    double runner_up_r0 = 0.0;          ///< its r0
    double runner_up_r1 = 0.0;          ///< its r1
    long evaluations = 0;               ///< energy evaluations (all starts)
    Outcome outcome;                    ///< no_solution at an undefined direction or a runaway; no_convergence
};

/// The fast minimiser (see above); outcome no_solution for an undefined direction.
SpacePseudoEnergyMinimum minimize_space_pseudo_energy(double theta0, double theta1, double phi,
                                                      const FastMinimizerOptions& opt = {});
/// The reference minimiser (see above).
SpacePseudoEnergyMinimum minimize_space_pseudo_energy_reference(double theta0, double theta1, double phi,
                                                                const ReferenceMinimizerOptions& opt = {});

}  // namespace cagd::fairness
