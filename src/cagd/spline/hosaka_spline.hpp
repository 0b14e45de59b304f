#pragma once
/// @file
/// Hosaka's curves from end derivatives and his C2 spline through points (hosaka section 3,
/// eq 15–20, with the journal's erratum to eq 18 applied: k_{i+1} → k_i).
///
/// A segment (eq 15): R(t) = Σ_{i=0}^{m} { R_0^{(i)} p_i(m, t) + R_1^{(i)} q_i(m, t) }, t ∈ [0, 1],
/// R_j^{(i)} the i-th t-derivative at the start (j = 0) and end (j = 1). HosakaCurve joins K such
/// segments on u ∈ [0, K] (segment s on [s, s+1]); any dimension, any m ≥ 0.
///
/// The C2 spline (m = 1; eq 16–20). Segment i (i = 1..n, from P_{i−1} to P_i) is
/// R_i(t) = P_{i−1} + A_i f(t) + B_i g(t) + C_i h(t) with A_i = P_i − P_{i−1} (the chord), B_i, C_i
/// the end tangents (eq 16, 17). Curvature continuity at the joins (eq 18, corrected):
///     R_i'(1) = k_i R_{i+1}'(0),  R_i''(1) = k_i² R_{i+1}''(0),  k_i = |A_i| / |A_{i+1}|   (19)
/// gives C_i = k_i B_{i+1} and the three-term recurrence (eq 20)
///     B_i + 2k_i(1 + k_i) B_{i+1} + k_i² k_{i+1} B_{i+2} = 3(A_i + k_i² A_{i+1}).
/// With (19) the joins are C2 in the chord-length parameter, so this is the chord-length cubic
/// spline written in Hosaka's form (tested); `HosakaScale::unit` (k_i = 1, the "conventional" form
/// the paper criticises) is the uniform-parameter cubic spline.
/// Unknowns B_1..B_n and C_n: a tridiagonal system (row per join, one per end), solved by the
/// Thomas algorithm in O(n) (numeric/tridiagonal.hpp; stable: diagonally dominant after scaling the
/// unknowns by |A_i|); a closed curve's cyclic system by Eigen SparseLU (natural ordering). End conditions: natural
/// (R'' = 0 at both ends: 2B_1 + k_1 B_2 = 3A_1 and B_n + 2C_n = 3A_n), tangent (B_1, C_n given), closed (the
/// recurrence wraps round; k_n = |A_n|/|A_1|). Preconditions (InvalidInput): ≥ 2 points open (≥ 3 closed), 1–3
/// coordinates, finite, no coincident consecutive points (k_i would be 0 or ∞); tangent ends need two finite vectors of
/// the points' dimension.
#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/points.hpp"
#include "cagd/spline/hosaka_basis.hpp"

namespace cagd::spline {

/// A curve of Hosaka segments of order m on u ∈ [0, K]: segment s on [s, s + 1] is Σ_i p_i(m, t) start_i + q_i(m, t)
/// end_i (eq 15).
class HosakaCurve : public Curve {
public:
    /// start[s], end[s]: (m+1) × dim matrices, row i = the i-th derivative at the segment's start / end.
    HosakaCurve(int m, const std::vector<Eigen::MatrixXd>& start, const std::vector<Eigen::MatrixXd>& end);
    /// The same data stacked: rows s(m+1) .. s(m+1)+m of `start` / `end` belong to segment s.
    HosakaCurve(int m, Eigen::MatrixXd start, Eigen::MatrixXd end);
    /// m.
    int m() const { return basis_.m(); }
    /// K, the number of segments.
    int segments() const { return static_cast<int>(start_.rows()) / (m() + 1); }
    /// The m + 1 derivatives (rows) at the start of segment s.
    Eigen::MatrixXd start_derivatives(int s) const { return start_.middleRows(s * (m() + 1), m() + 1); }
    /// The m + 1 derivatives (rows) at the end of segment s.
    Eigen::MatrixXd end_derivatives(int s) const { return end_.middleRows(s * (m() + 1), m() + 1); }

