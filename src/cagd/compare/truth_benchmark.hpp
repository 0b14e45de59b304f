#pragma once
/// @file
/// The interpolant benchmark on data with a truth (`cagd benchmark`): points sampled from the
/// curves of truth_curves.hpp, every configuration of the registry interpolating them, and each
/// curve measured against the curve the points came from.
///
/// Errors of one interpolant (truth_errors), per piece of each data span between the interpolant's
/// breakpoints (κ' may jump at a B-spline peer's knots inside a span), in the interpolant's own
/// parameter; each point q = c(u) is projected onto the truth, T(t*) nearest to q among the spans
/// beside it (the truth sampled at 8 steps per span over the data spans k − 1 … k + 1, wrapping round
/// a closed curve; Newton on (T(t) − q)·T'(t) = 0 from the nearest sample, between its neighbours):
///   distance       sup |q − T(t*)| ÷ the truth's length L
///   tangent angle  the largest angle between c'(u) and T'(t*) over the samples (radians)
///   curvature      sup |κ_c(u) − κ_T(t*)| × L, and the L2 form (∫ (κ_c − κ_T)² ds / L)^(1/2) × L,
///                  ds the interpolant's arc length, L the truth's (planar: signed κ; space: |κ|)
///   length         |L_c − L| / L (adaptive Gauss–Kronrod lengths, analysis/)
/// The L2 integral: 16-point Gauss–Legendre per piece, accepted where the 8-point rule agrees to
/// 1e−6 of it (or to the curvature's rounding level), the piece halved otherwise (at most 10 times).
/// The suprema: the largest of every sample (both rules' nodes and each piece's ends, one-sided), in
/// the 4 pieces of the largest samples refined by Brent's method between the samples beside it (the
/// maximiser to 2^−20 of that bracket, so a smooth maximum's value to about 2^−40 of it). The tests
/// hold both to a dense computation: at least every one of 128 equally spaced samples per span, and
/// within 1e−3 of their largest.
/// Each is dimensionless, so families and sizes compare.
///
/// Observed order (convergence_orders): from every pair of successive sizes n_k < n_{k+1} whose
/// errors are both above the rounding level (truth_rounding_level), p_k = −log(e_{k+1}/e_k)/log(n_{k+1}/
/// n_k). The published order is the last pair's; it is asymptotic when the pair before it agrees
/// within kAsymptoticBand, and otherwise marked pre-asymptotic, with its pairs. "exact" when a
/// direct method's error is at its rounding level at every size; "solver tolerance" when an
/// iterative method's is at its solver's level at every size. An order is a claim where a theorem
/// predicts it (predicted_orders: the source is named), checked only where it is asymptotic; and
/// otherwise a measurement.
#include <optional>
#include <string>
#include <vector>

#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/compare/truth_curves.hpp"
#include "cagd/compare/work_share.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::compare {

/// The rounding level of error `measure` (truth_error_names() index) at n points: 64 ε for the
/// distance (positions evaluated near the truth: the line's exact reproductions are at 1.4e−16),
/// 64 ε n for the tangent angle and the length (the length's quadrature sums n pieces), 64 ε n² for
/// the two curvature errors (a curvature from second derivatives over spans of length L/n
/// amplifies the positions' rounding by n²). A direct method's error at or below it is rounding;
/// the order's pairs use no error at or below it, for any method.
double truth_rounding_level(int measure, int n);
/// An iterative method's solver level of error `measure` at n points: 1e−13 n for the distance, the
/// tangent angle and the length, 1e−13 n² for the curvature errors. Its Newton stops at a residual
/// of 1e−12 per dimensionless equation (positions relative to their span's chord) or at its rounding
/// level, so its positions can drift along the curve by that much per span.
double truth_solver_level(int measure, int n);
/// The error of `method` in `measure` at n points below which it is not a finding: the rounding
/// level, or for an iterative method (methods::Method::iterative) the larger of it and the solver
/// level. Errors within it of each other rank as ties; an iterative method at or below it at every
/// size is "solver tolerance".
double truth_error_floor(const std::string& method, int measure, int n);
/// Whether `name` is an iterative configuration of the registry (its Method::iterative); false for
/// any other name (a peer's configuration: measured against the rounding level).
bool iterative_configuration(const std::string& name);
/// Successive pair orders agreeing within this make the last one asymptotic.
inline constexpr double kAsymptoticBand = 0.2;

