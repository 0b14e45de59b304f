#pragma once
/// @file
/// Planar log-aesthetic curves (typical_curves section 2.2, eq 5–15), every α including the two
/// the paper leaves out (α = 0: eq 9; α = 1: the logarithmic spiral).
///
/// A curve whose logarithmic curvature graph is a line of slope α (eq 5) satisfies
///   ρ^α = c0 s + c1            (α ≠ 0, eq 8)        ρ = c0 e^{c1 s}   (α = 0, eq 9)
/// with s the arc length. We parametrise by s ∈ [0, L] with signed curvature κ = σ/ρ (σ = ±1,
/// the turning direction), start point P0 and start tangent angle θ_start:
///   κ(s) = σ u(s)^{−1/α},  u = c0 s + c1                                    (α ≠ 0)
///   κ(s) = σ e^{−c1 s}/c0                                                   (α = 0)
///   θ(s) = θ_start + σ (Θ(s) − Θ(0)),  Θ' = |κ|, with the antiderivatives
///     Θ = α u^{(α−1)/α} / ((α−1) c0)   (α ≠ 0, 1; eq 13)     Θ = ln u / c0   (α = 1)
///     Θ = −e^{−c1 s}/(c0 c1)           (α = 0)               Θ = s/ρ       (c0 = 0 resp. c1 = 0:
///                                                                           a circle)
///   C(s) = P0 + ∫_0^s e^{iθ(v)} dv                                           (eq 14)
/// The integral is taken by tanh-sinh quadrature (Boost.Math, rel. 1e-14; it copes with the endpoint
/// singularity of θ' where c0 s + c1 = 0); for α = 1
/// and α = 2 closed forms exist (closed_form_point), which the experiments use as a check.
/// normalized_log_aesthetic_curve(α, L) is eq (15): C(s) = ∫_0^s e^{iα v^{(α−1)/α}} dv, i.e. θ(s) =
/// α s^{(α−1)/α}, κ = (α−1) s^{−1/α}: σ = sign(α − 1), c0 = |α − 1|^{−α}, c1 = 0. It exists only for
/// α < 0 or α > 1: for 0 < α ≤ 1 the turning ∫κ ds diverges at s = 0, α = 0 is not of this form.
///
/// Preconditions (InvalidInput naming the value): finite α, c0, c1, L > 0, σ = ±1; u > 0 on (0, L)
/// and, where u = 0 at an end, α < 0 or α > 1 (finite turning; for α > 1 the curvature is unbounded
/// there and jets of order ≥ 2 at that end throw); for α = 0, c0 > 0. Jets up to order 3.
#include <Eigen/Dense>
#include <optional>

#include "cagd/core/curve.hpp"

namespace cagd::aesthetic {

/// The radius law shared by planar curves (eq 8–9) and by the curvature and torsion of space curves
/// (eq 31–32): the rate r(s) = 1/ρ(s) with ρ^α = c0 s + c1 (α ≠ 0) or ρ = c0 e^{c1 s} (α = 0), and
/// the turning Θ(s) = ∫ r ds of eq (13)/(34)/(35) without its integration constant:
///   r = u^{−1/α}, u = c0 s + c1;  Θ = α u^{(α−1)/α}/((α−1) c0) (α ≠ 1),  ln u / c0 (α = 1),
///   Θ = r s (c0 = 0: a constant rate);   α = 0: r = e^{−c1 s}/c0, Θ = −e^{−c1 s}/(c0 c1) (s/c0 if c1 = 0).
/// `validate` checks the preconditions on [0, L] (InvalidInput naming `who` and the value): finite
/// α, c0, c1, L > 0; u > 0 on (0, L), and u = 0 at an end only for α < 0 or α > 1 (finite Θ); c0 > 0
/// for α = 0. Where u = 0 the rate is infinite (α > 1) or zero (α < 0); `derivative` throws where
/// it is unbounded.
struct LogAestheticRate {
    double alpha = -1.0;  ///< α
    double c0 = 1.0;      ///< c0
    double c1 = 1.0;      ///< c1
    /// InvalidInput naming `who` and `name` unless α, c0, c1 are finite and c0 s + c1 > 0 on [0, length] (where the
    /// power needs it).
    void validate(const char* who, const char* name, double length) const;
    /// c0 s + c1.
    double base(double s) const { return c0 * s + c1; }
    double value(double s) const;       ///< r(s) = 1/ρ
    double derivative(double s) const;  ///< dr/ds
    /// d²r/ds².
    double second_derivative(double s) const;
    double antiderivative(double s) const;  ///< Θ(s)
};

/// The parameters of a planar log-aesthetic curve ρ^α = c0 s + c1 of length `length`.
struct LogAestheticParameters {
    double alpha = -1.0;                              ///< α, the slope of the logarithmic curvature graph
    double c0 = 1.0;                                  ///< c0
    double c1 = 1.0;                                  ///< c1
    double length = 1.0;                              ///< the arc length
    int turn = 1;                                     ///< σ: +1 counter-clockwise, −1 clockwise
    double start_angle = 0.0;                         ///< θ_start
    Eigen::Vector2d start = Eigen::Vector2d::Zero();  ///< the start point
};

/// The planar log-aesthetic curve in arc length s ∈ [0, length] (eq 8–14, any α).
class LogAestheticCurve : public Curve {
public:
    /// The curve of these parameters; InvalidInput unless they are valid.
    explicit LogAestheticCurve(const LogAestheticParameters& p);
    /// Its parameters.
    const LogAestheticParameters& parameters() const { return p_; }

    int dimension() const override { return 2; }
    double t_min() const override { return 0.0; }
    double t_max() const override { return p_.length; }
    void evaluate_jet(double s, int first, JetSide, Eigen::Ref<Eigen::MatrixXd> out) const override {
        take_rows(whole_jet(s, first + static_cast<int>(out.rows()) - 1), first, out);
    }  ///< order ≤ 3
    std::vector<double> breakpoints() const override { return {0.0, p_.length}; }

    double curvature(double s) const;             ///< signed κ(s)
    double curvature_derivative(double s) const;  ///< dκ/ds
    double tangent_angle(double s) const;         ///< θ(s), closed form
    /// Points at `count` ≥ 2 arc lengths uniform in [0, L] (cumulative quadrature, one pass).
    Eigen::MatrixXd sample_points(int count) const;
    /// Closed-form C(s) for α = 1 (log spiral) and α = 2 (circle involute); nullopt otherwise.
    std::optional<Eigen::Vector2d> closed_form_point(double s) const;

private:
    Eigen::MatrixXd whole_jet(double s, int order) const;  ///< rows 0..order
    Eigen::Vector2d integrate(double a, double b) const;
    LogAestheticParameters p_;
    LogAestheticRate rate_;
    double theta_origin_ = 0.0;  ///< Θ(0)
};

/// The normalised curve of typical_curves eq (15): α and the length, unit radius at the start.
LogAestheticCurve normalized_log_aesthetic_curve(double alpha, double length);

}  // namespace cagd::aesthetic
