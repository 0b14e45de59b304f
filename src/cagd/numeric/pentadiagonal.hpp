#pragma once
/// @file
/// Solves A X = R for a symmetric positive definite pentadiagonal A (several right-hand sides) by
/// LDLᵀ without pivoting, O(n) time and memory. Row r of A is
///   second[r−2] x_{r−2} + first[r−1] x_{r−1} + diag[r] x_r + first[r] x_{r+1} + second[r] x_{r+2}
/// (first has n−1 entries, second n−2). Eigen has banded storage but no banded solver; its sparse
/// LDLᵀ does the same in O(n) with more overhead (the elastic line's benchmark measures both).
/// Stability: LDLᵀ of an SPD matrix needs no pivoting (every pivot is positive). A pivot ≤ 0 means A
/// is not positive definite: InvalidInput.
#include <Eigen/Dense>
#include <vector>

namespace cagd::numeric {

/// X with A X = rhs for the symmetric pentadiagonal A above (columns of rhs solved together).
Eigen::MatrixXd solve_symmetric_pentadiagonal(const std::vector<double>& diag, const std::vector<double>& first,
                                              const std::vector<double>& second, Eigen::MatrixXd rhs);

}  // namespace cagd::numeric