/// The errors of one interpolant against its truth (see above).
struct TruthErrors {
    double distance = 0.0;       ///< max distance to the truth ÷ L
    double tangent_angle = 0.0;  ///< max tangent angle error (rad)
    double curvature_max = 0.0;  ///< max |Δκ| × L
    double curvature_l2 = 0.0;   ///< L2 |Δκ| × L
    double length = 0.0;         ///< |ΔL| / L
};
/// The measure names, in the order of TruthErrors: distance, tangent_angle, curvature_max, curvature_l2, length.
const std::vector<std::string>& truth_error_names();
/// The value of measure `index` (0..4).
double truth_error(const TruthErrors& e, int index);
/// The errors of `interpolant` (through `sample`'s points) against `truth` (see above).
TruthErrors truth_errors(const methods::Interpolant& interpolant, const TruthSample& sample, const Curve& truth);

/// Scale-free shape measures of a curve (L its length), comparable across sizes, libraries and the
/// truth itself; on 16 Gauss nodes per piece of each span between the curve's breakpoints (the
/// integrals by that rule: exact to rounding on polynomial pieces' smooth integrands), and at the
/// pieces' ends (one-sided):
struct ShapeMeasures {
    double bending = 0.0;        ///< L ∫ κ² ds
    double variation = 0.0;      ///< L³ ∫ (dκ/ds)² ds
    double max_curvature = 0.0;  ///< max |κ| · L over the nodes and the pieces' ends
    int curvature_extrema = 0;   ///< sign changes of dκ/ds along the curve (|dκ/ds| L² ≤ 1e-9 counts as 0)
    double g2_defect = 0.0;      ///< max over the interior points (closed: every point) of |κ(u⁺) − κ(u⁻)| · L
    /// Sign changes of the signed κ along the curve (closed: around it), on the Gauss nodes and the
    /// pieces' ends (one-sided), |κ| L ≤ 1e-9 counting as 0; a κ jump through 0 at a G1 join counts.
    /// Space curves: 0 (|κ| has no sign).
    int inflections = 0;
    /// Inflections the polygon through the points does not imply: inflections less the sign changes
    /// of the polygon's turns at its points (the sign of (P_i − P_{i−1}) × (P_{i+1} − P_i); closed: at
    /// every point and around; a turn below 1e-12 rad counting as none), or 0 when that is negative.
    /// A count, not a location: a curve that moves an inflection to the wrong span and has no other
    /// is not caught. Space curves: 0.
    int unimplied_inflections = 0;
};
/// The shape measures of `curve` between consecutive `nodes` (its parameters at the points; closed:
/// the last is the first again). Planar curves: signed κ; space: |κ|. NaN where the speed vanishes.
ShapeMeasures shape_measures(const Curve& curve, const std::vector<double>& nodes, bool closed);
/// The inflections as the leaderboards print them: "k", or "k (+u)" when u of the k are not implied
/// by the polygon; "—" for a space curve (`space`).
std::string inflections_text(const ShapeMeasures& s, bool space);
/// The names of the shape measures, in the order of ShapeMeasures.
const std::vector<std::string>& shape_measure_names();

