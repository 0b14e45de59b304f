#pragma once
// The options of the interpolant benchmark that decide what it computes (the plan of
// compare/interpolant_benchmark.hpp), defined once for `cagd benchmark` (benchmark_command.cpp)
// and `cagd_benchmark_mpi` (mpi/benchmark_mpi.cpp), so that a plan split over MPI ranks or over
// processes (--part, --merge) is the plan of one whole run given the same options.
#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cagd/compare/interpolant_benchmark.hpp"
#include "cagd/compare/peer_curves.hpp"
#include "cagd/io/output_file.hpp"

namespace cagd::cli {

struct BenchmarkPlanArgs {
    std::string sizes = "6,12,24,48,96,192,384,768", families, methods, random_sizes = "8,32,128", classic;
    int threads = 0, random_sets = 1000, scatter_max_points = 32;
};

// A comma-separated, increasing list of numbers of points in 3..100000, given to `option`;
// InvalidInput naming the option and the value.
std::vector<int> parse_sizes(const std::string& option, const std::string& text);
// Adds the plan's options (and --threads) to `c`, stored in `a`.
void add_benchmark_plan_options(CLI::App* c, BenchmarkPlanArgs& a);
// The plan of `a`; InvalidInput naming the option and value (before any work).
compare::BenchmarkPlan benchmark_plan(const BenchmarkPlanArgs& a);
// Stages `files` (name, content) in `out` (committed by the caller).
void stage_benchmark_files(OutputDirectory& out, const std::vector<std::pair<std::string, std::string>>& files);

// The manifest of the peers' folder `peers` (its peers.csv), once its launcher `run` is there;
// InvalidInput naming --peers otherwise (`cagd peers`, `cagd scorecard`).
std::vector<compare::PeerConfiguration> peer_manifest(const std::string& peers);
// The launcher of the peers' folder `peers`, with the adapter programs in `programs`, else
// $CAGD_PEER_PROGRAMS, else peers/ beside this executable (the build tree's, where
// peers/CMakeLists.txt puts them).
compare::PeerLauncher peer_launcher(const std::string& peers, const std::string& programs);
// Adds --programs (the folder peer_launcher takes) to `c`, stored in `programs`.
void add_peer_programs_option(CLI::App* c, std::string& programs);

}  // namespace cagd::cli