    int dimension() const override { return static_cast<int>(start_.cols()); }
    double t_min() const override { return 0.0; }
    double t_max() const override { return segments(); }
    void evaluate_jet(double u, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const override;
    std::vector<double> breakpoints() const override;
    int polynomial_degree() const override { return 2 * m() + 1; }  ///< p_i(m, t), q_i(m, t) are of degree 2m + 1
    /// Row k: the k-th derivative of segment s at its local t ∈ [0, 1] (one-sided at the joins).
    Eigen::MatrixXd segment_jet(int s, double t, int order) const;

private:
    HosakaBasis basis_;
    Eigen::MatrixXd start_, end_;  ///< stacked, (m+1) rows per segment
    void validate() const;
};

/// The scale factors k_i of eq (19): chord (|A_i|/|A_{i+1}|) or unit (k_i = 1).
enum class HosakaScale { chord, unit };
/// The end condition: natural (vanishing higher derivatives) or given end tangents.
enum class HosakaEnd { natural, tangent };

/// The options of Hosaka's splines.
struct HosakaSplineOptions {
    HosakaScale scale = HosakaScale::chord;  ///< scale factors k_i
    HosakaEnd end = HosakaEnd::natural;      ///< end condition
    bool closed = false;                     ///< closed curve (periodic)
    Eigen::VectorXd start_tangent;           ///< B_1 for HosakaEnd::tangent
    Eigen::VectorXd end_tangent;             ///< C_n for HosakaEnd::tangent
};

/// Hosaka's C2 spline (eq 18–20): the curve and the quantities of its construction.
struct HosakaSpline {
    HosakaCurve curve;      ///< the curve, one segment per data span
    std::vector<double> k;  ///< k_i, one per join (closed: per segment, wrapping)
    Eigen::MatrixXd B;      ///< B_i of eq (20), one row per segment
    Eigen::MatrixXd C;      ///< C_i of eq (20), one row per segment
    /// dτ/dt of each segment: |A_i| (chord scale, as chord_lengths computes it) or 1 (unit scale).
    std::vector<double> span_lengths;
};

/// The C2 spline of eq (18)–(20) through the points; InvalidInput for fewer than 2 points (3 closed) or repeated
/// consecutive points.
HosakaSpline hosaka_c2_spline(const PointList& points, const HosakaSplineOptions& options = {});
/// The same through points validated already (options.closed as they were validated): the same
/// curve, the points not checked again where their checks cover this construction's.
HosakaSpline hosaka_c2_spline(const ValidPoints& points, const HosakaSplineOptions& options);

/// Higher order (end of section 3: "in general derivatives up to order 2m can be joined
/// continuously"): the spline of m-th order segments (eq 15) through points whose derivatives up to
/// order 2m are continuous in the global parameter τ (dτ = |A_i| dt on segment i with the chord
/// scale of eq 19, dτ = dt with the unit scale). Unknowns: the τ-derivatives of orders 1..m at every
/// point (segment i's end data are |A_i|^j times them); equations: continuity of the τ-derivatives
/// of orders m+1..2m at every interior point, and at open ends the natural conditions that those
/// derivatives vanish (for m = 1: R'' = 0, the spline of eq 20); closed curves wrap round. Solved with
/// Eigen SparseLU. m = 1 gives hosaka_c2_spline's curve (tested).
/// Tangent ends (open curves): the first derivative at each end is given, as a derivative in the end
/// segment's own parameter t (as B_1, C_n of eq 20), and the natural conditions keep orders m+1..2m−1
/// zero — the end conditions of the variational problem min ∫ |R^{(m+1)}(τ)|² dτ with R' clamped (for
/// m = 1: hosaka_c2_spline's tangent ends, tested).
/// The τ-derivatives are solved in units of λ = 2^e, the mean chord in [λ/2, λ) (τ = λσ): the
/// system's entries (chord/λ)^{j−k}, 1 ≤ j ≤ m < k ≤ 2m, stay near 1 at any scale of the points
/// (tested from 1e-150 to 1e150). Accuracy: m ≤ 3 gives the same curve at every scale to rounding;
/// the system grows ill-conditioned with m (at m = 6 two scales of Newbery–Garrett's points give
/// curves 8e-4 apart in the data's units).
/// Preconditions: as hosaka_c2_spline, m ≥ 1, ≥ 2 points open (≥ 3 closed).
/// Outcome no_solution (no curve) when the system is singular in double precision: chords of very
/// different lengths at a high order (entries (chord/λ)^{1−2m} beyond the range of double).
struct HosakaSplineFit {
    Outcome outcome;                   ///< ok, or no_solution (see above)
    std::optional<HosakaCurve> curve;  ///< the spline, when ok
};
/// The spline of order m through the points with the given scale, open or closed (see above).
HosakaSplineFit hosaka_spline(const PointList& points, int m, HosakaScale scale = HosakaScale::chord,
                              bool closed = false);
/// The spline of order m (continuous to order 2m) through the points, with the given options.
HosakaSplineFit hosaka_spline(const PointList& points, int m, const HosakaSplineOptions& options);
/// The same through points validated already (options.closed as they were validated): the same
/// curve, the points not checked again where their checks cover this construction's.
HosakaSplineFit hosaka_spline(const ValidPoints& points, int m, const HosakaSplineOptions& options);

/// The explicit form y(x), z(x) (eq 21–23): on [x_{i−1}, x_i] with u = (x − x_{i−1})/l, l = x_i − x_{i−1},
///     (y, z)(x) = Σ_{j=0}^{1} { (y, z)_{i−1}^{(j)} p_j(1, u) + (y, z)_i^{(j)} q_j(1, u) } l^j      (21, 22)
/// with the slopes y'_i from the C2 conditions at the interior abscissae,
///     y'_{i−1}/h_{i−1} + 2(1/h_{i−1} + 1/h_i) y'_i + y'_{i+1}/h_i = 3 (y_i − y_{i−1})/h_{i−1}² + 3 (y_{i+1} −
///     y_i)/h_i²
/// (eq 23 with the squares the printed right-hand side lacks: erratum hosaka-E4), h_i = x_{i+1} − x_i,
/// and natural ends y'' = 0 (2y'_0 + y'_1 = 3(y_1 − y_0)/h_0, y'_{n−1} + 2y'_n = 3(y_n − y_{n−1})/h_{n−1}).
/// Each column of `values` (y, or y and z) is one function of x. This curve minimises
/// ∫ (y''² + z''²) dx among interpolants (eq 24; checked by perturbation in the experiment).
/// Preconditions: strictly increasing finite abscissae, ≥ 2 of them, one value row per abscissa.
struct ExplicitSpline {
    std::vector<double> x;   ///< the abscissae x_0 < … < x_n
    Eigen::MatrixXd values;  ///< the values at the abscissae, one row per abscissa
    Eigen::MatrixXd slopes;  ///< the x-derivatives at the abscissae, one row per abscissa
    /// k-th x-derivative (k ≤ 3) at x ∈ [x_0, x_n] (InvalidInput outside); at an interior abscissa
    /// the interval to its right is used.
    Eigen::RowVectorXd evaluate(double at, int k = 0) const;
    /// The same on interval i = [x_i, x_{i+1}] at its local u ∈ [0, 1] (one-sided limits at the joins).
    Eigen::RowVectorXd evaluate_in(int interval, double u, int k = 0) const;
    double bending_energy() const;  ///< Σ over columns of ∫ (d²/dx²)² dx, exact (y'' is linear per interval)
};
/// The explicit spline through (x_i, values_i) with natural ends, columns interpolated independently (eq 21–23).
ExplicitSpline hosaka_explicit_spline(const std::vector<double>& x, const Eigen::MatrixXd& values);

}  // namespace cagd::spline
