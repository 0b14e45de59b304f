#include "cagd/numeric/taylor_jet.hpp"

#include <algorithm>
#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

TaylorJet::TaylorJet(int order, double value) {
    if (order < 0) fail_input("cagd::numeric::TaylorJet", "order must be >= 0, got " + std::to_string(order));
    a_.assign(static_cast<std::size_t>(order) + 1, 0.0);
    a_[0] = value;
}

TaylorJet TaylorJet::variable(int order, double x0) {
    TaylorJet j(order, x0);
    if (order >= 1) j.a_[1] = 1.0;
    return j;
}

TaylorJet TaylorJet::from_derivatives(const std::vector<double>& d) {
    if (d.empty()) fail_input("cagd::numeric::TaylorJet::from_derivatives", "needs at least the value");
    TaylorJet j(static_cast<int>(d.size()) - 1);
    double factorial = 1.0;
    for (std::size_t k = 0; k < d.size(); ++k) {
        if (k > 0) factorial *= static_cast<double>(k);
        j.a_[k] = d[k] / factorial;
    }
    return j;
}

double TaylorJet::coefficient(int k) const {
    if (k < 0 || k > order())
        fail_input("cagd::numeric::TaylorJet::coefficient",
                   "k must be in [0, " + std::to_string(order()) + "], got " + std::to_string(k));
    return a_[static_cast<std::size_t>(k)];
}

double TaylorJet::derivative(int k) const {
    double f = 1.0;
    for (int r = 2; r <= k; ++r) f *= r;
    return coefficient(k) * f;
}

TaylorJet TaylorJet::differentiated() const {
    TaylorJet d(std::max(order() - 1, 0));
    for (int k = 1; k <= order(); ++k) d.a_[static_cast<std::size_t>(k - 1)] = k * a_[static_cast<std::size_t>(k)];
    return d;
}

TaylorJet& TaylorJet::operator+=(const TaylorJet& b) {
    a_.resize(std::min(a_.size(), b.a_.size()));
    for (std::size_t k = 0; k < a_.size(); ++k) a_[k] += b.a_[k];
    return *this;
}

TaylorJet& TaylorJet::operator-=(const TaylorJet& b) {
    a_.resize(std::min(a_.size(), b.a_.size()));
    for (std::size_t k = 0; k < a_.size(); ++k) a_[k] -= b.a_[k];
    return *this;
}

TaylorJet& TaylorJet::operator*=(double s) {
    for (double& c : a_) c *= s;
    return *this;
}

TaylorJet operator+(TaylorJet a, const TaylorJet& b) { return a += b; }
TaylorJet operator-(TaylorJet a, const TaylorJet& b) { return a -= b; }
TaylorJet operator*(TaylorJet a, double s) { return a *= s; }
TaylorJet operator*(double s, TaylorJet a) { return a *= s; }

TaylorJet operator*(const TaylorJet& a, const TaylorJet& b) {
    TaylorJet c(std::min(a.order(), b.order()));
    for (std::size_t k = 0; k < c.a_.size(); ++k)
        for (std::size_t r = 0; r <= k; ++r) c.a_[k] += a.a_[r] * b.a_[k - r];
    return c;
}

TaylorJet reciprocal(const TaylorJet& a) {
    if (a.a_[0] == 0.0) fail_input("cagd::numeric::reciprocal", "the jet's value is 0");
    TaylorJet c(a.order());
    c.a_[0] = 1.0 / a.a_[0];
    // Σ_{r=0}^{k} a_r c_{k−r} = 0 for k ≥ 1.
    for (std::size_t k = 1; k < c.a_.size(); ++k) {
        double s = 0.0;
        for (std::size_t r = 1; r <= k; ++r) s += a.a_[r] * c.a_[k - r];
        c.a_[k] = -s / a.a_[0];
    }
    return c;
}

TaylorJet power(const TaylorJet& a, int n) {
    const TaylorJet base = n < 0 ? reciprocal(a) : a;
    TaylorJet result(a.order(), 1.0);
    for (int r = 0; r < (n < 0 ? -n : n); ++r) result = result * base;
    return result;
}

TaylorJet compose(const std::vector<double>& outer_derivatives, const TaylorJet& inner) {
    // g(f0 + δ) = Σ_r g^{(r)}(f0)/r! δ^r, δ = f − f0 (no constant term, so δ^r starts at h^r).
    TaylorJet delta = inner;
    delta.a_[0] = 0.0;
    TaylorJet result(inner.order()), delta_power(inner.order(), 1.0);
    double factorial = 1.0;
    for (int r = 0; r <= inner.order() && r < static_cast<int>(outer_derivatives.size()); ++r) {
        if (r > 0) {
            factorial *= r;
            delta_power = delta_power * delta;
        }
        result += delta_power * (outer_derivatives[static_cast<std::size_t>(r)] / factorial);
    }
    return result;
}

}  // namespace cagd::numeric
