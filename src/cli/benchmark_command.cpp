// `cagd benchmark --out DIR [--sizes 6,12,24,48,96] [--families F,…] [--methods M,…] [--threads N]`:
// the interpolant benchmark on data with a truth (compare/truth_benchmark.hpp). DIR receives, as a
// whole or not at all:
//   truth_runs.csv          one row per family × closedness × spacing × size × configuration
//   convergence_orders.csv  the observed order of every measure, with the predicted ones
//   leaderboard.md          per family the ranking at the largest size, exact reproductions, predictions
//   convergence_<family>.dat  the distance against n per configuration (uniform spacing; closed where
//                           the family is), one gnuplot index block per configuration, its first
//                           line naming it (scripts/plot/benchmark_fig_convergence.gp draws them)
//   random_sets.csv         per kind × size × configuration, the outcomes on --random-sets seeded
//                           random sets (compare/random_sets.hpp); leaderboard.md gets their failure rates
//   classic_runs.csv, classic.md  with --classic MANIFEST: every configuration on the classic data
//                           sets (compare/classic_benchmark.hpp); leaderboard.md gets a summary
// Deterministic: no timing in DIR. The random sets' run times (median, 90th percentile, largest per
// configuration) go to --timing-out FILE when given. Progress on stderr when it is a terminal.
//
// Split over processes (compare/interpolant_benchmark.hpp): `--part K/N --out FILE` computes share K
// of N of the same options' work and writes it as a part file; `--merge FILE… --out DIR` (the same
// options) writes DIR from the N parts, byte for byte what one whole run writes. cagd_benchmark_mpi
// does both on MPI ranks. The plan's options are defined in benchmark_options.cpp for both.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <system_error>

#include "cagd/compare/interpolant_benchmark.hpp"
#include "cagd/core/errors.hpp"
#include "cli/benchmark_options.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

// A part file is read whole; larger than this it is not one (the whole default benchmark's parts
// hold a few MB together).
constexpr std::uintmax_t kMaxPartBytes = std::uintmax_t{1} << 30;

struct BenchmarkArgs {
    BenchmarkPlanArgs plan;
    std::string out, timing_out, part;
    std::vector<std::string> merge;
};

// "K/N" with 1 ≤ K ≤ N ≤ 4096: share K − 1 of N.
compare::WorkShare parse_part(const std::string& text) {
    const std::size_t slash = text.find('/');
    int k = 0, n = 0;
    bool good = slash != std::string::npos;
    if (good) {
        try {
            std::size_t used_k = 0, used_n = 0;
            k = std::stoi(text.substr(0, slash), &used_k);
            n = std::stoi(text.substr(slash + 1), &used_n);
            good = used_k == slash && used_n == text.size() - slash - 1;
        } catch (const std::exception&) {
            good = false;
        }
    }
    if (!good || n < 1 || n > 4096 || k < 1 || k > n)
        fail_input("cagd benchmark", "--part \"" + text + "\": expected K/N with 1 <= K <= N <= 4096");
    return {k - 1, n};
}

std::string read_part(const std::string& path) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) fail_input("cagd benchmark", "--merge " + path + ": " + ec.message());
    if (size > kMaxPartBytes)
        fail_input("cagd benchmark",
                   "--merge " + path + ": " + std::to_string(size) + " bytes, more than a part holds");
    std::ifstream in(path, std::ios::binary);
    std::string text(static_cast<std::size_t>(size), '\0');
    if (!in.read(text.data(), static_cast<std::streamsize>(size)))
        fail_input("cagd benchmark", "--merge " + path + ": cannot be read");
    return text;
}

int run_benchmark(const BenchmarkArgs& a) {
    const compare::BenchmarkPlan plan = benchmark_plan(a.plan);
    if (!a.part.empty()) {
        const compare::WorkShare share = parse_part(a.part);
        if (!a.timing_out.empty())
            fail_input("cagd benchmark",
                       "--timing-out: with --part the run times go into the part; give --timing-out to --merge");
        OutputFile part(a.out, "--out");  // checked before the work
        if (progress_enabled())
            std::cerr << "cagd benchmark: part " << share.index + 1 << " of " << share.count << "\n";
        part.stream() << compare::benchmark_part_text(plan, share, compare::run_benchmark(plan, share, a.plan.threads));
        part.commit();
        return 0;
    }
    std::vector<std::pair<std::string, std::string>> parts;
    for (const std::string& path : a.merge) parts.emplace_back(path, read_part(path));
    OutputDirectory out(a.out);  // checked before the work
    // --timing-out is checked before the work too, except inside the --out directory, which exists
    // only once the results are committed (docs/benchmark.md's DIR/random_sets_seconds.csv).
    std::optional<OutputFile> timing;
    const auto directory = [](const std::filesystem::path& p) {
        std::error_code ec;
        std::filesystem::path c = std::filesystem::weakly_canonical(std::filesystem::absolute(p), ec);
        return c.has_filename() ? c : c.parent_path();
    };
    const bool inside_out =
        !a.timing_out.empty() && directory(std::filesystem::path(a.timing_out).parent_path().empty()
                                               ? "."
                                               : std::filesystem::path(a.timing_out).parent_path()) == directory(a.out);
    if (!a.timing_out.empty() && !inside_out) timing.emplace(a.timing_out, "--timing-out");
    if (progress_enabled() && parts.empty())
        std::cerr << "cagd benchmark: " << plan.truth.sizes.size() << " sizes, " << plan.classic.size()
                  << " classic data sets, " << plan.random.sets << " random sets per kind and size\n";
    const compare::BenchmarkResults results =
        parts.empty() ? compare::run_benchmark(plan, {}, a.plan.threads) : compare::merge_benchmark_parts(plan, parts);
    stage_benchmark_files(out, compare::benchmark_files(plan, results));
    out.commit();
    if (inside_out) timing.emplace(a.timing_out, "--timing-out");
    if (timing) {
        timing->stream() << compare::benchmark_timing_csv(results);
        timing->commit();
    }
    return 0;
}

}  // namespace

Command add_benchmark_command(CLI::App& app) {
    auto a = std::make_shared<BenchmarkArgs>();
    auto* c = app.add_subcommand(
        "benchmark",
        "Every method on points sampled from curves with a known answer: errors, convergence orders, leaderboards");
    c->add_option("--out", a->out,
                  "directory for truth_runs.csv, convergence_orders.csv, random_sets.csv, leaderboard.md, "
                  "convergence_<family>.dat; with --part the part file")
        ->required();
    add_benchmark_plan_options(c, a->plan);
    c->add_option("--timing-out", a->timing_out,
                  "CSV file for the random sets' run times per configuration (median, 90th percentile, largest); "
                  "absent: not written");
    auto* part =
        c->add_option("--part", a->part,
                      "K/N: compute only share K of N of the work and write it to --out as a part file, for --merge");
    c->add_option("--merge", a->merge,
                  "part files (all N of one plan, any order; the same options as their runs): write --out from them "
                  "instead of computing")
        ->excludes(part);
    return {c, [a] { return run_benchmark(*a); }};
}

}  // namespace cagd::cli
