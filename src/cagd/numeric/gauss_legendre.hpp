#pragma once
/// @file
/// Gauss–Legendre quadrature with n nodes on [−1, 1], mapped to [a, b].
///
/// Nodes and weights by the Golub–Welsch method: the nodes are the eigenvalues of the
/// symmetric tridiagonal Jacobi matrix with off-diagonal β_k = k / sqrt(4k² − 1),
/// k = 1..n−1; weight_i = 2·v_{0,i}² for the normalised eigenvector v_i. Eigen's
/// SelfAdjointEigenSolver does the eigen-decomposition; each node is then polished by
/// one Newton step on P_n (three-term recurrence) so the nodes are accurate to ~1 ulp.
/// Exact for polynomials of degree ≤ 2n − 1. Precondition: 1 ≤ n ≤ 200.
#include <concepts>
#include <cstddef>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace cagd::numeric {

/// The n-point Gauss–Legendre rule (nodes and weights on [−1, 1]).
class GaussLegendreRule {
public:
    /// The rule with n nodes, 1 ≤ n ≤ 200 (InvalidInput otherwise).
    explicit GaussLegendreRule(int n);
    /// n, the number of nodes.
    int size() const { return static_cast<int>(nodes_.size()); }
    /// The nodes, ascending, in (−1, 1).
    const std::vector<double>& nodes() const { return nodes_; }  // ascending, in (−1, 1)
    /// The weights, matching the nodes; they sum to 2.
    const std::vector<double>& weights() const { return weights_; }
    /// ∫_a^b f ≈ ((b − a)/2) Σ w_i f(x(ξ_i)).
    double integrate(const std::function<double(double)>& f, double a, double b) const;
    /// Sum of integrals over consecutive intervals [breaks[k], breaks[k+1]].
    double integrate_piecewise(const std::function<double(double)>& f, const std::vector<double>& breaks) const;
    /// Two integrands from one evaluation per node (f returns both values), each summed exactly as
    /// integrate_piecewise sums it alone. A template, so the integrand is called directly (no
    /// std::function per node: the fairness measures call it for every piece of a curve).
    template <class F>
    requires std::same_as<std::invoke_result_t<const F&, double>, std::pair<double, double>> std::pair<double, double>
    integrate_piecewise(const F& f, const std::vector<double>& breaks)
    const {
        double first = 0.0, second = 0.0;
        for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
            const double a = breaks[k], b = breaks[k + 1];
            const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
            double sum_first = 0.0, sum_second = 0.0;
            for (std::size_t i = 0; i < nodes_.size(); ++i) {
                const auto [u, v] = f(mid + half * nodes_[i]);
                sum_first += weights_[i] * u;
                sum_second += weights_[i] * v;
            }
            first += half * sum_first;
            second += half * sum_second;
        }
        return {first, second};
    }

private:
    std::vector<double> nodes_, weights_;
};

}  // namespace cagd::numeric
