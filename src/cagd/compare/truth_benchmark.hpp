#pragma once
/// @file
/// The interpolant benchmark on data with a truth (`cagd benchmark`): points sampled from the
/// curves of truth_curves.hpp, every configuration of the registry interpolating them, and each
/// curve measured against the curve the points came from.
///
/// Errors of one interpolant (truth_errors), on 16 Gauss–Legendre nodes in the interpolant's own
/// parameter on every span (8 left the curvature's L2 3 % low on 9 points of the ellipse); each node q = c(u) is
/// projected onto the truth, T(t*) nearest to q (Newton on (T(t) − q)·T'(t) = 0 from the truth parameter at the same
/// fraction of the span, clamped to the sampled stretch):
///   distance       max |q − T(t*)| over the nodes (a sample of the maximum: the tests find it
///                  within 5 % of 65 equally spaced samples per span), ÷ the truth's length L
///   tangent angle  max angle between c'(u) and T'(t*) (radians)
///   curvature      max |κ_c(u) − κ_T(t*)| × L, and the L2 form (∫ (κ_c − κ_T)² ds / L)^(1/2) × L
///                  over the interpolant's arc length (planar: signed κ; space: |κ|)
///   length         |L_c − L| / L (adaptive Gauss–Kronrod lengths, analysis/)
/// Each is dimensionless, so families and sizes compare.
///
/// Observed order (convergence_orders): p = −log(e_2/e_1)/log(n_2/n_1) from the two largest sizes
/// whose error is above truth_exact_level(n) (smaller sizes are before the asymptotic regime: the
/// slope fitted over 6..96 mixes regimes); "exact" when no size is above it, none when only one is. An order is a claim
/// where a theorem predicts it (predicted_orders: the source is named) and otherwise a measurement.
#include <optional>
#include <string>
#include <vector>

#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/compare/truth_curves.hpp"
#include "cagd/compare/work_share.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::compare {

/// Errors at or below truth_exact_level(n) are rounding: the curve reproduces the truth. The
/// level grows with n: the iterative methods stop at 1e−12 of the largest chord per equation, and
/// their positions drift by about that per span along the curve (the clothoid spline on a circle of
/// 768 non-uniform points: 3.7e−11 of its length; 1e−16 at 6 points).
inline constexpr double kTruthExactLevelPerPoint = 1e-13;
/// kTruthExactLevelPerPoint × n.
inline double truth_exact_level(int n) { return kTruthExactLevelPerPoint * n; }

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
/// truth itself; on the 16 Gauss nodes per span of truth_errors (the integrals by that rule):
struct ShapeMeasures {
    double bending = 0.0;        ///< L ∫ κ² ds
    double variation = 0.0;      ///< L³ ∫ (dκ/ds)² ds
    double max_curvature = 0.0;  ///< max |κ| · L
    int curvature_extrema = 0;   ///< sign changes of dκ/ds along the curve (|dκ/ds| L² ≤ 1e-9 counts as 0)
    double g2_defect = 0.0;      ///< max over the interior points (closed: every point) of |κ(u⁺) − κ(u⁻)| · L
    /// Sign changes of the signed κ along the curve (closed: around it), on the Gauss nodes and the
    /// spans' ends (one-sided), |κ| L ≤ 1e-9 counting as 0; a κ jump through 0 at a G1 join counts.
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
/// from the old, ÷ the old curve's length (truth_errors' distance with the old curve as the truth;
/// 16 Gauss nodes per span). Absent when the method refuses the new points or has no curve for them.
std::optional<double> extensionality(const methods::Configuration& configuration, const PointList& points, bool closed,
                                     const methods::Interpolant& interpolant);

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

/// What run_truth_benchmark runs.
struct TruthBenchmarkOptions {
    std::vector<int> sizes{6, 12, 24, 48, 96, 192, 384, 768};  ///< numbers of points (each ≥ 3)
    std::vector<std::string> families;                         ///< empty: every family
    std::vector<std::string> methods;  ///< configuration or method names; empty: every configuration
    int threads = 0;                   ///< cases measured at once (0: the hardware's); results do not depend on it
    WorkShare share;                   ///< the runs computed (by their index in the result); default: all
};
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
struct ConvergenceOrder {
    std::string family;                            ///< truth family
    TruthSpacing spacing = TruthSpacing::uniform;  ///< where the points are
    bool closed = false;                           ///< closed points
    std::string method;                            ///< configuration
    std::string measure;                           ///< one of truth_error_names()
    std::optional<double> order;                   ///< p, from the two largest sizes above truth_exact_level(n)
    bool exact = false;                            ///< every size at or below truth_exact_level(n)
    int sizes_fitted = 0;                          ///< sizes in the fit
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
/// convergence_orders.csv's columns: family, spacing, closed, method, measure, order, exact,
/// sizes_fitted, predicted, verdict (measured, holds, holds (exact), fails, not measurable), source.
std::vector<std::string> convergence_orders_header();
/// One row per order.
std::vector<std::vector<std::string>> convergence_orders_rows(const std::vector<ConvergenceOrder>& orders);
/// The Markdown leaderboards: per family, every configuration's errors at the largest size
/// (uniform spacing; closed where the family is closed), with the distance order, ranked by the
/// distance, and its shape measures beside the truth's at 24 points; then the exact reproductions
/// and the predicted orders with their verdicts.
std::string truth_leaderboard_markdown(const std::vector<TruthRun>& runs, const std::vector<ConvergenceOrder>& orders);

}  // namespace cagd::compare
