#pragma once
/// @file
/// The plane curve of a tangent-angle spline (curvature_profile eq 1):
///   r(s) = r_0 + ∫_0^s (cos ψ(σ), sin ψ(σ)) dσ,  0 ≤ s ≤ L,
/// parametrised by arc length. The breakpoint positions r(w_g) are accumulated segment by segment
/// with direction_integrals (eq 3's integrals); r(s) inside a segment adds the partial integral.
/// Jets (order ≤ 4) with e = (cos ψ, sin ψ), n = (−sin ψ, cos ψ):
///   r' = e, r'' = ψ' n, r''' = ψ'' n − ψ'² e, r'''' = (ψ''' − ψ'³) n − 3ψ'ψ'' e.
/// Preconditions (InvalidInput): start finite; 0 ≤ s ≤ L; 0 ≤ order ≤ 4.
#include <Eigen/Dense>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/intrinsic/tangent_angle_spline.hpp"

namespace cagd::intrinsic {

/// The plane curve r(s) = start + ∫_0^s (cos ψ, sin ψ) ds of a tangent-angle spline, in arc length.
class IntrinsicCurve : public Curve {
public:
    /// The curve starting at `start` with tangent angle ψ (positions at the breakpoints integrated once).
    IntrinsicCurve(Eigen::Vector2d start, TangentAngleSpline psi);

    /// ψ.
    const TangentAngleSpline& tangent_angle() const { return psi_; }
    /// (k + 1) × 2: r(w_0), …, r(w_k).
    const Eigen::MatrixXd& breakpoint_points() const { return points_; }
    /// The length L.
    double length() const { return psi_.length(); }

    int dimension() const override { return 2; }
    double t_min() const override { return 0.0; }
    double t_max() const override { return psi_.length(); }
    /// Rows r', r'', … from ψ alone (e = (cos ψ, sin ψ), n = e rotated by π/2; r' = e, r'' = ψ' n, …);
    /// the position, a quadrature, only where first = 0. Orders up to 4.
    void evaluate_jet(double s, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const override;
    std::vector<double> breakpoints() const override { return psi_.breakpoints(); }

    /// An upper bound on the distance between this curve and `other` at the same fraction τ of
    /// their segment j, |r(w_j + τ d_j) − r'(w'_j + τ d'_j)| over τ ∈ [0, 1], as jet_into computes
    /// them, without evaluating a position:
    ///   |r_j − r'_j| + |d_j − d'_j| + min(d_j, d'_j) · max_r |b_{j,r} − b'_{j,r}|,
    /// since |e^{iα} − e^{iβ}| ≤ |α − β| and ψ_j − ψ'_j, a Bernstein polynomial in τ with the
    /// differences b_{j,r} − b'_{j,r} as ordinates, is at most their largest magnitude (the
    /// quadrature's weights are positive: the computed integrals obey the same bound); enlarged by
    /// 1e-13 of the magnitudes involved (positions, lengths, lengths times ψ's ordinates) for the
    /// positions' rounding and quadrature error. It lets a comparison skip segments that cannot
    /// have moved by more than a tolerance (compare's locality footprint).
    /// InvalidInput unless both have segment j and the same degree.
    double segment_offset_bound(const IntrinsicCurve& other, int j) const;
    /// Where [t0, t1] is segment j of this curve and [u0, u1] segment j of `other`, another intrinsic
    /// curve of the same degree: segment_offset_bound(other, j) plus the rounding of the sample
    /// parameters t0 + f (t1 − t0) (16 ulps of |t0| + |t1| + |u0| + |u1|, at unit speed a distance
    /// as large); std::nullopt otherwise.
    std::optional<double> span_offset_bound(const Curve& other, double t0, double t1, double u0,
                                            double u1) const override;

private:
    TangentAngleSpline psi_;
    Eigen::MatrixXd points_;
};

/// The curvature profile for plots and tables: per segment j, `per_segment` + 1 equally spaced arc
/// lengths from w_j to w_{j+1} (both ends, so a κ jump at a G1 join shows as a vertical step), with
/// position, ψ and κ of segment j's polynomial (one-sided at its ends). per_segment ≥ 1.
struct ProfileSample {
    double s;      ///< arc length
    double x;      ///< position x
    double y;      ///< position y
    double psi;    ///< tangent angle ψ
    double kappa;  ///< curvature κ = ψ'
    int segment;   ///< the segment j sampled
};
/// The samples described above.
std::vector<ProfileSample> curvature_profile_samples(const IntrinsicCurve& curve, int per_segment);

}  // namespace cagd::intrinsic
