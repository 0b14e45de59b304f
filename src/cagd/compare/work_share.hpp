#pragma once
/// @file
/// One share of the benchmark's indexed work, for splitting it over processes or MPI ranks: share
/// `index` of `count` owns the units k with k mod count = index (round robin, so every share gets
/// small and large cases alike). Each unit is computed on its own, so the shares together give
/// exactly the values of one whole run (compare/interpolant_benchmark.hpp merges them).
#include <string>

namespace cagd::compare {

/// Share `index` of `count` (0 ≤ index < count); the default is the whole work.
struct WorkShare {
    int index = 0;  ///< this share, 0 … count − 1
    int count = 1;  ///< how many shares the work is split into (≥ 1)
    /// Whether unit `unit` belongs to this share.
    bool owns(long unit) const { return unit % count == index; }
    /// Whether this is the whole work.
    bool whole() const { return count == 1; }
};
/// InvalidInput naming `who` unless 1 ≤ share.count and 0 ≤ share.index < share.count.
void check_work_share(const WorkShare& share, const char* who);

}  // namespace cagd::compare
