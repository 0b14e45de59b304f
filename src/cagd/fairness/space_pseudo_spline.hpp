#pragma once
/// @file
/// The space pseudo-spline (pseudo_energy section 6, extended to space): the cubic Hermite curve through points in 3-D
/// whose spans are minimum pseudo-energy space segments (space_pseudo_energy.hpp), the generalisation of pseudo_energy
/// section 3 (eq 9–13) that section 6 proposes.
///
/// Tangents (eq 11–12 in space). At an interior point P_i with chords c_{i−1} (in) and c_i (out),
/// the unit tangent T minimises w(T) = l_{i−1} J(∠(T, c_{i−1})) + l_i J(∠(T, c_i)) over the sphere,
/// J(θ) = min over the far end's direction of J. Two facts reduce this to the plane:
///  (a) J(θ) in space is the planar J(θ) of eq (11): the best far-end direction for a given near-end
///      angle lies in a plane through the chord (checked numerically in the tests: over φ the
///      segment energy is least at φ = 0 or π);
///  (b) J(θ) grows with θ ∈ [0, π], so for any T off the plane of c_{i−1} and c_i, its projection onto
///      that plane (normalised) makes both angles smaller (cos ∠(T, a) = T∥·a ≤ T∥·a / |T∥| for a in
///      the plane, when T∥·a > 0), hence w smaller: the minimiser lies in that plane.
/// So T is the planar tangent of the three points in their own plane: α ∈ [−τ, 0] from the outgoing
/// chord, τ the turn, by the least value of w (exact: every breakpoint of w where J(θ) is read from a table, Brent
/// otherwise), the paper's 3-point parabola (approx) or the direction of P_{i+1} − P_{i−1} (none) — pseudo_spline.hpp's
/// rules, applied in each point's plane. Collinear chords give T along them; a turn of π (hairpin) is refused as in the
/// plane. Ends (eq 13): the end tangent lies in the plane of the end chord and the neighbouring tangent, at the angle
/// θ1(θ) that eq (11) gives for that tangent's angle θ with the chord. Spans (eq 9–10): in span i's frame, θ0 = ∠(T_i,
/// c_i), θ1 = ∠(T_{i+1}, c_i) ∈ [0, π] and φ the dihedral angle about c_i from the plane (c_i, T_i) to (c_i, T_{i+1});
/// (r0, r1) from the space oracle; derivatives l_i r0 T_i and l_i r1 T_{i+1}. Points in a plane give the planar
/// pseudo-spline (φ = 0 or π, the planar J by symmetry; tested to 1e-9 with the exact oracles).
/// Length (eq 16–17): L = Σ l_i L_i. A space curve encloses no area; none is reported.
///
/// Accuracy on a helix (the claims of experiment space_pseudo_spline). Take the circular helix
/// H(t) = (cos t, sin t, b t) (radius 1), points P_i = H(ih), h = 2π/n for n points per turn.
///  - Congruence. The screw motion t → t + h maps the points onto themselves, so every interior span
///    has the same (θ0 = θ1, φ) and the same r0 = r1, L, J.
///  - The tangent. The half-turn about the principal normal at P_i swaps P_{i−1} and P_{i+1}; w is
///    symmetric under it and its minimiser (when unique) is the bisector of the equal chords,
///    P_{i+1} − P_{i−1} ∝ (−σ sin t_i, σ cos t_i, b), σ = sin h / h = 1 − h²/6 + …: the helix's
///    tangent (−sin t_i, cos t_i, b) with its horizontal part shrunk, leaning toward the axis by
///    O(h²) in the plane of the tangent and the binormal.
///  - Torsion. On the span t ∈ [−h/2, h/2] (unit parameter u) the end derivatives are
///    ρ(σ(−sin t±, cos t±), b) with ρ = h(1 + αh² + …), α anything (magnitudes right to relative
///    O(h²)). Against the Hermite cubic with the helix's own derivatives h(−sin t±, cos t±, b), whose
///    third derivative is h³(0, −1, 0) + O(h⁴), the third derivative 12(P0 − P1) + 6(T0 + T1) gains
///    6(δ0 + δ1) (δ the differences of the end derivatives)
///      = 6[(ρσ − h)·2cos(h/2)·(0, 1, 0) + 2(ρ − h)·(0, 0, b)] = h³[12α(0, 1, b) − 2(0, 1, 0)] + O(h⁵).
///    The part along the tangent (0, 1, b) does not enter det(P', P'', P'''); what is left is
///    −2h³(0, 1, 0) beside the helix's −h³(0, 1, 0). With P' = h(0, 1, b) and P'' = −h²(1, 0, 0) to
///    leading order, τ = det(P', P'', P''')/|P' × P''|² → 3b/(1 + b²) = 3τ_helix, uniformly along the
///    span, whatever α. Any cubic Hermite interpolant with tangents along P_{i+1} − P_{i−1} (Hermite A,
///    Catmull–Rom, and Hermite B on equal chords) shares the factor 3; a C² cubic spline, whose third derivative
///    converges to the helix's, does not.
///  - Curvature. The differences δ are O(h³): relative O(h²) against P' = O(h), but relative O(h)
///    against P'' = O(h²). That O(h) part of P'' is along the tangent (no effect on P' × P'') or along
///    the binormal (the remainder of (0, 1, 0) once its tangent part is taken out), and P' × (binormal)
///    lies along the normal, perpendicular to P' × P'' (along the binormal): |P' × P''| changes at
///    second order, so |κ/κ_helix − 1| = O(h²).
///  - Length. The displacement Δ from the helix's Hermite cubic is O(h³), but its normal part is
///    O(h⁴) (δ0 and δ1 differ by O(h⁴) along the normal). The first variation ∫ κ N·Δ ds and the
///    second order ∫ |Δ'|²/|P'| are both O(h⁵) on a span of length O(h); the helix's Hermite cubic
///    errs by as much: the relative length error is O(h⁴). The inscribed polygon's is O(N⁻²), so the
///    polygon as accurate as the spline (the equivalent points) has N growing as n².
#include <Eigen/Dense>
#include <vector>

