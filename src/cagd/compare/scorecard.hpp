#pragma once
/// @file
/// The scorecard: the properties Levien names for an interpolating spline (R. Levien, From Spiral to
/// Spline: Optimal Techniques in Interactive Curve Design, PhD thesis, UC Berkeley, 2009:
/// roundness, extensionality, locality, existence) and four more users ask about, each measured as a
/// number for every configuration of the registry and every peer (peer_curves.hpp), on seeded random
/// polygons (with 95 % intervals, numeric/confidence_interval.hpp) and on the classic data.
///
/// The polygons. Polygon s (seed s) has kScorecardPoints points, open: a walk whose chords are
/// uniform in [0.5, 1.5] and whose turns are uniform in [−A, A], one of them (at a random interior
/// point) exactly ±A, A (the largest turning angle) uniform in [30°, 170°].
/// Co-circular sets for roundness: set s has n = 3 + (s mod 62) points (3 … 64) on the unit circle,
/// closed: at angles θ0 + 2π(i + j_i)/n, j_i uniform in [−0.3, 0.3]; open: an arc of Θ uniform in
/// [90°, 300°] at θ0 + Θ(i + j_i)/(n − 1), the two ends without jitter.
///
/// The measures, D the bounding-box diagonal of the points, each curve sampled at 33 equally spaced
/// fractions of each data span's parameter interval (span_samples; "sampled": the largest sample, a
/// lower bound of the supremum):
///   roundness         co-circular sets: the largest sampled | |c| − 1 | (the radial error).
///   extensionality    extension_distance (truth_benchmark.hpp): the point at the middle of the
///                     middle span inserted, the curve drawn again, its largest distance from the old
///                     one ÷ the old one's length (a supremum, refined by Brent's method).
///   locality          point ⌊n/2⌋ moved by δ = 10⁻³ D in a seeded direction: per span, the largest
///                     sampled displacement ÷ δ (its influence); the spans without influence (a
///                     displacement ≤ kZeroInfluence D: exact zero up to rounding) and the largest
///                     influence at each span distance r from the moved point (r = 0 the two spans
///                     beside it).
///   existence         the base curve's failure (no curve: the method's refusal or no result, a peer's
///                     error) against the largest turning angle A.
///   symmetry          the curve of the reversed points against the reversed curve: the largest sampled
///                     distance between span k at fraction f and its mirror span at 1 − f, ÷ D (an upper
///                     bound of the distance between the two curves as sets).
///   similarity        the curve of s R P + t (s = 10^(12u − 6): scales 10^±6; R a seeded rotation, t
///                     = s (a, b), a, b uniform in [−10, 10]) mapped back by the inverse map, against the
///                     curve of P at the same fractions: the largest sampled distance ÷ D.
///   κ-extrema         the κ-curve criterion (Z. Yan, S. Schiller, G. Wilensky, N. Carr, S. Schaefer,
///                     κ-curves: interpolation at local maximum curvature, ACM TOG 36(4) 2017: curvature
///                     maxima only at the points): the spans whose largest sampled |κ| lies strictly
///                     inside, above both ends' by more than the flatness policy (|Δκ| D > 10⁻⁹).
///   fairness          L∫κ² ds and L³∫(dκ/ds)² ds (shape_measures, scale-free), and the G2 defect.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cagd/compare/classic_benchmark.hpp"
#include "cagd/compare/curve_subject.hpp"
#include "cagd/numeric/confidence_interval.hpp"

