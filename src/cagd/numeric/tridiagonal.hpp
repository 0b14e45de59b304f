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
Eigen::MatrixXd solve_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag,
                                  const std::vector<double>& sup, Eigen::MatrixXd rhs);

/// The same solve with row r formed as the elimination reaches it: row(r, rhs, stride) returns row
/// r's entries (a TridiagonalRow) and writes its right-hand side's `cols` values to rhs[j·stride];
/// X is written to x (n × cols, column-major). For systems whose entries come from a few arrays (the
/// cubic splines' chords): no n-long arrays of diagonals and right-hand sides, and each row
/// eliminated while it is in cache. The same operations on the same values as solve_tridiagonal, so
/// the same X to the bit. A zero pivot throws InvalidInput.
template <class Row>
void solve_tridiagonal_rows(std::size_t n, std::size_t cols, Row&& row, double* x);

/// The cyclic (periodic) system: as above, with the corner entries A(0, n−1) = sub[0] and
/// A(n−1, 0) = sup[n−1], n ≥ 3. Sherman–Morrison on the Thomas solve: A = A' + u vᵀ with
/// u = (γ, 0, …, 0, sup[n−1]), v = (1, 0, …, 0, sub[0]/γ), γ = −diag[0], and one Thomas pass
/// with one extra right-hand side (A' z = u). O(n). Same stability condition as above, for A'
/// (whose first and last pivots are 2 diag[0] and diag[n−1] − sub[0] sup[n−1]/diag[0]);
/// a singular correction (1 + vᵀz = 0) throws InvalidInput.
Eigen::MatrixXd solve_cyclic_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag,
                                         const std::vector<double>& sup, const Eigen::MatrixXd& rhs);

}  // namespace cagd::numeric

#include "cagd/numeric/detail/thomas.hpp"
