#pragma once
/// @file
/// The elastic line in space with the true bending energy (hosaka, section 6, the paragraph after
/// Fig. 7), to measure the paper's argument that a space curve y(x), z(x) may be smoothed in each
/// projection separately.
///
/// Per projection (the paper): y(x) and z(x) each minimise eq (44), i.e. the energy is
///     ½ Σ_i |(y, z)(x_i) − a_i|² / λ_i + ½ ∫ (y''² + z''²) dx.
/// True bending energy (here): the same springs, and the elastica's ½ ∫ κ² ds of r(x) = (x, y, z)(x),
///     κ² ds = |r' × r''|² / |r'|⁵ dx,   r' = (1, y', z'),  r'' = (0, y'', z''),
/// which equals y''² + z''² only to first order in the slopes (|r'| = 1 + O(y'² + z'²)): the
/// projection argument needs small slopes. Minimised over C1 piecewise cubic Hermite y, z on the
/// data abscissae each cut into `subdivisions` equal pieces (unknowns y, y', z, z' at every knot),
/// ∫ by 4-point Gauss–Legendre per piece, with Ceres (Levenberg–Marquardt, automatic derivatives;
/// residuals √(w h) (r' × r'')/|r'|^{5/2} and (y, z)(x_i) − a_i over √λ_i), started from the
/// per-projection solution.
/// Preconditions: as smoothing::elastic_line with two value columns (y, z) and every λ_i > 0;
/// subdivisions ≥ 1 and (n − 1) · subdivisions ≤ kMaxSpaceCurvePieces (checked before anything is
/// allocated). Outcome no_convergence when Ceres reports no convergence.
#include <Eigen/Dense>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::smoothing {

/// The most Hermite pieces one minimisation takes: Ceres holds four quadrature residuals per piece,
/// so memory and time grow with the pieces; 2·10^4 keeps one run within a desktop's means.
inline constexpr long long kMaxSpaceCurvePieces = 20000;

/// The minimiser as a Curve r(x) = (x, y(x), z(x)) (so analysis/ measures it), parameter x.
struct ElasticSpaceCurve final : Curve {
    std::vector<double> knots;  ///< x of every Hermite knot (data abscissae and subdivisions)
    Eigen::MatrixXd values;     ///< (y, z) at the knots
    Eigen::MatrixXd slopes;     ///< (y', z') at the knots
    double energy = 0.0;        ///< ½ Σ springs + ½ ∫ κ² ds at the minimiser (Ceres' final cost)
    Outcome outcome;            ///< ok, or Ceres' reason for stopping short
    /// (y, z)(x).
    Eigen::RowVector2d evaluate(double x) const { return jet(x, 0).block<1, 2>(0, 1); }
    int dimension() const override { return 3; }
    double t_min() const override { return knots.front(); }
    double t_max() const override { return knots.back(); }
    void evaluate_jet(double x, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const override {
        take_rows(whole_jet(x, first + static_cast<int>(out.rows()) - 1, side), first, out);
    }
    std::vector<double> breakpoints() const override { return knots; }

private:
    Eigen::MatrixXd whole_jet(double x, int order, JetSide side) const;  ///< rows 0..order of the piece on `side`
};

/// The minimiser described above: `subdivisions` Hermite pieces per data interval, Ceres from the elastic lines of y
/// and z.
ElasticSpaceCurve elastic_space_curve(const std::vector<double>& x, const Eigen::MatrixXd& a,
                                      const std::vector<double>& lambda, int subdivisions = 8);

}  // namespace cagd::smoothing
