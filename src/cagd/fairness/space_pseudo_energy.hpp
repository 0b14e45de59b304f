#pragma once
// The space pseudo-energy that pseudo_energy section 6 proposes: the unit-chord cubic Hermite
// segment in 3-D and the minimum of J = L²E over its tangent magnitudes (the extension to space that section 6 of pseudo_energy proposes).
//
// Geometry (our construction; the paper gives none). Rotating about the chord puts the start
// tangent in the x–y plane, so three angles fix the directions:
//   P0 = (0, 0, 0), P1 = (1, 0, 0),
//   u0 = (cos θ0, sin θ0, 0),  u1 = (cos θ1, sin θ1 cos φ, sin θ1 sin φ),  θ0, θ1 ∈ [0, π], φ ∈ [0, 2π],
//   P'(0) = r0 u0, P'(1) = r1 u1, P(t) = b(t) P1 + c(t) r0 u0 + d(t) r1 u1 as eq (4)–(5).
// θ0, θ1 are the angles of the tangents with the chord; φ is the dihedral angle between the planes
// (chord, u0) and (chord, u1). φ = 0 is the planar segment (θ0, θ1) of hermite_segment.hpp, φ = π
// the planar (θ0, −θ1): J, r0, r1, L agree with the planar ones (tested to 1e-12).
//   strain energy  E = ∫ κ² ds = ∫ |P' × P''|² / |P'|⁵ dt (space curvature)
//   length         L = ∫ |P'| dt,   pseudo-energy J = L² E,   minimised over r0, r1 > 0 as eq (8).
// Symmetries (tested): reflection in the x–y plane (φ → 2π − φ), and reversal of the segment
// (θ0, θ1, φ) → (θ1, θ0, φ) with r0 ↔ r1.
//
// Types. In the plane eq (14) types a segment c (k(0)k(1) ≥ 0: it turns the same way at both ends)
// or s (an inflection). In space the curvature has no sign; its direction does: with
// w(t) = P'(t) × P''(t) (along the binormal), the segment is c when w(0)·w(1) ≥ 0 (its osculating
// planes at the ends turn the same way round) and s otherwise. At φ = 0 and φ = π w is along z and
// the rule is eq (14) exactly; in between it changes continuously with the geometry, so a table
// can keep the paper's same-type interpolation.
//
// Undefined directions: θ0, θ1 ∈ {0, π} (both tangents along the chord; φ then plays no part) —
// the straight segment or a cusp, as the planar undefined nodes.
//
// Paths. Fast: the planar fast path's quadrature (20-point Gauss–Legendre on pieces graded towards
// near-cusps) and minimiser (log-r scan, Newton in log r). Reference: Romberg (rel 1e-13) and Ceres
// nonlinear CG with a Newton polish, seeded by the scan and by the fast minimum — the planar
// reference method (fairness/detail/pseudo_energy_descent.hpp holds the shared code).
// Preconditions: finite angles in the ranges above (1e-12 of slack), r0, r1 finite and > 0;
// InvalidInput names the value otherwise.
#include <Eigen/Dense>

#include "cagd/core/errors.hpp"
#include "cagd/fairness/hermite_segment.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"

namespace cagd::fairness {

class SpaceUnitChordHermite {
public:
    SpaceUnitChordHermite(double theta0, double theta1, double phi, double r0, double r1);

    double theta0() const { return theta0_; }
    double theta1() const { return theta1_; }
    double phi() const { return phi_; }
    double r0() const { return r0_; }
    double r1() const { return r1_; }

    Eigen::Vector3d position(double t) const;         // P(t)
    Eigen::Vector3d first(double t) const;            // P'(t) = A + Bt + Ct²
    Eigen::Vector3d second(double t) const;           // P''(t) = B + 2Ct
    Eigen::Vector3d binormal_vector(double t) const;  // w(t) = P'(t) × P''(t)
    SegmentType type() const;                         // c when w(0)·w(1) ≥ 0, else s (see above)

    const Eigen::Vector3d& a() const { return a_; }
    const Eigen::Vector3d& b() const { return b_; }
    const Eigen::Vector3d& c() const { return c_; }
    const Eigen::Vector3d& u0() const { return u0_; }
    const Eigen::Vector3d& u1() const { return u1_; }

private:
    double theta0_, theta1_, phi_, r0_, r1_;
    Eigen::Vector3d u0_, u1_, a_, b_, c_;
};

// E, L, J and ∂J/∂log r of the space segment: the reference (Romberg, rel_tol ≤ 1e-12) and fast
// (Gauss–Legendre, 20 or 8 nodes) paths, as segment_energy_reference / segment_energy_fast.
SegmentEnergy space_segment_energy_reference(const SpaceUnitChordHermite& seg, double rel_tol = 1e-13, bool with_gradient = true);
SegmentEnergy space_segment_energy_fast(const SpaceUnitChordHermite& seg, bool with_gradient = true, int rule_nodes = 20);

// True for θ0, θ1 ∈ {0, π} (to 1e-12): no minimum exists (straight segment or cusp).
bool is_undefined_space_direction(double theta0, double theta1);

struct SpacePseudoEnergyMinimum {
    double theta0 = 0.0, theta1 = 0.0, phi = 0.0;
    double pseudo_energy = 0.0;  // J(θ0, θ1, φ)
    double r0 = 0.0, r1 = 0.0;
    double length = 0.0, strain_energy = 0.0;
    SegmentType type = SegmentType::x;
    double gradient_norm = 0.0, error_estimate = 0.0;
    int local_minima = 0;
    double runner_up = 0.0, runner_up_r0 = 0.0, runner_up_r1 = 0.0;  // second local minimum (+∞ if none)
    long evaluations = 0;
    Outcome outcome;  // no_solution at an undefined direction or a runaway; no_convergence
};

SpacePseudoEnergyMinimum minimize_space_pseudo_energy(double theta0, double theta1, double phi, const FastMinimizerOptions& opt = {});
SpacePseudoEnergyMinimum minimize_space_pseudo_energy_reference(double theta0, double theta1, double phi, const ReferenceMinimizerOptions& opt = {});

}  // namespace cagd::fairness
