#pragma once
/// @file
/// Hosaka's approximation 1 (hosaka, section 7 (iii), eq 60): local least squares with a plate
/// energy over 5 × 5 windows of the grid.
/// Grids: x, y strictly increasing, heights a(i, j) at (x_i, y_j) (rows: x, columns: y), all finite;
/// λ one for all nodes (1 × 1) or one per node (a matrix like a).
///
/// Approximation 1 (eq 60, section 7 (iii)): at each node, ζ = Σ_{i,j≤3} c_ij ψ_i(s) ψ_j(t) over the
/// 5 × 5 window of grid nodes around it (shifted inwards at the border), s, t in grid steps, ψ_i the
/// discrete orthonormal polynomials on s = −2..2; c minimises ½ Σ_window (ζ − a)² + ½ λ ∬_window e
/// (so (I + λE) c = ψ-coefficients of a). ζ^(i,j) at the node, i, j ≤ 1, go into eq (30). Needs
/// equally spaced grids (each direction) with ≥ 5 lines. The printed ψ_2 = (t² − 1)/2 is not
/// orthogonal to ψ_0 and none of the printed ψ has unit norm (erratum hosaka-E12); ours are
/// ψ_0 = 1/√5, ψ_1 = t/√10, ψ_2 = (t² − 2)/√14, ψ_3 = (5t³ − 17t)/(6√10) (proportional to the
/// printed ψ_1, ψ_3).
#include <Eigen/Dense>
#include <vector>

#include "cagd/smoothing/plate_smoothing.hpp"
#include "cagd/surface/hosaka_patch.hpp"

namespace cagd::smoothing {

/// Orthonormal polynomials on the points s = −(n−1)/2 .. (n−1)/2 (step 1), degrees 0..degree:
/// row i = coefficients of ψ_i in 1, s, s², … (Gram–Schmidt in the discrete inner product).
Eigen::MatrixXd discrete_orthonormal_polynomials(int points, int degree);
/// G(i, j) = Σ_k ψ_i(s_k) ψ_j(s_k) over the same points, for any coefficient rows (the identity for
/// the orthonormal set; eq (60)'s claim checked on the printed rows).
Eigen::MatrixXd discrete_gram_matrix(const Eigen::MatrixXd& psi, int points);
/// The 16 × 16 matrix E of ∬_{[−2,2]²} e over c (grid steps hx, hy), and the sizes of the blocks
/// into which I + λE separates (connected components of its nonzero pattern, ascending), for the
/// basis whose rows are given (orthonormal or not; the spring term is then the basis's Gram matrix).
Eigen::MatrixXd window_energy_matrix(const Eigen::MatrixXd& psi, PlateEnergy energy, double hx, double hy,
                                     double poisson_ratio = 0.3);
/// The block sizes of I + λE described above.
std::vector<int> window_block_sizes(const Eigen::MatrixXd& psi, PlateEnergy energy, double poisson_ratio = 0.3);
/// Approximation 1: the 5 × 5 window fit at every node, the node derivatives into eq (30).
surface::CartesianSurface local_orthogonal_smoothing(const std::vector<double>& x, const std::vector<double>& y,
                                                     const Eigen::MatrixXd& a, double lambda, PlateEnergy energy,
                                                     double poisson_ratio = 0.3);

}  // namespace cagd::smoothing
