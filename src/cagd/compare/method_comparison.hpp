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
/// Peers (ComparisonOptions::peers: other libraries' configurations, run by their adapters,
/// compare/curve_subject.hpp) are measured after the same rules, on their own pieces; a peer draws the
/// points and the moved points (the footprint's) in one run of its adapter, whose wall time, process
/// start included, is its `seconds`. A peer's refusal is its row's "no result" with the peer's message.
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
#include <utility>
#include <vector>

#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/compare/curve_subject.hpp"
#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::compare {

using methods::Interpolant;
using methods::InterpolationResult;

struct MethodComparison;

/// What compare_methods measures and how.
struct ComparisonOptions {
    std::vector<std::string> methods{};  ///< configuration or method names (methods::find_configuration); empty: every
                                         ///< configuration, unless `peers` are given
    /// Configurations given whole (a method under parameter values of the caller's choice,
    /// methods::find_configuration with overrides); when not empty they are compared instead of `methods`.
    std::vector<methods::Configuration> configurations{};
    bool closed = false;   ///< closed curves
    bool locality = true;  ///< measure the locality footprint (it interpolates once more per method)
    /// Compute the measures (length, energies, fairness). Off: the curves only, status "ok" for each
    /// that exists and no measure, for drawing them (the viewer's frames); comparison_figure_data
    /// then leaves out a sample of zero speed (κ undefined) instead of the whole profile.
    bool measures = true;
    /// Called as each method is done (progress), one call at a time, in completion order.
    std::function<void(const MethodComparison&)> on_method{};
    /// Methods measured in parallel, one per thread (0: the hardware's thread count). The results,
    /// in the configurations' order, do not depend on it (the `seconds` timings aside).
    int threads = 0;
    /// Continuation (the viewer's drag frames): by configuration name, the solver_state of an earlier
    /// comparison of as many points, open or closed alike; such a configuration's solve starts there
    /// (methods::interpolate_from). Empty: every method builds anew.
    std::map<std::string, Eigen::VectorXd> starts{};
    /// Peers' configurations (installed_peer_subjects, peer_subject), compared too: their rows follow
    /// the configurations', named as the subjects are ("peer:configuration").
    std::vector<CurveSubject> peers{};
};

/// One method's row of the comparison.
struct MethodComparison {
    std::string method;                        ///< the configuration's name
    bool peer = false;                         ///< a peer's row (ComparisonOptions::peers)
    AttemptStatus status = AttemptStatus::ok;  ///< what became of it (interpolation_attempt.hpp)
    /// The reason when status is not ok; for a peer's curve that approximates the peer's own (a peer
    /// that gives samples only, `approximation`), that bound.
    std::string note;
    /// A peer's row: what made the curve, as its adapter wrote it (empty for a configuration's row).
    std::optional<exports::CurveProvenance> provenance;
    /// A peer's row whose pieces approximate the peer's curve: the adapter's bound on their distance
    /// (DrawnCurve::approximation); every measure is the approximation's.
    std::optional<double> approximation;
    std::optional<Interpolant> interpolant;  ///< the curve, when the method applies and succeeds
    Eigen::VectorXd solver_state;  ///< the build's InterpolationResult::solver_state (empty for direct methods)
    double length = 0.0;           ///< arc length
    double area = 0.0;             ///< enclosed area (closed)
    double pseudo_energy = 0.0;    ///< Σ L_k² E_k over the data spans
    std::optional<analysis::FairnessMeasures> fairness;  ///< absent for a cusp
    int spans = 0;                                       ///< data spans
    std::optional<int> locality_footprint;  ///< spans moved when the middle point moves (absent when not measured)
    double seconds = 0.0;                   ///< wall time of interpolate() (not deterministic)
    /// Wall time of Method::prepare before it: the tables the method shares between builds, loaded
    /// from the user's cache or built (not deterministic; about 0 for a method with nothing shared;
    /// none for a peer, whose `seconds` is its adapter's whole run).
    double shared_seconds = 0.0;
};

/// Per data span k of `a`, the length L_k and bending energy E_k that fairness_measures `f`
/// integrated, summed over its pieces — where every node parameter is a breakpoint (every method
/// but Eigen's spline fits, whose knots average the node parameters); nothing otherwise.
std::optional<std::vector<std::pair<double, double>>> measured_span_integrals(const Interpolant& a,
                                                                              const analysis::FairnessMeasures& f);
/// Samples (8 to 128) and Gauss–Legendre sub-pieces (2 to 512) per piece for a curve of `pieces`
/// pieces: about 2·10^6 of each in all, fewer per piece for long inputs.
analysis::FairnessSampling comparison_sampling(int pieces);
/// The row of `configuration` (a peer's "peer:configuration", or a name methods::find_configuration
/// knows); InvalidInput if the name is unknown or the comparison has no such row.
const MethodComparison& find_comparison(const std::vector<MethodComparison>& c, const std::string& configuration);
/// Every configuration (or those named) on the points, in the configurations' order, then the peers
/// (see above).
std::vector<MethodComparison> compare_methods(const PointList& points, const ComparisonOptions& options);

}  // namespace cagd::compare
