#pragma once
/// @file
/// The benchmark's seeded random point sets (`cagd benchmark`): how often each configuration of the
/// registry gives no curve, and how long a construction takes, over many sets of the same size.
///
/// Two kinds of set, each the same points for the same seed on every platform (std::mt19937):
///   walk     core/random_walk.hpp: chords uniform in [0.1, 2], turns uniform in [−1, 1] rad
///            (data a designer might place: no hairpins);
///   scatter  points uniform in the unit square (any turn, crossings, near-reversals).
/// Set s of a kind and size has seed s (s = 0 … sets − 1). Each configuration interpolates every set
/// as an open curve; the outcome is counted as ok, no result by its returned status — no solution
/// (the method showed that none exists: the curvature-profile Newton's inconsistent conditions, with
/// a rank deficiency or more equations than unknowns), no convergence (the solver failed, which
/// shows nothing about the data), not representable — refused (InvalidInput: the method's own check,
/// e.g. a reversal where no tangent exists) or not applicable (methods::method_applicability). The
/// failure rate is (no result + refused) / (sets − not applicable).
///
/// Run times are wall-clock seconds per construction (methods::interpolate, its input checks
/// included), measured in the worker thread; they vary from run to run and are reported apart from
/// the counts (random_set_timing_rows), which do not depend on the thread count.
#include <string>
#include <vector>

#include "cagd/compare/work_share.hpp"
#include "cagd/core/points.hpp"

namespace cagd::compare {

/// The kinds of random set (see above).
enum class RandomSetKind { walk, scatter };
/// "walk" or "scatter".
const char* to_string(RandomSetKind kind);
/// Set `seed` of `kind` with n points (n ≥ 2).
PointList random_set(RandomSetKind kind, int n, unsigned seed);

/// What run_random_sets runs.
struct RandomSetOptions {
    std::vector<int> sizes{8, 32, 128};  ///< numbers of points (each ≥ 3)
    /// Scattered sets only up to this many points (0: none). Beyond 32 nearly every scattered set
    /// defeats the two Newton methods, and curvature-profile's dense Moore–Penrose fallback on each
    /// failing set would dominate the run.
    int scatter_max_points = 32;
    int sets = 1000;                   ///< sets per kind and size (≥ 1)
    std::vector<std::string> methods;  ///< configuration or method names; empty: every configuration
    int threads = 0;                   ///< sets interpolated at once (0: the hardware's)
    /// The sets interpolated, by task (kind, size, set) in run order: task k = case × sets + set,
    /// the cases in the order below; default: all. A share's summaries count its own sets only
    /// (`sets` too): summed over the shares they are the whole run's (merge_random_sets).
    WorkShare share;
};

/// One configuration on the sets of one kind and size.
struct RandomSetSummary {
    RandomSetKind kind = RandomSetKind::walk;  ///< the kind
    int n = 0;                                 ///< points per set
    std::string method;                        ///< configuration
    int sets = 0;                              ///< sets interpolated
    int ok = 0;                                ///< a curve
    int no_solution = 0;                       ///< no result: Status::no_solution
    int no_convergence = 0;                    ///< no result: Status::no_convergence
    int not_representable = 0;                 ///< no result: Status::not_representable
    int refused = 0;                           ///< InvalidInput from the method
    int not_applicable = 0;                    ///< outside the method's claims
    std::vector<double> seconds;               ///< per construction that ran (ok, no result, refused), in set order
    /// A returned status without a curve: no_solution + no_convergence + not_representable.
    int no_result() const { return no_solution + no_convergence + not_representable; }
    /// (no_result + refused) / (sets − not_applicable); 0 when every set is not applicable.
    double failure_rate() const;
};
/// Every kind × size × configuration, in that order (scattered sets up to scatter_max_points).
std::vector<RandomSetSummary> run_random_sets(const RandomSetOptions& options);
/// Adds `part`'s counts and run times to `total`'s (the same kind × size × configuration, in the
/// same order; std::logic_error otherwise): shares of one run merged.
void merge_random_sets(std::vector<RandomSetSummary>& total, const std::vector<RandomSetSummary>& part);

/// random_sets.csv's columns: kind, n, method, sets, ok, no_solution, no_convergence,
/// not_representable, refused, not_applicable, failure_rate.
std::vector<std::string> random_sets_header();
/// One row per summary (deterministic).
std::vector<std::vector<std::string>> random_sets_rows(const std::vector<RandomSetSummary>& summaries);
/// The timing file's columns: kind, n, method, runs, median_seconds, p90_seconds, max_seconds.
std::vector<std::string> random_set_timing_header();
/// One row per summary: the median, 90th percentile (nearest rank) and largest run time.
std::vector<std::vector<std::string>> random_set_timing_rows(const std::vector<RandomSetSummary>& summaries);
/// A Markdown section: per kind, each configuration's failure rate at every size (configurations
/// that never fail are listed in one line).
std::string random_sets_markdown(const std::vector<RandomSetSummary>& summaries);

}  // namespace cagd::compare