/// Extensionality (a curve is extensional when adding a point that lies on it leaves it unchanged;
/// Levien 2009 names the property for Spiro): the point c(u*) at the middle of the parameter
/// interval of span ⌊spans/2⌋ of `interpolant` is inserted between that span's points, `configuration`
/// interpolates the n + 1 points again, and the result is the largest distance of the new curve
/// from the old, ÷ the old curve's length (truth_errors' distance with the old curve as the truth). Absent when the
/// method refuses the new points or has no curve for them.
std::optional<double> extensionality(const methods::Configuration& configuration, const PointList& points, bool closed,
                                     const methods::Interpolant& interpolant);
/// The points extensionality() interpolates: `points` with c(u*) inserted after point `span`, u* the
/// middle of the parameter interval of span ⌊spans/2⌋ of `interpolant` (through `points`, open or
/// `closed`). InvalidInput when the interpolant's nodes do not match the points.
struct ExtendedPoints {
    PointList points;        ///< the n + 1 points
    std::size_t span = 0;    ///< the span the point was taken on
    double parameter = 0.0;  ///< u*
};
/// The extended points of `interpolant` (see ExtendedPoints).
ExtendedPoints extended_points(const PointList& points, bool closed, const methods::Interpolant& interpolant);
/// How far `again`, a curve through `extended`'s points, lies from `interpolant`: the largest
/// distance of `again` from it ÷ its length (truth_errors' distance, the old curve as the truth).
/// extensionality() with the new curve drawn by anyone (the scorecard's peers).
double extension_distance(const methods::Interpolant& interpolant, const ExtendedPoints& extended, bool closed,
                          const methods::Interpolant& again);

/// One interpolation of the benchmark.
struct TruthRun {
    std::string family;                            ///< truth family
    TruthSpacing spacing = TruthSpacing::uniform;  ///< where the points are
    bool closed = false;                           ///< closed points
    int n = 0;                                     ///< number of points
    std::string method;                            ///< configuration name
    AttemptStatus status = AttemptStatus::ok;      ///< what became of it (interpolation_attempt.hpp)
    std::string note;                              ///< why not ok
    TruthErrors errors;                            ///< when ok
    ShapeMeasures shape;                           ///< when ok
    ShapeMeasures truth_shape;             ///< the truth's over the same stretch (the same for every method of a case)
    std::optional<double> extensionality;  ///< when ok: how far a point taken on the curve moves it (extensionality())
};

/// Measures `r` (its family, closedness, size and name set; status ok) from its interpolant `in`
/// through `sample` of `truth`: the errors, the shape measures and `extension` (extensionality()),
/// or the status cusp when a measure is not finite (a node of zero speed).
void measure_truth_run(TruthRun& r, const methods::Interpolant& in, const TruthSample& sample, const Curve& truth,
                       std::optional<double> extension);

/// What run_truth_benchmark runs.
struct TruthBenchmarkOptions {
    std::vector<int> sizes{6, 12, 24, 48, 96, 192, 384, 768};  ///< numbers of points (each 3..100000, increasing)
    std::vector<std::string> families;                         ///< empty: every family
    std::vector<std::string> methods;  ///< configuration or method names; empty: every configuration
    int threads = 0;                   ///< cases measured at once (0: the hardware's); results do not depend on it
    WorkShare share;                   ///< the runs computed (by their index in the result); default: all
};
/// InvalidInput (from `who`) unless `sizes` is not empty and increases within 3 … 100000.
void check_truth_sizes(const std::vector<int>& sizes, const char* who);
/// One case of the benchmark: a truth, how its points are spaced, its closedness, their number.
struct TruthCase {
    const TruthFamily* family = nullptr;           ///< the truth
    TruthSpacing spacing = TruthSpacing::uniform;  ///< the spacing of its points
    bool closed = false;                           ///< closed points (a closed truth also runs as an open arc)
    int n = 0;                                     ///< the number of points
};
/// The cases of `families`, in the benchmark's order: each family, closed first where its truth is
/// closed, then open; in each, every spacing of `spacings`; in each, every size of `sizes`.
std::vector<TruthCase> truth_cases(const std::vector<const TruthFamily*>& families,
                                   const std::vector<TruthSpacing>& spacings, const std::vector<int>& sizes);
