#pragma once
/// @file
/// Solves a tridiagonal system A X = R (several right-hand sides) by Gaussian elimination without
/// pivoting (the Thomas algorithm), O(n). Row r is sub[r] x_{r−1} + diag[r] x_r + sup[r] x_{r+1}
/// (sub[0] and sup[n−1] are ignored).
/// Stability: no pivoting is safe when A D is diagonally dominant for some positive diagonal D
/// (column scaling leaves the elimination multipliers unchanged) — the case for the spline systems
/// that call it, which say why. A zero pivot throws InvalidInput.
#include <Eigen/Dense>
#include <vector>

namespace cagd::numeric {

/// X with A X = rhs for the tridiagonal A above (columns of rhs solved together).
Eigen::MatrixXd solve_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag, const std::vector<double>& sup, Eigen::MatrixXd rhs);

/// The cyclic (periodic) system: as above, with the corner entries A(0, n−1) = sub[0] and
/// A(n−1, 0) = sup[n−1], n ≥ 3. Sherman–Morrison on the Thomas solve: A = A' + u vᵀ with
/// u = (γ, 0, …, 0, sup[n−1]), v = (1, 0, …, 0, sub[0]/γ), γ = −diag[0], and one Thomas pass
/// with one extra right-hand side (A' z = u). O(n). Same stability condition as above, for A'
/// (whose first and last pivots are 2 diag[0] and diag[n−1] − sub[0] sup[n−1]/diag[0]);
/// a singular correction (1 + vᵀz = 0) throws InvalidInput.
Eigen::MatrixXd solve_cyclic_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag, const std::vector<double>& sup, const Eigen::MatrixXd& rhs);

}  // namespace cagd::numeric
