#pragma once
/// @file
/// Hosaka's plate smoothing, method (i) (hosaka, section 7, eq 55–59): gridded data a(x_i, y_j)
/// pulled by springs onto an elastic plate.
/// Grids: x, y strictly increasing, heights a(i, j) at (x_i, y_j) (rows: x, columns: y), all finite;
/// λ one for all nodes (1 × 1) or one per node (a matrix like a).
/// λ = D/k, finite and > 0.
///
/// Plates (eq 55–59): U = U1 + U2, U2 = ½ Σ k_i (ζ_i − a_i)² (59), U1 = ½ D ∬ e dx dy with
///     (55) e = (ζxx + ζyy)² − 2(1 − ν)(ζxx ζyy − ζxy²)   (printed "+ ζxy²": erratum hosaka-E11)
///     (56) e = ζxx² + ζyy² + 2ζxy²   (ν = 0)      (57) e = ζxx² + ζyy²      (58) e = (ζxx + ζyy)².
/// Method (i) (section 7 (i)): ζ bicubic on every grid cell (the m = 1 Cartesian patch, eq 30, with
/// node unknowns ζ, ζ^(1,0), ζ^(0,1), ζ^(1,1)); U minimised over all node unknowns — each equation
/// couples a node with its 9 neighbours' 4 unknowns (the paper's "36-term equations"). Cell integrals
/// by 4 × 4 Gauss–Legendre (exact). Grid-aligned boundaries only (the paper's Lagrange terms for a
/// boundary across the cells are not implemented).
#include <Eigen/Dense>
#include <vector>

#include "cagd/surface/hosaka_patch.hpp"

namespace cagd::smoothing {

/// The plate energy e: poisson (eq 55, corrected), no_poisson (56), no_twist (57), mean_curvature (58).
enum class PlateEnergy { poisson, no_poisson, no_twist, mean_curvature };
/// The 3 × 3 form e = hᵀ C h, h = (ζxx, ζyy, ζxy), of each energy (corrected (55)).
Eigen::Matrix3d plate_energy_form(PlateEnergy energy, double poisson_ratio = 0.3);
/// ∬ e dx dy of a Cartesian surface over its grid (4 × 4 Gauss per cell).
double plate_energy(const surface::CartesianSurface& s, PlateEnergy energy, double poisson_ratio = 0.3);

/// The smoothed surface of method (i) and the size of its system.
struct PlateSmoothing {
    surface::CartesianSurface surface;  ///< m = 1 Cartesian patch (eq 30)
    int max_equation_terms = 0;  ///< most nonzero coefficients in one equation (36 for m = 1 on an uneven grid; 25 on
                                 ///< an equally spaced one, where value–own-slope couplings cancel)
    long system_size = 0;        ///< unknowns
};
/// Method (i): the bicubic surface over the grid minimising U (see above).
PlateSmoothing plate_smoothing(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a,
                               const Eigen::MatrixXd& lambda, PlateEnergy energy, double poisson_ratio = 0.3);

}  // namespace cagd::smoothing
