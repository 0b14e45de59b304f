#pragma once
// Hosaka's surface smoothing (hosaka, sections 6–7, eq 53–60): gridded data a(x_i, y_j) pulled by
// springs onto an elastic net or an elastic plate. Grids: x, y strictly increasing, heights
// a(i, j) at (x_i, y_j) (rows: x, columns: y), all finite; λ = EI/k (net) or D/k (plate), finite,
// ≥ 0 for the net and > 0 for the plates, one for all nodes or one per node (a matrix like a).
//
// Elastic net (eq 53–54). Every grid line is an elastic line (section 6); at a node the x line and
// the y line share the displacement ζ_ij only. With P = ζ^(2,0), Q = ζ^(0,2) at the nodes (natural:
// P = 0 on the x ends, Q = 0 on the y ends), the spring law is
//     ζ_ij = a_ij − λ_ij (δ_i² ζ^(2,0)_ij + δ_j² ζ^(0,2)_ij)                               (53)
// (x differences of the x second derivatives, y of y: the printed (53) pairs δ_i² with ζ^(0,2) and
// δ_j² with ζ^(2,0), erratum hosaka-E10, which also reads the Z'' of (54) as this bracket), and each
// line's C2 conditions become the two five-term families of (54). Block system
//     [R_x + 6 D_xᵀΛD_x, 6 D_xᵀΛD_y; 6 D_yᵀΛD_x, R_y + 6 D_yᵀΛD_y] (P, Q) = 6 (D_xᵀ a, D_yᵀ a),
// symmetric positive definite, solved by Eigen's sparse LDLᵀ (AMD ordering). The net minimises
//     ½ Σ k_ij (ζ_ij − a_ij)² + ½ EI Σ_lines ∫ (line's second derivative)²            (checked).
//
// Plates (eq 55–59): U = U1 + U2, U2 = ½ Σ k_i (ζ_i − a_i)² (59), U1 = ½ D ∬ e dx dy with
//     (55) e = (ζxx + ζyy)² − 2(1 − ν)(ζxx ζyy − ζxy²)   (printed "+ ζxy²": erratum hosaka-E11)
//     (56) e = ζxx² + ζyy² + 2ζxy²   (ν = 0)      (57) e = ζxx² + ζyy²      (58) e = (ζxx + ζyy)².
// Method (i) (section 7 (i)): ζ bicubic on every grid cell (the m = 1 Cartesian patch, eq 30, with
// node unknowns ζ, ζ^(1,0), ζ^(0,1), ζ^(1,1)); U minimised over all node unknowns — each equation
// couples a node with its 9 neighbours' 4 unknowns (the paper's "36-term equations"). Cell integrals
// by 4 × 4 Gauss–Legendre (exact). Grid-aligned boundaries only (the paper's Lagrange terms for a
// boundary across the cells are not implemented).
// Method (ii) (section 7 (ii)), our reading: one surface of eq (31) over the whole rectangle
// between its lower and upper boundary lines y_0, y_n: ζ = Σ_{j=0}^{m} l^j {ζ^(0,j)(x, y_0) p_j(v) +
// ζ^(0,j)(x, y_n) q_j(v)}. The boundary heights are prescribed (the boundary rows of the data smoothed
// by the elastic line with the mean λ of the row); the cross-boundary derivatives ζ^(0,j), j = 1..m,
// are natural cubic splines in x through unknown node values — the parameters the paper varies —
// chosen to minimise U (dense, 2 m n_x unknowns).
// Approximation 1 (eq 60, section 7 (iii)): at each node, ζ = Σ_{i,j≤3} c_ij ψ_i(s) ψ_j(t) over the
// 5 × 5 window of grid nodes around it (shifted inwards at the border), s, t in grid steps, ψ_i the
// discrete orthonormal polynomials on s = −2..2; c minimises ½ Σ_window (ζ − a)² + ½ λ ∬_window e
// (so (I + λE) c = ψ-coefficients of a). ζ^(i,j) at the node, i, j ≤ 1, go into eq (30). Needs
// equally spaced grids (each direction) with ≥ 5 lines. The printed ψ_2 = (t² − 1)/2 is not
// orthogonal to ψ_0 and none of the printed ψ has unit norm (erratum hosaka-E12); ours are
// ψ_0 = 1/√5, ψ_1 = t/√10, ψ_2 = (t² − 2)/√14, ψ_3 = (5t³ − 17t)/(6√10) (proportional to the
// printed ψ_1, ψ_3).
// Approximation 2 (section 7 (iv)): the net's ζ, then splines (λ = 0) along the grid lines for
// ζ^(1,0), ζ^(0,1), ζ^(1,1) (surface::cartesian_spline_surface).
#include <Eigen/Dense>
#include <vector>