/// Every family (closed families also as open arcs) × spacing × size × configuration, in that order.
/// With a share of the work, the runs outside it are left empty (TruthRun{}: no method), the others
/// are the values of the whole run.
std::vector<TruthRun> run_truth_benchmark(const TruthBenchmarkOptions& options);

/// A predicted order of convergence, with its source.
struct PredictedOrder {
    std::string method;   ///< configuration
    std::string measure;  ///< one of truth_error_names()
    bool closed;          ///< for closed curves (else open arcs)
    double order;         ///< p
    std::string source;   ///< the theorem
};
/// The orders the literature predicts for configurations of the registry.
const std::vector<PredictedOrder>& predicted_orders();

/// The observed order of one measure of one configuration on one family, spacing and closedness.
/// The regime of an observed order (see above).
enum class OrderRegime {
    asymptotic,      ///< the last two pair orders agree within kAsymptoticBand
    pre_asymptotic,  ///< they do not, or there is one pair only
    exact,           ///< a direct method at its rounding level at every size
    solver_level,    ///< an iterative method at its solver's level at every size
    none             ///< fewer than two sizes above the floor, and not every one at it
};
/// "asymptotic", "pre-asymptotic", "exact", "solver tolerance", "none".
const char* to_string(OrderRegime regime);
/// One pair of successive sizes and the order it gives.
struct PairOrder {
    int n0 = 0;          ///< the smaller size
    int n1 = 0;          ///< the larger size, n1 > n0
    double order = 0.0;  ///< −log(e1/e0)/log(n1/n0)
};
/// The observed order of one measure of one configuration on one truth (see above).
struct ConvergenceOrder {
    std::string family;                            ///< truth family
    TruthSpacing spacing = TruthSpacing::uniform;  ///< where the points are
    bool closed = false;                           ///< closed points
    std::string method;                            ///< configuration
    std::string measure;                           ///< one of truth_error_names()
    std::vector<PairOrder> pairs;                  ///< every successive pair above the floor, in increasing n
    OrderRegime regime = OrderRegime::none;        ///< see above
    std::optional<double> order;                   ///< the last pair's order (asymptotic or pre-asymptotic)
    std::optional<double> predicted;               ///< the predicted order, when there is one
    std::string source;                            ///< its source
};
/// Observed orders of every measure, from the runs (ok runs only; a case with a failed size has none).
std::vector<ConvergenceOrder> convergence_orders(const std::vector<TruthRun>& runs);
/// A predicted order holds when the observed one is within this of it.
inline constexpr double kPredictedOrderTolerance = 0.35;

/// truth_runs.csv's columns: family, spacing, closed, n, method, status, the five errors, the five
/// shape measures, extensionality, the truth's five shape measures, note.
std::vector<std::string> truth_runs_header();
/// One row per run, the errors to `digits` significant digits (empty unless ok).
std::vector<std::vector<std::string>> truth_runs_rows(const std::vector<TruthRun>& runs, int digits = 6);
/// convergence_orders.csv's columns: family, spacing, closed, method, measure, order, regime, pairs
/// ("n0/n1:p" separated by ";"), predicted, verdict (measured, holds, holds (exact), fails, not
/// asymptotic, not measurable), source.
std::vector<std::string> convergence_orders_header();
/// One row per order.
std::vector<std::vector<std::string>> convergence_orders_rows(const std::vector<ConvergenceOrder>& orders);
/// The Markdown leaderboards: per family, every configuration's errors at the largest size
/// (uniform spacing; closed where the family is closed), with the distance order, ranked by the
/// distance, and its shape measures beside the truth's at 24 points; then the exact reproductions
/// and the predicted orders with their verdicts.
std::string truth_leaderboard_markdown(const std::vector<TruthRun>& runs, const std::vector<ConvergenceOrder>& orders);

}  // namespace cagd::compare