namespace cagd::compare {

/// Points of each random polygon (see above): enough spans that a point moved in the middle leaves
/// spans untouched on both sides of an S-spline's footprint (2 (m + 2) spans for m = 1, 2, 4).
inline constexpr int kScorecardPoints = 16;
/// A span without influence moved by at most this × D (rounding: the spans after a moved point
/// are evaluated at shifted parameters).
inline constexpr double kZeroInfluence = 1e-12;
/// The moved point's displacement δ ÷ D.
inline constexpr double kLocalityMove = 1e-3;

/// Random polygon `seed` (see above) and its largest turning angle A (radians).
struct ScorecardPolygon {
    PointList points{};         ///< kScorecardPoints rows, planar
    double largest_turn = 0.0;  ///< A
};
/// Polygon `seed` (see above).
ScorecardPolygon scorecard_polygon(unsigned seed);
/// Co-circular set `seed` (see above), closed or an open arc.
PointList co_circular_points(unsigned seed, bool closed);

/// The scores of one subject on one set of points (see above); absent where the curves needed
/// were not drawn.
struct CaseScore {
    AttemptStatus status = AttemptStatus::ok;     ///< the base curve's
    std::string note{};                           ///< why not ok
    std::optional<double> extensionality{};       ///< extension_distance
    std::optional<double> symmetry{};             ///< ÷ D
    std::optional<double> similarity{};           ///< ÷ D
    std::optional<int> spans_moved{};             ///< spans with influence (locality)
    std::optional<int> zero_influence_spans{};    ///< spans without (locality)
    std::vector<double> influence{};              ///< the largest influence at span distance r = 0, 1, …
    std::optional<int> inner_curvature_maxima{};  ///< spans whose |κ| peaks inside (κ-extrema)
    std::optional<double> bending{};              ///< L∫κ² ds
    std::optional<double> variation{};            ///< L³∫(dκ/ds)² ds
    std::optional<double> g2_defect{};            ///< ShapeMeasures::g2_defect
};

/// What run_scorecard runs.
struct ScorecardOptions {
    int polygons = 10000;                   ///< random polygons, and co-circular sets of each kind (≥ 1)
    std::vector<ClassicDataSet> classic{};  ///< the classic data (classic_benchmark.hpp), each as listed
    int threads = 0;                        ///< cases measured at once (0: the hardware's); results do not depend on it
};

/// One subject's scores.
struct SubjectScores {
    std::string subject{};                   ///< its name
    std::string kind{};                      ///< "method" or "peer"
    std::vector<CaseScore> polygons{};       ///< one per random polygon, by seed
    std::vector<double> largest_turns{};     ///< A of each polygon (radians)
    std::vector<DrawnCurve> round_closed{};  ///< the closed co-circular sets' curves' status (interpolant dropped)
    std::vector<DrawnCurve> round_open{};    ///< the open arcs' curves' status (interpolant dropped)
    std::vector<std::optional<double>> roundness_closed{};  ///< radial errors of the closed sets, by seed
    std::vector<std::optional<double>> roundness_open{};    ///< radial errors of the open arcs, by seed
    std::vector<CaseScore> classic{};                       ///< one per classic data set
};
/// Every score of `subject` (see above). InvalidInput for options outside their ranges.
SubjectScores run_scorecard(const CurveSubject& subject, const ScorecardOptions& options);

/// One summary: a property's quantity over the random polygons.
struct ScorecardRow {
    std::string subject{};         ///< the subject
    std::string kind{};            ///< method or peer
    std::string property{};        ///< e.g. symmetry, existence_120_130
    std::string quantity{};        ///< median, q95 or rate (each with its interval), max (no interval), mean
    long sets = 0;                 ///< the polygons (or sets) it is over
    numeric::Estimate estimate{};  ///< the value and its 95 % interval
};
/// The summaries of `scores` (docs/benchmark.md lists them).
std::vector<ScorecardRow> scorecard_rows(const SubjectScores& scores);
/// The summaries as CSV: subject,kind,property,quantity,sets,value,low,high.
std::string scorecard_csv(const std::vector<ScorecardRow>& rows);
/// The classic data's scores as CSV: subject,kind,data_set,closed,status,extensionality,symmetry,
/// similarity,spans_moved,zero_influence_spans,inner_curvature_maxima,bending,variation,g2_defect.
std::string scorecard_classic_csv(const std::vector<SubjectScores>& scores, const std::vector<ClassicDataSet>& sets);
/// The scorecard's page (results/benchmark/scorecard.md): the properties per subject, the failure
/// rates by largest turning angle, the skipped peers (`skipped`: one line each), and the figure.
std::string scorecard_markdown(const std::vector<ScorecardRow>& rows, int polygons,
                               const std::vector<std::string>& skipped);
/// The figure's data (scripts/plot/benchmark_fig_scorecard.gp): per subject with both, the mean spans
/// moved and the median bending, and whether its median G2 defect is 0 to 10⁻⁹ (curvature continuous).
std::string scorecard_figure_data(const std::vector<ScorecardRow>& rows);

}  // namespace cagd::compare
