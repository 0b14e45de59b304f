#pragma once
/// @file
/// Every interpolation method on the same planar or space points, measured the same way (`cagd compare`):
///
///   length, enclosed area (closed)   ∫|r'| dt, ½∮(x y' − y x') dt (analysis/curve_measures)
///   pseudo-energy                    Σ_k L_k² E_k over the data spans k (L_k, E_k = ∫κ² ds on span k;
///                                    = Σ l_k J_k, pseudo_energy eq 7, 12, whatever the curve's pieces)
///   bending energy ∫κ² ds, curvature sign changes (inflections; also a
///   κ jump through 0 at a G1 join), max |κ|, max |dκ/ds|, overshoot beyond the data's bounding box
///   (÷ its diagonal)                 analysis/fairness_measures, sampled per piece
///   locality footprint               moving the middle data point P_⌊n/2⌋ by 10⁻³ × diagonal in y
///                                    moves how many spans, a span moving when some sample at the
///                                    same fraction of its parameter interval moves by more than
///                                    10⁻⁹ × diagonal (9 samples per span); an iterative method
///                                    solves for the moved point from its first solution
///                                    (methods::interpolate_from)
///   seconds                          wall time of interpolate() (not deterministic), the
///                                    method's shared tables loaded before (Method::prepare)
///   shared_seconds                   wall time of that Method::prepare, reported on its own
///
/// Space points (3 columns): no enclosed area and no inflections; the largest |τ| instead
/// (analysis/fairness_measures); the figure data are the curves in 3-D and κ(s), τ(s), no combs.
/// A method that does not apply (too few points, closed curves unsupported, 3-D) is listed with
/// the reason; a returned outcome (the curvature-profile Newton) is listed with its message; a curve
/// with a point of zero speed (a cusp: Boost's pchip does this where x and y turn together) has no
/// curvature there, and its κ measures are left empty with that note; a method that throws anything
/// else (a defect) is listed as "failed" with the message. A closed planar curve whose turning
/// number differs from its polygon's, or that is more than 1.5 times the polygon's perimeter, is
/// measured and listed as "loops" with the reason (analysis::closed_curve_anomaly). Nothing is NaN.
/// Sampling: `samples` and `quadrature_pieces` per piece default to 128 and 16, reduced for long
/// inputs so that a method measures about 2·10⁶ samples in all (at least 8 and 2 per piece).
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::compare {

using methods::Interpolant;
using methods::InterpolationResult;

struct MethodComparison;

/// What compare_methods measures and how.
struct ComparisonOptions {
    std::vector<std::string> methods;  ///< configuration or method names (methods::find_configuration); empty: every configuration
    /// Configurations given whole (a method under parameter values of the caller's choice,
    /// methods::find_configuration with overrides); when not empty they are compared instead of `methods`.
    std::vector<methods::Configuration> configurations;
    bool closed = false;  ///< closed curves
    bool locality = true;  ///< measure the locality footprint (it interpolates once more per method)
    /// Compute the measures (length, energies, fairness). Off: the curves only, status "ok" for each
    /// that exists and no measure, for drawing them (the viewer's frames); comparison_figure_data
    /// then leaves out a sample of zero speed (κ undefined) instead of the whole profile.
    bool measures = true;
    /// Called as each method is done (progress), one call at a time, in completion order.
    std::function<void(const MethodComparison&)> on_method;
    /// Methods measured in parallel, one per thread (0: the hardware's thread count). The results,
    /// in the configurations' order, do not depend on it (the `seconds` timings aside).
    int threads = 0;
    /// Continuation (the viewer's drag frames): by configuration name, the solver_state of an earlier
    /// comparison of as many points, open or closed alike; such a configuration's solve starts there
    /// (methods::interpolate_from). Empty: every method builds anew.
    std::map<std::string, Eigen::VectorXd> starts;
};

/// One method's row of the comparison.
struct MethodComparison {
    std::string method;  ///< the configuration's name
    std::string status;  ///< "ok", "not applicable", "refused", "no result", "cusp", "loops", "failed" (AttemptStatus)
    std::string note;    ///< the reason when status is not ok
    std::optional<Interpolant> interpolant;  ///< the curve, when the method applies and succeeds
    Eigen::VectorXd solver_state;  ///< the build's InterpolationResult::solver_state (empty for direct methods)
    double length = 0.0;  ///< arc length
    double area = 0.0;  ///< enclosed area (closed)
    double pseudo_energy = 0.0;  ///< Σ L_k² E_k over the data spans
    std::optional<analysis::FairnessMeasures> fairness;  ///< absent for a cusp
    int spans = 0;  ///< data spans
    std::optional<int> locality_footprint;  ///< spans moved when the middle point moves (absent when not measured)
    double seconds = 0.0;  ///< wall time of interpolate() (not deterministic)
    /// Wall time of Method::prepare before it: the tables the method shares between builds, loaded
    /// from the user's cache or built (not deterministic; about 0 for a method with nothing shared).
    double shared_seconds = 0.0;
};

/// Why a method with these claims does not apply to the points ("open curves only", "needs at least
/// 4 points", "takes at most 2000 points", "planar points only"), or "" when it applies.
std::string method_applicability(const methods::MethodClaims& claims, const PointList& points, bool closed);
/// Samples (8 to 128) and Gauss–Legendre sub-pieces (2 to 512) per piece for a curve of `pieces`
/// pieces: about 2·10^6 of each in all, fewer per piece for long inputs.
analysis::FairnessSampling comparison_sampling(int pieces);
/// The row of `configuration` (a name methods::find_configuration knows); InvalidInput if the name is
/// unknown or the comparison has no such row.
const MethodComparison& find_comparison(const std::vector<MethodComparison>& c, const std::string& configuration);
/// Every configuration (or those named) on the points, in the configurations' order (see above).
std::vector<MethodComparison> compare_methods(const PointList& points, const ComparisonOptions& options);

/// The table: one row per method, numbers to `digits` significant digits, empty where undefined.
/// With timing = false the seconds column is left out (deterministic output).
/// `dimension` 3: the space columns (no area, no inflections, max_abs_torsion).
std::vector<std::string> comparison_header(bool closed, bool timing, int dimension = 2);
/// The table's rows, numbers to `digits` significant digits, empty where undefined.
std::vector<std::vector<std::string>> comparison_rows(const std::vector<MethodComparison>& c, bool closed, bool timing, int digits = 8, int dimension = 2);
/// The table in Markdown.
std::string comparison_markdown(const std::vector<MethodComparison>& c, bool closed, bool timing, int digits = 6, int dimension = 2);

/// Figure data (planar; for space points see above: curves (index, x, y, z), profiles (index, s, κ,
/// τ), no combs). Curve samples (method index, method, x, y), `per_span` per span; the curvature
/// profile (method index, s, κ), `per_span` per span with both ends of every span; the curvature
/// comb (method index, x, y, tooth end x, y), the tooth r − c·κ·n (n the left unit normal), c one
/// scale for every method, such that the 95th percentile of |κ| over all methods' samples draws
/// 10 % of the data diagonal (equal teeth are equal curvature in every panel; a spike shows as a
/// long tooth without flattening the rest). A comb has at most kMaxCombTeeth teeth: every
/// comb_stride-th curve sample of the method (the first and the last always), so that a panel
/// stays readable and cheap to draw however long the input; comb_scale and comb_stride record, per
/// method, the length factor c and that stride (methods.csv prints both).
/// Long inputs: only every `span_stride`-th span is sampled (the arc length s still runs over every
/// span: a span not sampled adds the length the measures integrated, where every node is a
/// breakpoint, else one 20-point Gauss rule's), so a figure of 10^5 spans stays a few MB; figure_sampling(spans, budget) picks per_span
/// (≤ 32) and the stride for at most about `budget` samples per method (a sampled span gives
/// per_span + 1 samples).
struct FigureData {
    std::vector<std::vector<double>> curves;  ///< curve samples (method index, x, y[, z])
    std::vector<std::vector<double>> profiles;  ///< the curvature profiles (method index, s, κ[, τ])
    std::vector<std::vector<double>> combs;  ///< the comb teeth (method index, x, y, tip x, tip y)
    std::vector<double> comb_scale;  ///< per method: c, the tooth length per unit curvature (0: no comb)
    std::vector<int> comb_stride;  ///< per method: a tooth at every comb_stride-th sample (0: no comb)
};
/// The most teeth a method's curvature comb draws.
inline constexpr int kMaxCombTeeth = 1000;
/// How densely the figure data sample a curve.
struct FigureSampling {
    int per_span = 32;  ///< samples per sampled span
    int span_stride = 1;  ///< every span_stride-th span is sampled
    /// How the profiles' arc length s is summed from sample to sample: the 20-point Gauss rule on
    /// each step (quadrature, the figures'), or the trapezoid rule on the samples' own speeds
    /// (trapezoid: no evaluation beyond the samples, a relative error of order (step·κ)²/12, for
    /// interactive drawing; every span must then be sampled, span_stride 1).
    enum class ArcLength { quadrature, trapezoid };
    ArcLength arc_length = ArcLength::quadrature;  ///< the rule for s (see ArcLength)
};
/// per_span and the stride for at most about `budget` samples per method over `spans` spans.
FigureSampling figure_sampling(int spans, int budget);
/// How far each data span of `a` moved in `b` (the same method on the same points but some moved):
/// per span k, the largest distance between the two curves at the same fraction of the span's
/// parameter interval, over `samples_per_span` + 1 equally spaced fractions (the ends included).
/// The locality footprint counts the spans whose distance exceeds its tolerance; the viewer shades
/// every span by it. InvalidInput unless both have the same number of spans and samples_per_span ≥ 1.
std::vector<double> span_displacements(const Interpolant& a, const Interpolant& b, int samples_per_span = 8);
/// The positions span_displacements compares: per data span k, the curve at samples_per_span + 1
/// equally spaced fractions j / samples_per_span of the span's parameter interval, in row
/// k·(samples_per_span + 1) + j. Kept, they let one curve be compared with many (the viewer's
/// anchor of a drag with every frame). InvalidInput unless samples_per_span ≥ 1.
Eigen::MatrixXd span_samples(const Interpolant& a, int samples_per_span = 8);
/// span_displacements from two curves' span_samples taken with the same samples_per_span: per span,
/// the largest distance between corresponding rows. InvalidInput unless both have the same shape, a
/// whole number of spans of samples_per_span + 1 rows.
std::vector<double> span_displacements(const Eigen::MatrixXd& a_samples, const Eigen::MatrixXd& b_samples, int samples_per_span);
/// The figure data of a comparison (see above).
FigureData comparison_figure_data(const std::vector<MethodComparison>& c, const PointList& points, const FigureSampling& sampling);

/// The methods table of the figure data (methods.csv): index, method, and for each of curves,
/// curvature and combs the first data row of that method (0-based after the header) and its row
/// count; then comb_stride and comb_scale (0 for a method without a comb), and the status (as
/// the measures table's, spaces written as '-': one word for the plot script). A method's rows are consecutive, so the plot script reads them with gnuplot's
/// `every ::first::last`, which stops there — filtering whole files per panel costs methods² rows.
std::vector<std::string> figure_methods_header();
/// The rows of methods.csv.
std::vector<std::vector<std::string>> figure_methods_rows(const std::vector<MethodComparison>& c, const FigureData& d);

}  // namespace cagd::compare
