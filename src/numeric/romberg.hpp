#pragma once
// Romberg integration: the reference quadrature the papers prescribe.
//
// Trapezoid sums T(h), h = (b−a)/2^k, extrapolated by Richardson's scheme
// R(k, j) = R(k, j−1) + (R(k, j−1) − R(k−1, j−1)) / (4^j − 1).
// The error estimate is |R(k, k) − R(k−1, k−1)|; the result is converged when that
// estimate is ≤ max(rel_tol·|R(k, k)|, abs_tol) for two consecutive levels (a single
// small difference can be a coincidence of the trapezoid samples).
// Accuracy: O(h^{2k+2}) for integrands smooth on [a, b]; integrate piecewise smooth
// functions piece by piece. Cost: 2^max_levels + 1 evaluations at most.
// Not converging within max_levels is an Outcome, not an exception.
#include <functional>

#include "core/errors.hpp"

namespace cagd::numeric {

struct RombergResult {
    double value = 0.0;
    double error_estimate = 0.0;   // |R(k,k) − R(k−1,k−1)| at the last level
    int levels = 0;                // k reached
    long evaluations = 0;
    Outcome outcome;
};

// Preconditions: a, b finite; rel_tol > 0; abs_tol ≥ 0; 2 ≤ max_levels ≤ 30.
RombergResult romberg(const std::function<double(double)>& f, double a, double b,
                      double rel_tol = 1e-12, double abs_tol = 0.0, int max_levels = 24);

}  // namespace cagd::numeric
