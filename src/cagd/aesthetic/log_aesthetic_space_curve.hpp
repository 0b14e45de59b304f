#pragma once
/// @file
/// Log-aesthetic space curves (typical_curves section 4, eq 31–35).
///
/// Both the logarithmic curvature graph (slope α) and the logarithmic torsion graph (slope β) are
/// lines:   ρ^α = c s + d  (eq 31),   μ^β = g s + h  (eq 32),
/// ρ = 1/κ the radius of curvature, μ = 1/τ the radius of torsion, s the arc length. In our names
/// curvature = LogAestheticRate{α, c, d} and torsion = LogAestheticRate{β, g, h} (α = 0 or β = 0:
/// the exponential law of eq 9, footnote 1). The tangent turns about the binormal by θ_κ(s) and the
/// normal about the tangent by θ_τ(s), eq (34)–(35), the antiderivatives of κ and τ; their constants
/// c_κ2, c_τ2 cancel in every difference and are not stored: we use the angles turned since s = 0,
///   θ_κ(s) = Θ_κ(s) − Θ_κ(0),   θ_τ(s) = Θ_τ(s) − Θ_τ(0).
/// The curve is the solution of the Frenet–Serret equations (33) from C(0) = 0 with the frame
/// t = e_x, n = e_y, b = e_z; τ > 0 is right-handed (b' = −τ n).
///
/// normalized_log_aesthetic_space_parameters(α, β, L, s0) extends eq (15) to space: the piece
/// σ ∈ [s0, s0 + L] of κ = |α − 1| σ^{−1/α}, τ = |β − 1| σ^{−1/β} (θ_κ = α sign(α − 1) σ^{(α−1)/α},
/// θ_τ = β sign(β − 1) σ^{(β−1)/β}), re-parametrised by s = σ − s0: c = |α − 1|^{−α}, d = c s0,
/// g = |β − 1|^{−β}, h = g s0. Defined for α, β < 0 or > 1 (for s0 = 0 the turning must be finite).
/// The paper states none of c, d, g, h, c_κ2, c_τ2 or L; this is our choice for its Figs. 3–5.
///
/// Evaluation: the Frenet–Serret system (position and frame, 12 unknowns) is integrated with
/// Boost.Odeint's Dormand–Prince 5(4) pair, abs./rel. tolerance 1e-13, in the variable w with
/// s = L w^m; where a rate law has c s + d = 0 at s = 0 (κ or τ unbounded or 0 there) m is chosen
/// so that κ ds/dw and τ ds/dw stay continuously differentiable (m ≥ 2α/(α − 1) for α > 1).
/// States are stored at 257 values of w; a point is integrated from the nearest stored state.
/// Jets (orders ≤ 4) follow from the Frenet frame: r' = t, r'' = κn, r''' = −κ²t + κ'n + κτb,
/// r'''' = −3κκ't + (κ'' − κ³ − κτ²)n + (2κ'τ + κτ')b.
///
/// Preconditions (InvalidInput naming the value): each law valid on [0, L] (LogAestheticRate::
/// validate); c s + d (g s + h) may vanish only at s = 0 (the integration handles a singular start,
/// not a singular end); s ∈ [0, L]; jets of order ≥ 2 (≥ 3 for τ) where κ (τ) is unbounded throw.
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "cagd/aesthetic/log_aesthetic_curve.hpp"
#include "cagd/core/curve.hpp"

namespace cagd::aesthetic {

/// The parameters of a log-aesthetic space curve: laws of curvature and torsion, and its length.
struct LogAestheticSpaceParameters {
    LogAestheticRate curvature{1.5, 1.0, 1.0};  ///< ρ^α = c s + d
    LogAestheticRate torsion{1.2, 1.0, 1.0};    ///< μ^β = g s + h
    double length = 1.0;                        ///< the arc length
};

/// The normalised parameters of typical_curves section 4 for α, β, the length and the start s0.
LogAestheticSpaceParameters normalized_log_aesthetic_space_parameters(double alpha, double beta, double length,
                                                                      double start = 0.0);

/// The log-aesthetic space curve in arc length, solved from the Frenet–Serret equations (eq 31–35).
class LogAestheticSpaceCurve : public Curve {
public:
    /// The curve of these parameters; InvalidInput unless they are valid.
    explicit LogAestheticSpaceCurve(const LogAestheticSpaceParameters& p);
    /// Its parameters.
    const LogAestheticSpaceParameters& parameters() const { return p_; }

    int dimension() const override { return 3; }
    double t_min() const override { return 0.0; }
    double t_max() const override { return p_.length; }
    void evaluate_jet(double s, int first, JetSide, Eigen::Ref<Eigen::MatrixXd> out) const override {
        take_rows(whole_jet(s, first + static_cast<int>(out.rows()) - 1), first, out);
    }  ///< order ≤ 4
    std::vector<double> breakpoints() const override { return {0.0, p_.length}; }

    /// κ(s).
    double curvature(double s) const { return p_.curvature.value(s); }
    /// τ(s).
    double torsion(double s) const { return p_.torsion.value(s); }
    double curvature_angle(double s) const;  ///< θ_κ(s), eq (34) minus its value at 0
    double torsion_angle(double s) const;    ///< θ_τ(s), eq (35) minus its value at 0
    /// Columns t, n, b at s.
    Eigen::Matrix3d frame(double s) const;

private:
    Eigen::MatrixXd whole_jet(double s, int order) const;  ///< rows 0..order
    using State = std::array<double, 12>;                  ///< r, t, n, b
    State state_at(double s) const;
    void check_s(double s) const;
    LogAestheticSpaceParameters p_;
    int exponent_ = 1;          ///< m of s = L w^m
    std::vector<State> nodes_;  ///< at w = k/(nodes − 1)
};

}  // namespace cagd::aesthetic
