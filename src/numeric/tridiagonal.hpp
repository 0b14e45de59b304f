#pragma once
// Solves a tridiagonal system A X = R (several right-hand sides) by Gaussian elimination without
// pivoting (the Thomas algorithm), O(n). Row r is sub[r] x_{r−1} + diag[r] x_r + sup[r] x_{r+1}
// (sub[0] and sup[n−1] are ignored).
// Stability: no pivoting is safe when A D is diagonally dominant for some positive diagonal D
// (column scaling leaves the elimination multipliers unchanged) — the case for the spline systems
// that call it, which say why. A zero pivot throws InvalidInput.
#include <Eigen/Dense>
#include <vector>

namespace cagd::numeric {

Eigen::MatrixXd solve_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag, const std::vector<double>& sup, Eigen::MatrixXd rhs);

}  // namespace cagd::numeric
