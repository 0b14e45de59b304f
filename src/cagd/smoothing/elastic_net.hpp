#pragma once
/// @file
/// Hosaka's elastic net (hosaka, section 7, eq 53–54) and approximation 2 (section 7 (iv)): gridded
/// data a(x_i, y_j) pulled by springs onto a net of elastic lines.
/// Grids: x, y strictly increasing, heights a(i, j) at (x_i, y_j) (rows: x, columns: y), all finite;
/// λ one for all nodes (1 × 1) or one per node (a matrix like a).
/// λ = EI/k, finite and ≥ 0.
///
/// Elastic net (eq 53–54). Every grid line is an elastic line (section 6); at a node the x line and
/// the y line share the displacement ζ_ij only. With P = ζ^(2,0), Q = ζ^(0,2) at the nodes (natural:
/// P = 0 on the x ends, Q = 0 on the y ends), the spring law is
///     ζ_ij = a_ij − λ_ij (δ_i² ζ^(2,0)_ij + δ_j² ζ^(0,2)_ij)                               (53)
/// (x differences of the x second derivatives, y of y: the printed (53) pairs δ_i² with ζ^(0,2) and
/// δ_j² with ζ^(2,0), erratum hosaka-E10, which also reads the Z'' of (54) as this bracket), and each
/// line's C2 conditions become the two five-term families of (54). Block system
///     [R_x + 6 D_xᵀΛD_x, 6 D_xᵀΛD_y; 6 D_yᵀΛD_x, R_y + 6 D_yᵀΛD_y] (P, Q) = 6 (D_xᵀ a, D_yᵀ a),
/// symmetric positive definite, solved by Eigen's sparse LDLᵀ (AMD ordering). The net minimises
///     ½ Σ k_ij (ζ_ij − a_ij)² + ½ EI Σ_lines ∫ (line's second derivative)²            (checked).
///
/// Approximation 2 (section 7 (iv)): the net's ζ, then splines (λ = 0) along the grid lines for
/// ζ^(1,0), ζ^(0,1), ζ^(1,1) (surface::cartesian_spline_surface).
#include <Eigen/Dense>
#include <vector>

#include "cagd/surface/hosaka_patch.hpp"

namespace cagd::smoothing {

/// The elastic net's displacements and second derivatives at the nodes.
struct ElasticNet {
    Eigen::MatrixXd values;    ///< ζ at the nodes (nx × ny)
    Eigen::MatrixXd xx;        ///< ζ^(2,0) at the nodes
    Eigen::MatrixXd yy;        ///< ζ^(0,2) at the nodes
    long system_size = 0;      ///< unknowns
    long factor_nonzeros = 0;  ///< nonzeros of the LDLᵀ factor
};
/// The net of eq (53)–(54); lambda: 1 × 1 (all nodes) or nx × ny.
ElasticNet elastic_net(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a,
                       const Eigen::MatrixXd& lambda);

/// Approximation 2: the net, then splines along the grid lines for the node derivatives.
surface::CartesianSurface net_spline_smoothing(const std::vector<double>& x, const std::vector<double>& y,
                                               const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda);

}  // namespace cagd::smoothing
