#pragma once
/// @file
/// The peers against the truths: every subject (curve_subject.hpp; the peers of peer_curves.hpp as
/// `cagd peers` runs them) on the truth benchmark's points (truth_curves.hpp), measured as the
/// registry's configurations are (truth_benchmark.hpp: the errors, the shape measures,
/// extensionality), so that their orders and leaderboard read as the benchmark's. Each family
/// uniform in arc length (the leaderboard's spacing), closed families closed and as open arcs; a
/// subject draws all its cases in one batch, then their extensions in a second.
#include <vector>

#include "cagd/compare/curve_subject.hpp"
#include "cagd/compare/truth_benchmark.hpp"

namespace cagd::compare {

/// The sizes of subject_truth_runs unless told: the benchmark's.
inline const std::vector<int> kPeerTruthSizes{6, 12, 24, 48, 96, 192, 384, 768};

/// Every subject on every family (closed ones also as open arcs), uniform in arc length, at `sizes`
/// points (each 3 … 100000, increasing), measured `threads` runs at once (0: the hardware's; the
/// results do not depend on it): family × closedness × size × subject, in that order. InvalidInput
/// for sizes out of range.
std::vector<TruthRun> subject_truth_runs(const std::vector<CurveSubject>& subjects,
                                         const std::vector<int>& sizes = kPeerTruthSizes, int threads = 0);

}  // namespace cagd::compare
