#pragma once
/// @file
/// The tangent angle ψ(s) as a B-spline in arc length (curvature_profile, section 2, eq 1):
///   r'(s) = (cos ψ(s), sin ψ(s)),  κ(s) = dψ/ds,
/// ψ of degree p on the knots of a KnotLayout placed at the breakpoints w_0 = 0 < w_1 < … < w_k
/// (w_{j+1} − w_j = Δw_j, the segment arc lengths), with de Boor ordinates B_0..B_q.
///
/// Two evaluations, kept independent so each checks the other:
///   jet(s, order)      de Boor / Cox–de Boor basis functions (spline/bspline, Piegl–Tiller A2.3);
///   bezier()           the per-segment Bézier form of section 2, ψ_j(t) = Σ_r b_{j,r} B^p_r(t),
///                      t = (s − w_j)/Δw_j ∈ [0, 1], by blossoming (detail/bezier_extraction.hpp).
/// direction_integrals() integrates (cos ψ_j, sin ψ_j) over t ∈ [0, τ] — the integrals of eq (3).
/// Rule: the segment is cut into m = max(1, ⌈max_t |dψ_j/dt| / 3⌉) equal pieces (≤ 3 rad of
/// turning each; the bound is the largest |p Δb_{j,r}|, the derivative's Bézier ordinates), 16-point
/// Gauss–Legendre on each. The integrand e^{iψ} is entire. On a piece of ≤ 1 rad mapped to [−1, 1] it
/// stays below e^3 on the Bernstein ellipse ρ = 4 for every degree p ≤ 4 (the worst Bézier derivative
/// ordinates, ±1, give e^1.46 for p = 3 and e^2.36 for p = 4); Im ψ grows linearly with the turning,
/// so on a piece of ≤ 3 rad it stays below e^{3·2.36} < 1200, and the Gauss error bound
/// (64/15) M ρ^{−32}/(ρ² − 1) is < 2e−17 of the piece: the rule is exact to rounding (tested against
/// adaptive Gauss–Kronrod).
///
/// Preconditions (InvalidInput): segment lengths finite and > 0, one per segment; de Boor ordinates
/// finite, layout.ordinates() of them; s in [0, length()].
#include <Eigen/Dense>
#include <vector>

#include "cagd/intrinsic/knot_difference_list.hpp"

namespace cagd::intrinsic {

/// The tangent angle ψ(s) as a B-spline in arc length s ∈ [0, L] (see above).
class TangentAngleSpline {
public:
    /// ψ on `layout` with the segments' lengths Δw_j (k values > 0) and the de Boor ordinates B_0..B_q.
    TangentAngleSpline(KnotLayout layout, std::vector<double> segment_lengths, Eigen::VectorXd de_boor);
    /// From the unknown vector of eq (2), u = (S_0..S_{l−1}, B_0..B_q).
    static TangentAngleSpline from_unknowns(const KnotLayout& layout, const Eigen::VectorXd& u);

    /// The knot layout.
    const KnotLayout& layout() const { return layout_; }
    /// p.
    int degree() const { return layout_.degree(); }
    /// k.
    int segments() const { return layout_.segments(); }
    /// Δw_j, one per segment.
    const std::vector<double>& segment_lengths() const { return lengths_; }
    const std::vector<double>& breakpoints() const { return w_; }  ///< w_0 = 0, …, w_k = L
    /// L = w_k.
    double length() const { return w_.back(); }
    /// B_0..B_q.
    const Eigen::VectorXd& de_boor() const { return de_boor_; }
    std::vector<double> farin_knots() const;  ///< v_{−p+1}..v_q
    /// The 2p Farin knots that shape segment j, measured from its start w_j by summing segment
    /// lengths (exact up to the sum of a few terms). The Bézier extraction uses these rather than
    /// farin_knots(): differences of absolute knots cost ε·w_k each, which at 10^5 segments floors the
    /// eq (3) residual near 1e−11 and stops Newton short of its tolerance.
    std::vector<double> local_farin_knots(int segment) const;
    void local_farin_knots_into(int segment, double* out) const;  ///< the same into out[0..2p), no allocation
    /// The same from a layout and segment lengths alone (no spline built: the Newton iterations'
    /// path); lengths has layout.segments() values.
    static void local_farin_knots_into(const KnotLayout& layout, const std::vector<double>& lengths, int segment,
                                       double* out);
    /// InvalidInput naming `who` unless every segment length is finite and > 0 and every one of the
    /// `ordinates` de Boor ordinates is finite (the constructor's checks, for callers that hold ψ's
    /// values without building it).
    static void require_valid_values(const char* who, const std::vector<double>& lengths, const double* de_boor,
                                     std::size_t ordinates);
    std::vector<double> greville_abscissae() const;  ///< one per de Boor ordinate
    const Eigen::MatrixXd& bezier() const {
        return bezier_;
    }  ///< k × (p + 1): the Bézier ordinates b_{j,r} of each segment

    /// ψ^{(d)}(s), d = 0..order, by the B-spline basis (right-continuous; s = length from the left).
    Eigen::VectorXd jet(double s, int order) const;
    /// The same for the polynomial of segment j, s ∈ [w_j, w_{j+1}] (one-sided limits at its ends).
    Eigen::VectorXd jet_in_segment(int segment, double s, int order) const;
    /// The same into out[0..order] (order ≤ 7), without allocating: the hot path of positions.
    void jet_in_segment_into(int segment, double s, int order, double* out) const;
    int segment_at(double s) const;  ///< j with w_j ≤ s < w_{j+1} (the last segment at s = length)
    /// From the Bézier form: ψ and κ at the start (t = 0) or end (t = 1) of segment j.
    double angle(int segment, bool at_end) const;
    /// κ = ψ' at the start or end of segment j, from the Bézier form.
    double curvature(int segment, bool at_end) const;

private:
    int checked_span(int segment, double s) const;  ///< the knot span of segment j; InvalidInput if s is outside it
    std::vector<double> basis_knots_;  ///< farin_knots() with w_0 and w_k added: the knot vector of jet_in_segment
    KnotLayout layout_;
    std::vector<double> lengths_, w_;
    Eigen::VectorXd de_boor_;
    Eigen::MatrixXd bezier_;
};

/// ∫_0^τ (cos ψ(t), sin ψ(t)) dt for the Bézier polynomial ψ with ordinates b (degree = size − 1,
/// ≤ 4), 0 ≤ τ ≤ 1, by the rule above. With `weights`, also W(0, r) = ∫_0^1 cos ψ B^p_r dt and
/// W(1, r) = ∫_0^1 sin ψ B^p_r dt (τ must be 1), the derivatives' building blocks.
/// b may be a row of bezier() (any inner stride: no copy).
Eigen::Vector2d direction_integrals(const Eigen::Ref<const Eigen::VectorXd, 0, Eigen::InnerStride<>>& b,
                                    double tau = 1.0, Eigen::Matrix<double, 2, Eigen::Dynamic>* weights = nullptr);
/// The same with the weights in fixed storage (degree ≤ 4: at most 5 columns), no allocation.
using DirectionWeights = Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, 5>;
/// The same as above with the weights in fixed storage.
Eigen::Vector2d direction_integrals(const Eigen::Ref<const Eigen::VectorXd, 0, Eigen::InnerStride<>>& b, double tau,
                                    DirectionWeights* weights);

}  // namespace cagd::intrinsic
