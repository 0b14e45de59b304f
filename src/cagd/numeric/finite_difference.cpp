#include "cagd/numeric/finite_difference.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

std::vector<double> one_sided_derivatives(const std::function<double(double)>& f, double x0, double h, int side,
                                          int points) {
    const char* who = "cagd::numeric::one_sided_derivatives";
    if (!(h > 0) || !std::isfinite(h)) fail_input(who, "h must be positive and finite, got " + full_precision(h));
    if (side != 1 && side != -1) fail_input(who, "side must be +1 or -1, got " + std::to_string(side));
    if (points < 2 || points > 12) fail_input(who, "points must be in [2, 12], got " + std::to_string(points));
    // Interpolate in the scaled variable t = k (nodes 0..N−1): f ≈ Σ c_r t^r, d^r f/dx^r = r! c_r / (side h)^r.
    Eigen::MatrixXd V(points, points);
    Eigen::VectorXd values(points);
    for (int k = 0; k < points; ++k) {
        for (int r = 0; r < points; ++r) V(k, r) = std::pow(double(k), r);
        values(k) = f(x0 + side * k * h);
    }
    const Eigen::VectorXd c = V.fullPivLu().solve(values);
    std::vector<double> d(static_cast<std::size_t>(points));
    double factorial = 1.0;
    for (int r = 0; r < points; ++r) {
        if (r > 0) factorial *= r;
        d[static_cast<std::size_t>(r)] = factorial * c(r) / std::pow(side * h, r);
    }
    return d;
}

}  // namespace cagd::numeric
