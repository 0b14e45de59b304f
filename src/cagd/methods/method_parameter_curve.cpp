#include "cagd/methods/method_parameter_curve.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::methods {

namespace {
constexpr const char* kWho = "cagd::methods::MethodParameterCurve";
}  // namespace

MethodParameterCurve::MethodParameterCurve(const Interpolant& interpolant)
    : base_(interpolant.curve), u_(interpolant.node_parameters), dtau_du_(interpolant.dtau_du) {
    if (!base_) fail_input(kWho, "the interpolant has no curve");
    if (u_.size() != dtau_du_.size() + 1 || dtau_du_.empty())
        fail_input(kWho, std::to_string(u_.size()) + " node parameters for " + std::to_string(dtau_du_.size()) +
                             " spans; needs one more node than spans, and a span");
    tau_.assign(u_.size(), 0.0);
    for (std::size_t k = 0; k < dtau_du_.size(); ++k) {
        const double d = dtau_du_[k], du = u_[k + 1] - u_[k];
        if (!(d > 0.0 && std::isfinite(d)))
            fail_input(kWho,
                       "dtau/du of span " + std::to_string(k) + " = " + full_precision(d) + "; allowed > 0 and finite");
        if (!(du > 0.0))
            fail_input(kWho, "node parameters not ascending at span " + std::to_string(k) + " (" +
                                 full_precision(u_[k]) + ", " + full_precision(u_[k + 1]) + ")");
        tau_[k + 1] = tau_[k] + d * du;
    }
    const auto spans = static_cast<int>(dtau_du_.size());
    buckets_per_unit_ = spans / (tau_.back() - tau_.front());
    bucket_span_.resize(static_cast<std::size_t>(spans));
    int k = 0;
    for (int b = 0; b < spans; ++b) {
        const double left = tau_.front() + b / buckets_per_unit_;
        while (k + 1 < spans && tau_[static_cast<std::size_t>(k) + 1] <= left) ++k;
        bucket_span_[static_cast<std::size_t>(b)] = k;
    }
}

namespace {
[[noreturn, gnu::noinline, gnu::cold]] void reject_tau(double tau, double first, double last) {
    fail_input(kWho, "t = " + full_precision(tau) + " outside [" + full_precision(first) + ", " + full_precision(last) +
                         "] (the method's parameter)");
}
}  // namespace

// Inline (the message out of line): jets_into calls it per parameter.
inline int MethodParameterCurve::span_of_tau(double tau, bool from_left) const {
    if (!(tau >= tau_.front() && tau <= tau_.back())) [[unlikely]]
        reject_tau(tau, tau_.front(), tau_.back());
    const auto spans = static_cast<int>(dtau_du_.size());
    if (from_left) {  // the span that ends at or after τ
        const auto it = std::lower_bound(tau_.begin() + 1, tau_.end(), tau);
        return std::clamp(static_cast<int>(it - tau_.begin()) - 1, 0, spans - 1);
    }
    // From the right: the last span that starts at or before τ (the last span at τ_n) — what
    // upper_bound − 1 gives, found from τ's bucket: a step back if rounding put τ before the
    // bucket's span, then forward over the spans that start at or before τ.
    const auto b =
        static_cast<std::size_t>(std::clamp(static_cast<int>((tau - tau_.front()) * buckets_per_unit_), 0, spans - 1));
    int k = bucket_span_[b];
    while (k > 0 && tau_[static_cast<std::size_t>(k)] > tau) --k;
    while (k + 1 < spans && tau_[static_cast<std::size_t>(k) + 1] <= tau) ++k;
    return k;
}

double MethodParameterCurve::span_parameter(double tau) const {
    const int k = span_of_tau(tau, false);
    const auto s = static_cast<std::size_t>(k);
    return std::min(u_[s + 1], u_[s] + (tau - tau_[s]) / dtau_du_[s]);
}

double MethodParameterCurve::method_parameter(double u) const {
    if (!(u >= u_.front() && u <= u_.back()))
        fail_input(kWho, "u = " + full_precision(u) + " outside [" + full_precision(u_.front()) + ", " +
                             full_precision(u_.back()) + "]");
    const auto k = static_cast<std::size_t>(
        std::clamp(static_cast<int>(std::upper_bound(u_.begin(), u_.end(), u) - u_.begin()) - 1, 0,
                   static_cast<int>(dtau_du_.size()) - 1));
    return std::min(tau_[k + 1], tau_[k] + dtau_du_[k] * (u - u_[k]));
}

void MethodParameterCurve::evaluate_jet(double tau, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const {
    const bool left = side == JetSide::left;
    const int k = span_of_tau(tau, left);
    const auto s = static_cast<std::size_t>(k);
    const double u = std::min(u_[s + 1], u_[s] + (tau - tau_[s]) / dtau_du_[s]);
    base_->evaluate_jet(u, first, left && u > base_->t_min() ? JetSide::left : JetSide::right, out);
    // The chain rule: d^k r̃/dτ^k = (du/dτ)^k d^k r/du^k, u affine in τ on the span.
    const double inv = 1.0 / dtau_du_[s];
    double f = 1.0;  // (du/dτ)^k, row by row from k = 1 (first is 0 or 1)
    for (Eigen::Index i = first == 0 ? 1 : 0; i < out.rows(); ++i) out.row(i) *= (f *= inv);
}

std::vector<double> MethodParameterCurve::breakpoints() const {
    std::vector<double> out;
    for (const double u : base_->breakpoints()) out.push_back(method_parameter(u));
    out.front() = tau_.front();
    out.back() = tau_.back();
    return out;
}

}  // namespace cagd::methods
