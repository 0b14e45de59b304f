#pragma once
/// @file
/// The identity table: interpolants that claim to draw the same curve, and some that should not,
/// measured against each other on the benchmark's classic data (`cagd peers`, results/benchmark/).
///
/// The measure. Two curves of K pieces each, piece i of both between data points i and i + 1, are
/// compared piece by piece as polynomials in their own local parameter w ∈ [0, 1]: the breaks do not
/// matter, since an affine change of a piece's parameter leaves its Bézier points as they are. Both
/// pieces raised to a common degree (exactly), their difference is a Bézier curve whose control
/// points are the differences D_k, so by the convex hull property
///   max_k |D_k|  ≥  sup_w |a_i(w) − b_i(w)|  ≥  max_{j = 0..64} |Σ_k B_k(j/64) D_k|,
/// and the supremum over the curve lies between the sampled value and the bound. Both are divided by
/// the diagonal of the points' bounding box. Curves of different piece counts are not comparable
/// this way, nor an open curve with no piece between the ones left out at its ends, nor a peer's
/// samples; the row says so. Where they differ is counted too: the pieces whose bound exceeds
/// kIdentityTolerance, and how far the farthest of them lies from the nearest end (open) or from the
/// seam (closed), in pieces: 0 for the end pieces themselves.
///
/// A claim (reference/benchmark/peer_identities.csv: left, right, closed, ends, expected, reason)
/// names two sides, each a peer's configuration ("gsl:cspline", compare/peer_curves.hpp) or one of the
/// registry's ("cagd:cubic-b"), and what is expected: `identical` holds when every bound is at most
/// kIdentityTolerance; `differs` is confirmed when some sampled difference exceeds it, and its
/// reason explains the difference. `ends` pieces at each end of an open curve are left out of the
/// comparison (the same interior, where the ends follow different conventions).
#include <string>
#include <vector>

#include "cagd/compare/classic_benchmark.hpp"
#include "cagd/compare/peer_curves.hpp"
#include "cagd/export/bezier_form.hpp"

namespace cagd::compare {

/// Identical to this, relative to the points' diagonal: a few hundred ε, the rounding of two
/// different solves of the same spline (elimination orders, the adapters' text at 17 digits).
inline constexpr double kIdentityTolerance = 1e-12;

/// The difference of two piecewise curves (see above).
struct PieceDifference {
    std::string incomparable{};  ///< why they cannot be compared piece by piece (empty when measured)
    double sampled = 0.0;        ///< the largest sampled difference ÷ scale: a lower bound of the supremum
    double bound = 0.0;          ///< the largest control-point difference ÷ scale: an upper bound
    int compared = 0;            ///< the pieces compared
    int over = 0;                ///< the pieces whose bound exceeds kIdentityTolerance
    int farthest = -1;           ///< the farthest of those from an end or the seam, in pieces (−1: none)
};
/// `a` against `b`, divided by `scale` > 0, leaving out `ends` pieces at each end (see above).
PieceDifference piecewise_difference(const exports::BezierPieces& a, const exports::BezierPieces& b, double scale,
                                     int ends = 0);

/// One claim (see above).
struct IdentityClaim {
    std::string left{};     ///< "peer:configuration" or "cagd:configuration"
    std::string right{};    ///< the other side, the same way
    bool closed = false;    ///< measured on the closed data sets (else the open ones)
    int ends = 0;           ///< pieces left out at each end (open curves only)
    bool identical = true;  ///< expected: identical (else: differs)
    std::string reason{};   ///< why the two should agree, or differ
};
/// The claims of `path`; InvalidInput naming path:line for a bad row.
std::vector<IdentityClaim> read_identity_claims(const std::string& path);

/// A peer as the run found it.
struct PeerStatus {
    std::string peer;        ///< its folder
    bool installed = false;  ///< false: skipped
    std::string version{};   ///< its adapter's --version line
    std::string reason{};    ///< why it was skipped, or why its run failed (empty otherwise)
};
/// One claim on one data set.
struct IdentityMeasure {
    std::size_t claim = 0;         ///< index into the claims
    std::string data_set{};        ///< ClassicDataSet::name
    std::string failure{};         ///< a side without a curve ("left: …"), or why not comparable; empty when measured
    PieceDifference difference{};  ///< when measured
};
/// What a run of the identity table found.
struct IdentityResults {
    std::vector<PeerStatus> peers;          ///< every peer of the manifest, in its order
    std::vector<IdentityMeasure> measures;  ///< per claim, per data set of its closedness
};
/// Every claim on every classic data set of its closedness: each peer run once on all its requests.
/// InvalidInput for a claim naming a configuration that is neither in `manifest` nor in the registry.
IdentityResults measure_identities(const std::vector<IdentityClaim>& claims, const std::vector<ClassicDataSet>& sets,
                                   const std::vector<PeerConfiguration>& manifest, const PeerLauncher& launcher);

/// peer_identities.csv: one row per measure.
std::string identity_measures_csv(const std::vector<IdentityClaim>& claims, const IdentityResults& results);
/// peers.md: the peers (version and configurations; those skipped, and why) and the identity table
/// (per claim: the largest differences, where they lie and the verdict).
std::string peers_markdown(const std::vector<IdentityClaim>& claims, const std::vector<PeerConfiguration>& manifest,
                           const IdentityResults& results);

}  // namespace cagd::compare