#include "cagd/core/points.hpp"
#include "cagd/fairness/pseudo_spline.hpp"
#include "cagd/fairness/space_pseudo_energy_table.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace cagd::fairness {

/// Where a space pseudo-spline reads its segment values and J(θ).
class SpaceSegmentOracle {
public:
    virtual ~SpaceSegmentOracle() = default;
    /// J, r0, r1, L, type of the segment (θ0, θ1, φ), θ0, θ1 ∈ [0, π] not both in {0, π}.
    virtual SpaceTableValue segment(double theta0, double theta1, double phi) const = 0;
    /// The planar eq (11) source: J(θ) and θ1(θ) (see (a) above).
    virtual const SegmentOracle& planar() const = 0;
};

/// The fast minimiser at the exact angles; J(θ) from ExactOracle (0.15 s a value), or from a given
/// planar oracle (its tables: what `cagd interpolate --method pseudo-spline` does on 3-D points).
class ExactSpaceOracle : public SpaceSegmentOracle {
public:
    ExactSpaceOracle() = default;
    /// The fast minimiser at the exact angles, J(θ) from `planar` (which must outlive this oracle).
    explicit ExactSpaceOracle(const SegmentOracle& planar) : planar_ref_(&planar) {}
    SpaceTableValue segment(double theta0, double theta1, double phi) const override;
    const SegmentOracle& planar() const override { return planar_ref_ ? *planar_ref_ : exact_; }

private:
    ExactOracle exact_;
    const SegmentOracle* planar_ref_ = nullptr;
};

/// A 3-D table for the segments and a planar oracle (its tables) for J(θ). Keep both alive.
class TableSpaceOracle : public SpaceSegmentOracle {
public:
    /// Segments from the space table, J(θ) from `planar` (both must outlive this oracle).
    TableSpaceOracle(const SpacePseudoEnergyTable& table, const SegmentOracle& planar)
        : table_(table), planar_(planar) {}
    SpaceTableValue segment(double theta0, double theta1, double phi) const override {
        return table_.lookup(theta0, theta1, phi);
    }
    const SegmentOracle& planar() const override { return planar_; }

private:
    const SpacePseudoEnergyTable& table_;
    const SegmentOracle& planar_;
};

/// One span of a space pseudo-spline: its angles and the values it used.
struct SpacePseudoSplineSpan {
    double theta0 = 0.0;    ///< θ0
    double theta1 = 0.0;    ///< θ1
    double phi = 0.0;       ///< φ
    SpaceTableValue value;  ///< J, r0, r1, L, type used for the span
};

/// The space pseudo-spline through points and how it was built.
struct SpacePseudoSpline {
    spline::PiecewiseHermiteCurve curve;       ///< the curve, in Hermite form on unit spans
    std::vector<Eigen::Vector3d> tangent;      ///< unit tangent at every point
    std::vector<double> chord_length;          ///< l_i, one per span
    std::vector<SpacePseudoSplineSpan> spans;  ///< one per span
    double length_from_tables() const;         ///< eq (16), (17)
};

/// Points n × 3 (2 columns are taken as z = 0). Open: at least 2 points; closed: at least 3.
SpacePseudoSpline space_pseudo_spline(const PointList& points, const SpaceSegmentOracle& oracle,
                                      TangentOptimization mode, bool closed);

}  // namespace cagd::fairness
