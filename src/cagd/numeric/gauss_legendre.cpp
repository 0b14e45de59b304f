#include "cagd/numeric/gauss_legendre.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

namespace {
// P_n(x) and P_n'(x) by the three-term recurrence.
void legendre(int n, double x, double& p, double& dp) {
    double p0 = 1.0, p1 = x;
    if (n == 0) {
        p = 1.0;
        dp = 0.0;
        return;
    }
    for (int k = 2; k <= n; ++k) {
        const double pk = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
    }
    p = p1;
    dp = n * (x * p1 - p0) / (x * x - 1.0);
}
}  // namespace

GaussLegendreRule::GaussLegendreRule(int n) {
    if (n < 1 || n > 200)
        fail_input("cagd::numeric::GaussLegendreRule", "n must be in [1, 200], got " + std::to_string(n));
    Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(n, n);
    for (int k = 1; k < n; ++k) {
        const double beta = k / std::sqrt(4.0 * k * k - 1.0);
        jacobi(k, k - 1) = jacobi(k - 1, k) = beta;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(jacobi);
    nodes_.resize(static_cast<std::size_t>(n));
    weights_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        double x = eig.eigenvalues()(i);
        if (n > 1) {
            double p, dp;
            legendre(n, x, p, dp);
            x -= p / dp;  // one Newton polish
            legendre(n, x, p, dp);
            weights_[i] = 2.0 / ((1.0 - x * x) * dp * dp);
        } else {
            weights_[i] = 2.0;
        }
        nodes_[i] = x;
    }
}

double GaussLegendreRule::integrate(const std::function<double(double)>& f, double a, double b) const {
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    double sum = 0.0;
    for (std::size_t i = 0; i < nodes_.size(); ++i) sum += weights_[i] * f(mid + half * nodes_[i]);
    return half * sum;
}

double GaussLegendreRule::integrate_piecewise(const std::function<double(double)>& f,
                                              const std::vector<double>& breaks) const {
    double sum = 0.0;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) sum += integrate(f, breaks[k], breaks[k + 1]);
    return sum;
}

}  // namespace cagd::numeric
