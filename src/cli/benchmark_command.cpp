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
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "cagd/compare/classic_benchmark.hpp"
#include "cagd/compare/random_sets.hpp"
#include "cagd/compare/truth_benchmark.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

// Distances at rounding level are drawn at this floor (the plot is log-scaled; 0 is "exact").
constexpr double kDrawnFloor = 1e-17;

struct BenchmarkArgs {
    std::string out, sizes = "6,12,24,48,96,192,384,768", families, methods, random_sizes = "8,32,128", timing_out, classic;
    int threads = 0, random_sets = 1000, scatter_max_points = 32;
};

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) out.push_back(item);
    return out;
}

// A comma-separated list of numbers of points in 3..100000, given to `option`.
std::vector<int> parse_sizes(const std::string& option, const std::string& text) {
    std::vector<int> sizes;
    for (const std::string& s : split(text)) {
        std::size_t used = 0;
        int n = 0;
        try {
            n = std::stoi(s, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != s.size() || n < 3 || n > 100000) fail_input("cagd benchmark", option + ": \"" + s + "\" is not a whole number of points in 3..100000");
        sizes.push_back(n);
    }
    return sizes;
}

int run_benchmark(const BenchmarkArgs& a) {
    compare::TruthBenchmarkOptions options;
    options.sizes = parse_sizes("--sizes", a.sizes);
    compare::RandomSetOptions random;
    random.sizes = parse_sizes("--random-sizes", a.random_sizes);
    random.sets = a.random_sets;
    random.scatter_max_points = a.scatter_max_points;
    options.families = split(a.families);
    for (const std::string& f : options.families) compare::find_truth_family(f);  // bad names before any work
    for (const std::string& m : split(a.methods)) options.methods.push_back(methods::find_configuration(m).name);
    options.threads = random.threads = a.threads;
    random.methods = options.methods;
    std::vector<compare::ClassicDataSet> classic_sets;
    if (!a.classic.empty()) classic_sets = compare::read_classic_data(a.classic);  // bad data before any work
    OutputDirectory out(a.out);  // checked before the work
    std::optional<OutputFile> timing;
    if (!a.timing_out.empty()) timing.emplace(a.timing_out, "--timing-out");  // checked before the work too
    if (progress_enabled()) std::cerr << "cagd benchmark: " << options.sizes.size() << " sizes\n";
    const std::vector<compare::TruthRun> runs = compare::run_truth_benchmark(options);
    const std::vector<compare::ConvergenceOrder> orders = compare::convergence_orders(runs);
    std::vector<compare::ClassicRun> classic_runs;
    if (!classic_sets.empty()) {
        if (progress_enabled()) std::cerr << "cagd benchmark: " << classic_sets.size() << " classic data sets\n";
        classic_runs = compare::run_classic_benchmark(classic_sets, options.methods, a.threads);
        CsvOutput w(out.staged("classic_runs.csv"), compare::classic_runs_header());
        for (const auto& row : compare::classic_runs_rows(classic_runs)) w.row_text(row);
        w.commit();
        OutputFile f(out.staged("classic.md"));
        f.stream() << compare::classic_tables_markdown(classic_runs, classic_sets);
        f.commit();
    }
    std::vector<compare::RandomSetSummary> random_runs;
    if (random.sets > 0) {
        if (progress_enabled()) std::cerr << "cagd benchmark: " << random.sets << " random sets per kind and size\n";
        random_runs = compare::run_random_sets(random);
        CsvOutput w(out.staged("random_sets.csv"), compare::random_sets_header());
        for (const auto& row : compare::random_sets_rows(random_runs)) w.row_text(row);
        w.commit();
    }
    {
        CsvOutput w(out.staged("truth_runs.csv"), compare::truth_runs_header());
        for (const auto& row : compare::truth_runs_rows(runs)) w.row_text(row);
        w.commit();
    }
    {
        CsvOutput w(out.staged("convergence_orders.csv"), compare::convergence_orders_header());
        for (const auto& row : compare::convergence_orders_rows(orders)) w.row_text(row);
        w.commit();
    }
    {
        OutputFile f(out.staged("leaderboard.md"));
        f.stream() << compare::truth_leaderboard_markdown(runs, orders) << compare::classic_summary_markdown(classic_runs, classic_sets)
                   << compare::random_sets_markdown(random_runs);
        f.commit();
    }
    for (const compare::TruthFamily& family : compare::truth_families()) {
        // The configurations in the runs' order, each a block of its sizes.
        std::vector<std::string> order;
        for (const compare::TruthRun& r : runs)
            if (r.family == family.name && std::find(order.begin(), order.end(), r.method) == order.end()) order.push_back(r.method);
        if (order.empty()) continue;
        OutputFile f(out.staged("convergence_" + family.name + ".dat"));
        for (std::size_t m = 0; m < order.size(); ++m) {
            f.stream() << (m ? "\n\n" : "") << "n \"" << order[m] << "\" distance\n";
            for (const compare::TruthRun& r : runs)
                if (r.family == family.name && r.method == order[m] && r.spacing == compare::TruthSpacing::uniform && r.closed == family.closed && r.status == "ok")
                    f.stream() << r.n << " " << r.n << " " << format_number(std::max(r.errors.distance, kDrawnFloor), 6) << "\n";
        }
        f.commit();
    }
    out.commit();
    if (timing) {
        CsvOutput w(*timing, compare::random_set_timing_header());
        for (const auto& row : compare::random_set_timing_rows(random_runs)) w.row_text(row);
        w.commit();
    }
    return 0;
}

}  // namespace

Command add_benchmark_command(CLI::App& app) {
    auto a = std::make_shared<BenchmarkArgs>();
    auto* c = app.add_subcommand("benchmark", "Every method on points sampled from curves with a known answer: errors, convergence orders, leaderboards");
    c->add_option("--out", a->out, "directory for truth_runs.csv, convergence_orders.csv, random_sets.csv, leaderboard.md, convergence_<family>.dat")->required();
    c->add_option("--sizes", a->sizes, "numbers of points, comma-separated (each 3..100000)")->capture_default_str();
    c->add_option("--families", a->families, "truth families, comma-separated (absent: all: line, circle, ellipse, epitrochoid, clothoid, log-aesthetic, helix, trefoil)");
    c->add_option("--methods", a->methods, "configurations, comma-separated (absent: every configuration)");
    c->add_option("--threads", a->threads, "cases measured at once (0: the hardware's; results do not depend on it)")->check(CLI::Range(0, 256));
    c->add_option("--random-sets", a->random_sets, "seeded random sets per kind (walk, scatter) and size, for the failure rates (0: none)")
        ->capture_default_str()
        ->check(CLI::Range(0, 100000));
    c->add_option("--random-sizes", a->random_sizes, "numbers of points of the random sets, comma-separated (each 3..100000)")->capture_default_str();
    c->add_option("--scatter-max-points", a->scatter_max_points, "scattered random sets only up to this many points (walks at every --random-sizes)")
        ->capture_default_str()
        ->check(CLI::Range(0, 100000));
    c->add_option("--classic", a->classic,
                  "manifest of classic data sets (CSV: name, group, file, closed, source; reference/benchmark/classic_data.csv): classic_runs.csv, classic.md "
                  "and a summary in leaderboard.md; absent: none");
    c->add_option("--timing-out", a->timing_out, "CSV file for the random sets' run times per configuration (median, 90th percentile, largest); absent: not written");
    return {c, [a] { return run_benchmark(*a); }};
}

}  // namespace cagd::cli