#include "cagd/spline/hosaka_basis.hpp"
#include "cagd/spline/hosaka_spline.hpp"
#include "cagd/surface/hosaka_patch.hpp"

namespace cagd::smoothing {

// ---- elastic net -------------------------------------------------------------------------------
struct ElasticNet {
    Eigen::MatrixXd values;                     // ζ at the nodes (nx × ny)
    Eigen::MatrixXd xx, yy;                     // ζ^(2,0), ζ^(0,2) at the nodes
    long system_size = 0, factor_nonzeros = 0;  // unknowns and nonzeros of the LDLᵀ factor
};
// lambda: 1 × 1 (all nodes) or nx × ny.
ElasticNet elastic_net(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda);

// ---- plates ------------------------------------------------------------------------------------
enum class PlateEnergy { poisson, no_poisson, no_twist, mean_curvature };  // eq 55, 56, 57, 58
// The 3 × 3 form e = hᵀ C h, h = (ζxx, ζyy, ζxy), of each energy (corrected (55)).
Eigen::Matrix3d plate_energy_form(PlateEnergy energy, double poisson_ratio = 0.3);
// ∬ e dx dy of a Cartesian surface over its grid (4 × 4 Gauss per cell).
double plate_energy(const surface::CartesianSurface& s, PlateEnergy energy, double poisson_ratio = 0.3);

struct PlateSmoothing {
    surface::CartesianSurface surface;  // m = 1 Cartesian patch (eq 30)
    int max_equation_terms = 0;         // most nonzero coefficients in one equation (36 for m = 1 on an uneven
                                        // grid; 25 on an equally spaced one, where value–own-slope couplings cancel)
    long system_size = 0;
};
PlateSmoothing plate_smoothing(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda, PlateEnergy energy,
                               double poisson_ratio = 0.3);

// Method (ii): eq (31) between the boundary lines y_0 and y_n.
class BoundaryPlateSurface {
public:
    BoundaryPlateSurface(int m, double y0, double y1, spline::ExplicitSpline boundary_data);
    double value(double x, double y) const { return derivative(x, y, 0, 0); }
    double derivative(double x, double y, int a, int b) const;  // a ≤ 2 (splines in x), any b
    int m() const { return basis_.m(); }

private:
    spline::HosakaBasis basis_;
    double y0_, y1_;
    // Columns: ζ^(0,j)(x, y_0) for j = 0..m, then ζ^(0,j)(x, y_n) for j = 0..m, as splines in x.
    spline::ExplicitSpline data_;
};
struct BoundaryPlateSmoothing {
    BoundaryPlateSurface surface;
    long system_size = 0;
};
BoundaryPlateSmoothing boundary_plate_smoothing(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda,
                                                PlateEnergy energy, int m = 2, double poisson_ratio = 0.3);

// ---- approximation 1 -----------------------------------------------------------------------------
// Orthonormal polynomials on the points s = −(n−1)/2 .. (n−1)/2 (step 1), degrees 0..degree:
// row i = coefficients of ψ_i in 1, s, s², … (Gram–Schmidt in the discrete inner product).
Eigen::MatrixXd discrete_orthonormal_polynomials(int points, int degree);
// G(i, j) = Σ_k ψ_i(s_k) ψ_j(s_k) over the same points, for any coefficient rows (the identity for
// the orthonormal set; eq (60)'s claim checked on the printed rows).
Eigen::MatrixXd discrete_gram_matrix(const Eigen::MatrixXd& psi, int points);
// The 16 × 16 matrix E of ∬_{[−2,2]²} e over c (grid steps hx, hy), and the sizes of the blocks
// into which I + λE separates (connected components of its nonzero pattern, ascending), for the
// basis whose rows are given (orthonormal or not; the spring term is then the basis's Gram matrix).
Eigen::MatrixXd window_energy_matrix(const Eigen::MatrixXd& psi, PlateEnergy energy, double hx, double hy, double poisson_ratio = 0.3);
std::vector<int> window_block_sizes(const Eigen::MatrixXd& psi, PlateEnergy energy, double poisson_ratio = 0.3);
surface::CartesianSurface local_orthogonal_smoothing(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, double lambda, PlateEnergy energy,
                                                     double poisson_ratio = 0.3);

// ---- approximation 2 -----------------------------------------------------------------------------
surface::CartesianSurface net_spline_smoothing(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda);

}  // namespace cagd::smoothing
