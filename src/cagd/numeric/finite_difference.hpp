#pragma once
/// @file
/// One-sided derivatives from samples: the derivatives at x0 of the polynomial of degree N−1 through
/// f(x0 + side·k·h), k = 0..N−1 (side = +1 or −1). Used to measure smoothness across a seam from
/// values alone, independently of the code that computes derivatives analytically.
/// Accuracy: the r-th derivative has truncation error O(h^{N−r}) and rounding error O(ε/h^r).
/// Preconditions (InvalidInput): h > 0, side = ±1, 2 ≤ N ≤ 12.
#include <functional>
#include <vector>

namespace cagd::numeric {

/// Result[r] = r-th derivative at x0, r = 0..N−1.
std::vector<double> one_sided_derivatives(const std::function<double(double)>& f, double x0, double h, int side,
                                          int points);

}  // namespace cagd::numeric
