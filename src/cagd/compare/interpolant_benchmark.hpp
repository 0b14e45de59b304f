#pragma once
/// @file
/// The interpolant benchmark as a whole (`cagd benchmark`, `cagd_benchmark_mpi`): what it runs (a
/// plan: the truth runs of truth_benchmark.hpp, the classic data of classic_benchmark.hpp, the
/// random sets of random_sets.hpp), how it splits over processes or MPI ranks, and the files it
/// writes.
///
/// Splitting. Share k of N (work_share.hpp) computes the truth runs, the classic runs and the random
/// sets' tasks whose index is k mod N. Its results travel as a part: a text of every value at full
/// precision (hexadecimal floating point, read back bit for bit), led by the part's number and the
/// plan's fingerprint and closed by a checksum line (core/checksum.hpp):
///   # cagd benchmark part
///   part,K,N                 this part is share K − 1 of N
///   plan,FINGERPRINT         FNV-1a of the plan's text: sizes, families, configurations, random
///                            sets, the classic data (names, closedness, every coordinate) and the
///                            library version; a part of another plan or build is refused
///   units,T,C,R              the whole plan's truth runs, classic runs and random summaries
///   truth,INDEX,…  classic,INDEX,…  random,INDEX,…   one record per computed unit (every random
///                            summary, with the part's own counts)
///   # checksum fnv1a64 DIGITS
/// merge_benchmark_parts takes the N parts in any order and gives exactly the results of one whole
/// run, so the files written from them are byte-identical (the random sets' run times are merged
/// too; they are timings, not compared).
#include <string>
#include <utility>
#include <vector>

#include "cagd/compare/classic_benchmark.hpp"
#include "cagd/compare/random_sets.hpp"
#include "cagd/compare/truth_benchmark.hpp"
#include "cagd/compare/work_share.hpp"

namespace cagd::compare {

/// What one benchmark runs.
struct BenchmarkPlan {
    TruthBenchmarkOptions truth;          ///< the truth runs (its share and threads are set by run_benchmark)
    RandomSetOptions random;              ///< the random sets; random.sets = 0: none
    std::vector<ClassicDataSet> classic;  ///< the classic data sets (empty: none)
};

/// What it computed: every run, or a share's (the others left empty).
struct BenchmarkResults {
    std::vector<TruthRun> truth;           ///< run_truth_benchmark's runs
    std::vector<ClassicRun> classic;       ///< run_classic_benchmark's runs (empty without classic data)
    std::vector<RandomSetSummary> random;  ///< run_random_sets' summaries (empty without random sets)
};

/// The plan's share `share` of the work, on `threads` threads (0: the hardware's).
BenchmarkResults run_benchmark(const BenchmarkPlan& plan, const WorkShare& share = {}, int threads = 0);

/// The plan's fingerprint (16 hexadecimal digits; see above).
std::string benchmark_plan_fingerprint(const BenchmarkPlan& plan);
/// The part text of share `share`'s results (see above).
std::string benchmark_part_text(const BenchmarkPlan& plan, const WorkShare& share, const BenchmarkResults& results);
/// The results of the whole plan from its parts, each (a name for messages, its text). InvalidInput,
/// naming the part and line, when a part is damaged, belongs to another plan or build, comes twice,
/// is missing, holds other counts of records than its units line declares for its share (checked
/// before anything is sized from that line), a record outside its share, or a value that is not
/// finite.
BenchmarkResults merge_benchmark_parts(const BenchmarkPlan& plan,
                                       const std::vector<std::pair<std::string, std::string>>& parts);

/// The deterministic files of results/benchmark/, (name, content), from the whole plan's results:
/// truth_runs.csv, convergence_orders.csv, leaderboard.md, convergence_<family>.dat; with random
/// sets random_sets.csv; with classic data classic_runs.csv and classic.md.
std::vector<std::pair<std::string, std::string>> benchmark_files(const BenchmarkPlan& plan,
                                                                 const BenchmarkResults& results);
/// The random sets' run times as CSV (random_set_timing_header and rows): not deterministic.
std::string benchmark_timing_csv(const BenchmarkResults& results);

}  // namespace cagd::compare
