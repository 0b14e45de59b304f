#pragma once
/// @file
/// An interpolant in its method's own parameter τ (chord length, centripetal, arc length, uniform,
/// as MethodClaims::parameter states), where the registry's curve runs in u.
///
/// Definition: on span k, between data points k and k + 1 (u ∈ [u_k, u_{k+1}]), τ is affine in u
/// with dτ/du = d_k = Interpolant::dtau_du[k] (method_registry.hpp), and τ_0 = 0:
///   τ_{k+1} = τ_k + d_k (u_{k+1} − u_k),   r̃(τ) = r(u_k + (τ − τ_k) / d_k),
///   d^i r̃/dτ^i = d_k^{−i} d^i r/du^i.
/// So τ_{k+1} − τ_k is the span's chord for a chord-length method, its arc length for the
/// curvature-profile spline, and 1 for the uniform ones; "C^k in τ" (MethodClaims) is continuity
/// of these derivatives. Between data points r̃ has the pieces of r (its breakpoints mapped).
/// Preconditions (InvalidInput): node_parameters ascending with one more entry than dtau_du, every
/// d_k > 0 and finite. Cost: a binary search over the spans per evaluation.
#include <memory>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::methods {

/// The interpolant's curve r̃(τ) in its method's parameter (see above).
class MethodParameterCurve final : public Curve {
public:
    /// Wraps `interpolant` (its curve is shared, not copied).
    explicit MethodParameterCurve(const Interpolant& interpolant);
    int dimension() const override { return base_->dimension(); }
    double t_min() const override { return tau_.front(); }
    double t_max() const override { return tau_.back(); }
    /// The span curve's jet at u(τ), then the chain rule in place.
    void evaluate_jet(double tau, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const override;
    std::vector<double> breakpoints() const override;
    /// The span curve's: τ is affine in u on every piece.
    int polynomial_degree() const override { return base_->polynomial_degree(); }
    /// τ of each data point (closed: n + 1 values, the last = t_max).
    const std::vector<double>& node_parameters() const { return tau_; }
    /// u (the registry curve's parameter) at τ.
    double span_parameter(double tau) const;
    /// τ at u.
    double method_parameter(double u) const;
    /// The curve in u this one re-parametrises.
    const std::shared_ptr<const Curve>& span_curve() const { return base_; }

private:
    std::shared_ptr<const Curve> base_;
    std::vector<double> u_, tau_, dtau_du_;
    // Equal buckets over [τ_0, τ_n], one per span: bucket_span_[b] is the span holding the
    // bucket's left end, where the search for τ starts (O(1) per point for spans of similar length).
    std::vector<int> bucket_span_;
    double buckets_per_unit_ = 0.0;
    int span_of_tau(double tau, bool from_left) const;
};

}  // namespace cagd::methods
