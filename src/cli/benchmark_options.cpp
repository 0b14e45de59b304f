#include "cli/benchmark_options.hpp"

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "cagd/core/errors.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::cli {

namespace {

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) out.push_back(item);
    return out;
}

}  // namespace

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
        if (used != s.size() || n < 3 || n > 100000)
            fail_input(option, "\"" + s + "\" is not a whole number of points in 3..100000");
        if (!sizes.empty() && !(n > sizes.back()))
            fail_input(option,
                       std::to_string(n) + " after " + std::to_string(sizes.back()) + "; the sizes must increase");
        sizes.push_back(n);
    }
    return sizes;
}

void add_benchmark_plan_options(CLI::App* c, BenchmarkPlanArgs& a) {
    c->add_option("--sizes", a.sizes, "numbers of points, comma-separated and increasing (each 3..100000)")
        ->capture_default_str();
    c->add_option("--families", a.families,
                  "truth families, comma-separated (absent: all: line, circle, ellipse, epitrochoid, clothoid, "
                  "log-aesthetic, helix, trefoil)");
    c->add_option("--methods", a.methods, "configurations, comma-separated (absent: every configuration)");
    c->add_option("--threads", a.threads, "cases measured at once (0: the hardware's; results do not depend on it)")
        ->check(CLI::Range(0, 256));
    c->add_option("--random-sets", a.random_sets,
                  "seeded random sets per kind (walk, scatter) and size, for the failure rates (0: none)")
        ->capture_default_str()
        ->check(CLI::Range(0, 100000));
    c->add_option("--random-sizes", a.random_sizes,
                  "numbers of points of the random sets, comma-separated (each 3..100000)")
        ->capture_default_str();
    c->add_option("--scatter-max-points", a.scatter_max_points,
                  "scattered random sets only up to this many points (walks at every --random-sizes)")
        ->capture_default_str()
        ->check(CLI::Range(0, 100000));
    c->add_option("--classic", a.classic,
                  "manifest of classic data sets (CSV: name, group, file, closed, source; "
                  "reference/benchmark/classic_data.csv): classic_runs.csv, classic.md "
                  "and a summary in leaderboard.md; absent: none");
}

compare::BenchmarkPlan benchmark_plan(const BenchmarkPlanArgs& a) {
    compare::BenchmarkPlan plan;
    plan.truth.sizes = parse_sizes("--sizes", a.sizes);
    plan.random.sizes = parse_sizes("--random-sizes", a.random_sizes);
    plan.random.sets = a.random_sets;
    plan.random.scatter_max_points = a.scatter_max_points;
    plan.truth.families = split(a.families);
    for (const std::string& f : plan.truth.families) compare::find_truth_family(f);  // bad names before any work
    for (const std::string& m : split(a.methods)) plan.truth.methods.push_back(methods::find_configuration(m).name);
    plan.random.methods = plan.truth.methods;
    if (!a.classic.empty()) plan.classic = compare::read_classic_data(a.classic);  // bad data before any work
    return plan;
}

void stage_benchmark_files(OutputDirectory& out, const std::vector<std::pair<std::string, std::string>>& files) {
    for (const auto& [name, content] : files) {
        OutputFile f(out.staged(name));
        f.stream() << content;
        f.commit();
    }
}

std::vector<compare::PeerConfiguration> peer_manifest(const std::string& peers) {
    const std::filesystem::path folder(peers);
    if (!std::filesystem::is_regular_file(folder / "run"))
        fail_input("--peers", peers + ": no launcher " + (folder / "run").string());
    return compare::read_peer_manifest((folder / "peers.csv").string());
}

compare::PeerLauncher peer_launcher(const std::string& peers, const std::string& programs) {
    std::string folder = programs;
    if (folder.empty() && std::getenv("CAGD_PEER_PROGRAMS")) folder = std::getenv("CAGD_PEER_PROGRAMS");
    if (folder.empty()) {
        std::error_code ec;
        folder = (std::filesystem::read_symlink("/proc/self/exe", ec).parent_path() / "peers").string();
    }
    return {.run = std::filesystem::absolute(std::filesystem::path(peers) / "run").string(), .programs = folder};
}

void add_peer_programs_option(CLI::App* c, std::string& programs) {
    c->add_option("--programs", programs,
                  "where the adapter programs were built (absent: $CAGD_PEER_PROGRAMS, else peers/ beside this "
                  "executable)");
}

}  // namespace cagd::cli
