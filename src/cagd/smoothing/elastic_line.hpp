#pragma once
/// @file
/// Hosaka's elastic-line smoothing (hosaka, section 6, eq 44–52).
///
/// Model (Fig. 6a): data a_i at strictly increasing abscissae x_i (i = 0..n) pull, through springs of
/// stiffness k_i and rest length 0, on a beam of bending stiffness EI. The beam's shape y(x) minimises
///     V = ½ Σ_i k_i {y(x_i) − a_i}² + ½ EI ∫ y''² dx                                         (44)
/// over [x_0, x_n]. Only λ_i = EI/k_i matters (V/EI). The minimiser is the natural cubic spline
/// (y'' = 0 at both ends) through its own node values y_i, with second derivatives M_i = y''_i
/// satisfying, with l_i = x_i − x_{i−1} and δ²f_i = (f_{i+1} − f_i)/l_{i+1} − (f_i − f_{i−1})/l_i
/// (terms beyond the ends dropped), the spring law
///     y_i − a_i + λ_i δ²M_i = 0                                                              (50)
/// (δ²M_i is the jump of y''' at x_i, the beam's shear reaction; the printed (50) reads
/// "y_i − a_i − λ_i δ²y''_i", no "= 0" and the sign reversed: erratum hosaka-E8) and the five-term
/// system obtained by putting (50) into the spline's C2 conditions (49 = 23),
///     l_i M_{i−1} + 2(l_i + l_{i+1}) M_i + l_{i+1} M_{i+1}
///       + (6/l_{i+1})(λ_{i+1} δ²M_{i+1} − λ_i δ²M_i) − (6/l_i)(λ_i δ²M_i − λ_{i−1} δ²M_{i−1}) = 6 δ²a_i  (51)
/// for i = 1..n−1, M_0 = M_n = 0. In matrix form (R + 6 Qᵀ Λ Q) M = 6 Qᵀ a with R the spline's
/// tridiagonal matrix and Q the (n+1) × (n−1) second-difference matrix: symmetric positive definite
/// and pentadiagonal, assembled band by band and solved by a banded LDLᵀ
/// (numeric::solve_symmetric_pentadiagonal), O(n) time and memory.
/// The curve is eq (52) — on [x_i, x_{i+1}], u = (x − x_i)/l_{i+1},
///     y = y_i + (y_{i+1} − y_i) u − (2M_i + M_{i+1})(l²/6) p_1(u) + (M_i + 2M_{i+1})(l²/6) q_1(u),
/// which is the cubic Hermite segment of eq (45) with the slopes of the spline; we return it as a
/// spline::ExplicitSpline (values y_i and those slopes).
/// λ_i = 0 is an infinitely stiff spring (y_i = a_i); λ = 0 everywhere gives the interpolating spline
/// of eq (23). Several value columns (y and z of a space curve, x and y of a parametric curve) are
/// smoothed independently with the same λ.
///
/// Preconditions (InvalidInput otherwise): ≥ 2 strictly increasing finite abscissae, one finite value
/// row per abscissa, λ_i finite and ≥ 0 (one per abscissa, or one for all).
#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/core/points.hpp"
#include "cagd/spline/hosaka_spline.hpp"

