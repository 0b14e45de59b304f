#pragma once
/// @file
/// Hosaka's plate smoothing, method (ii) (hosaka, section 7 (ii), eq 31 with 55–59).
/// Grids: x, y strictly increasing, heights a(i, j) at (x_i, y_j) (rows: x, columns: y), all finite;
/// λ one for all nodes (1 × 1) or one per node (a matrix like a).
/// λ = D/k, finite and > 0. The plate energies are those of smoothing/plate_smoothing.hpp.
///
/// Method (ii) (section 7 (ii)), our reading: one surface of eq (31) over the whole rectangle
/// between its lower and upper boundary lines y_0, y_n: ζ = Σ_{j=0}^{m} l^j {ζ^(0,j)(x, y_0) p_j(v) +
/// ζ^(0,j)(x, y_n) q_j(v)}. The boundary heights are prescribed (the boundary rows of the data smoothed
/// by the elastic line with the mean λ of the row); the cross-boundary derivatives ζ^(0,j), j = 1..m,
/// are natural cubic splines in x through unknown node values — the parameters the paper varies —
/// chosen to minimise U (dense, 2 m n_x unknowns).
#include <Eigen/Dense>
#include <vector>

#include "cagd/smoothing/plate_smoothing.hpp"
#include "cagd/spline/hosaka_basis.hpp"
#include "cagd/spline/hosaka_spline.hpp"

namespace cagd::smoothing {

/// Method (ii): eq (31) between the boundary lines y_0 and y_n.
class BoundaryPlateSurface {
public:
    /// The surface of order m between the lines y0 and y1, from the boundary data's splines (columns below).
    BoundaryPlateSurface(int m, double y0, double y1, spline::ExplicitSpline boundary_data);
    /// ζ(x, y).
    double value(double x, double y) const { return derivative(x, y, 0, 0); }
    double derivative(double x, double y, int a, int b) const;  ///< a ≤ 2 (splines in x), any b
    /// m.
    int m() const { return basis_.m(); }

private:
    spline::HosakaBasis basis_;
    double y0_, y1_;
    /// Columns: ζ^(0,j)(x, y_0) for j = 0..m, then ζ^(0,j)(x, y_n) for j = 0..m, as splines in x.
    spline::ExplicitSpline data_;
};
/// The smoothed surface of method (ii) and the size of its system.
struct BoundaryPlateSmoothing {
    BoundaryPlateSurface surface;  ///< eq (31) between the first and last y lines
    long system_size = 0;          ///< unknowns (2 m n_x)
};
/// Method (ii) (see above).
BoundaryPlateSmoothing boundary_plate_smoothing(const std::vector<double>& x, const std::vector<double>& y,
                                                const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda,
                                                PlateEnergy energy, int m = 2, double poisson_ratio = 0.3);

}  // namespace cagd::smoothing