namespace cagd::smoothing {

/// Hosaka's elastic line (eq 50–52): the smoothed curve and its second derivatives at the abscissae.
struct ElasticLine {
    spline::ExplicitSpline curve;        ///< eq (52): values y_i, slopes y'_i at the abscissae
    Eigen::MatrixXd second_derivatives;  ///< M_i = y''_i, one row per abscissa (zero at both ends)
    /// The abscissae.
    const std::vector<double>& x() const { return curve.x; }
    /// The smoothed values y_i, one row per abscissa.
    const Eigen::MatrixXd& values() const { return curve.values; }
};

/// Eq (50)–(52): the five-term system (51) solved directly.
ElasticLine elastic_line(const std::vector<double>& x, const Eigen::MatrixXd& a, const std::vector<double>& lambda);
/// The same with one λ for every point.
ElasticLine elastic_line(const std::vector<double>& x, const Eigen::MatrixXd& a, double lambda);

/// The paper's iteration (text after eq 51): start from λ = 0 (the three-term spline system for M),
/// then repeatedly solve R M^{(k+1)} = 6 Qᵀ a − 6 Qᵀ Λ Q M^{(k)} (the λ terms of (51) moved to the
/// right with the previous iterate). It converges exactly when the spectral radius ρ of
/// 6 R⁻¹ Qᵀ Λ Q is below 1, i.e. for λ small against the cube of the spacing (for equal spacing l
/// and equal λ, ρ → 48 λ / l³ · (1 − O(1/n²)), the highest-frequency mode). `contraction` is the
/// observed ratio of successive corrections (an estimate of ρ). Outcome no_convergence when the
/// correction has not fallen below `tolerance` · max |M| after `max_iterations`, or grows.
struct ElasticLineIteration {
    ElasticLine line;          ///< the last iterate
    Outcome outcome;           ///< ok, or no_convergence (see above)
    int iterations = 0;        ///< iterations done
    double contraction = 0.0;  ///< observed ratio of successive corrections
};
/// The iteration above.
ElasticLineIteration elastic_line_iterative(const std::vector<double>& x, const Eigen::MatrixXd& a,
                                            const std::vector<double>& lambda, double tolerance = 1e-14,
                                            int max_iterations = 10000);

/// Smoothing a parametric curve (2-D or 3-D points): x(t), y(t) (, z(t)) each smoothed as above
/// over the chord-length parameter t_0 = 0, t_i = t_{i−1} + |P_i − P_{i−1}| (consecutive points
/// must differ). The returned line's x() are the t_i.
ElasticLine elastic_line_parametric(const PointList& points, const std::vector<double>& lambda);
/// The chord-length parameters t_i of the points (InvalidInput naming `who` for repeated consecutive points).
std::vector<double> chord_parameters(const PointList& points, const char* who);

/// The second, independent formulation (eq 44–49): V of eq (44) minimised directly over the
/// piecewise cubic Hermite curve (45) with unknowns (y_i, y'_i) at every abscissa (one value column).
/// ∫y''² is the exact quadratic form of eq (46) (Gauss–Legendre, exact for the degree); springs
/// w_i = 1/λ_i (λ_i = 0: the point is fixed). Constraints by Lagrange multipliers (text after eq 44):
/// fixed values y(x_j) = c_j and fixed end slopes y'(x_0), y'(x_n). The stationarity conditions are
/// (48) and (49): without slope constraints the minimiser is C2 and equals elastic_line's curve.
/// Solved as one sparse KKT system (Eigen SparseLU).
struct ElasticLineConstraints {
    std::vector<std::pair<int, double>> fixed_values;  ///< (index j, c_j): y(x_j) = c_j
    std::optional<double> start_slope;                 ///< y'(x_0), if fixed
    std::optional<double> end_slope;                   ///< y'(x_n), if fixed
};
/// The minimiser of eq (44) over the Hermite curve (45), with its Lagrange multipliers.
struct HermiteElasticLine {
    spline::ExplicitSpline curve;  ///< values y_i and slopes y'_i
    Eigen::VectorXd multipliers;  ///< one Lagrange multiplier per constraint: fixed values (λ_i = 0 points first, then
                                  ///< fixed_values), then slopes
    double energy = 0.0;          ///< V / EI at the minimiser
};
/// The formulation above (one value column).
HermiteElasticLine elastic_line_hermite(const std::vector<double>& x, const Eigen::VectorXd& a,
                                        const std::vector<double>& lambda,
                                        const ElasticLineConstraints& constraints = {});

/// V / EI = ½ Σ (y_i − a_i)² / λ_i + ½ ∫ y''² dx of a curve through the abscissae (terms with λ_i = 0
/// are left out: those points are constrained), column `column` of the curve's values.
double elastic_line_energy(const spline::ExplicitSpline& curve, const Eigen::VectorXd& a,
                           const std::vector<double>& lambda, int column = 0);

/// Inflections of the smoothed y(x): y'' is linear between abscissae, so they are the sign changes
/// of the node values M_i (values below 1e-12 · max |M| count as zero and are skipped).
int inflection_count(const ElasticLine& line, int column = 0);

/// The natural spline's matrices as dense matrices (for checks and small problems): R, the
/// (n−1) × (n−1) C2 matrix (l_i, 2(l_i + l_{i+1}), l_{i+1}) for the interior M, and Q, the (n+1) × (n−1)
/// second-difference matrix ((Q M)_i = δ²M_i). Then RM = 6Qᵀy and ∫y''² dx = 6 yᵀ Q R⁻¹ Qᵀ y.
struct SplineMatrices {
    Eigen::MatrixXd r;  ///< R, (n−1) × (n−1)
    Eigen::MatrixXd q;  ///< Q, (n+1) × (n−1)
};
/// R and Q for the abscissae x.
SplineMatrices natural_spline_matrices(const std::vector<double>& x);

/// λ given once for all points, expanded to one per abscissa; validated (finite, ≥ 0).
std::vector<double> per_point_lambda(const std::vector<double>& lambda, std::size_t count, const char* who);

}  // namespace cagd::smoothing
