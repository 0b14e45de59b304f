// `cagd energy-table --grid N [--placement P] [--method fast|reference] [--threads T] --out T.txt`:
// a lookup table of J, r0, r1, L, S and the segment type over the direction pairs (pseudo_energy
// section 4.1), as `cagd interpolate --method pseudo-spline --table` reads it. Progress on stderr.
#include <cstdio>
#include <memory>

#include "cagd/core/errors.hpp"
#include "cagd/fairness/pseudo_energy_table.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

struct EnergyTableArgs {
    int grid = 36, threads = 2;
    fairness::NodePlacement placement = fairness::NodePlacement::periodic;
    fairness::TableMethod method = fairness::TableMethod::fast;
    std::string out;
};

int run_energy_table(const EnergyTableArgs& a) {
    OutputFile out(a.out);
    const bool show = progress_enabled();
    const auto progress = [show](long done, long total) {
        if (!show) return;
        std::fprintf(stderr, "\rcagd energy-table: %ld / %ld nodes", done, total);
        if (done == total) std::fprintf(stderr, "\n");
    };
    const fairness::PseudoEnergyTable t = fairness::PseudoEnergyTable::build(
        {a.grid, a.placement}, a.method, a.threads, a.method == fairness::TableMethod::fast, progress);
    t.save(out.stream());
    out.commit();
    return 0;
}

}  // namespace

Command add_energy_table_command(CLI::App& app) {
    auto a = std::make_shared<EnergyTableArgs>();
    CLI::App* c = app.add_subcommand(
        "energy-table", "Build a lookup table of J, r0, r1, L, S and the segment type (pseudo_energy section 4.1)");
    c->add_option("--grid", a->grid,
                  "nodes per axis (grid^2 minimisations: 720, a 0.5 degree grid, takes minutes with the fast method)")
        ->required()
        ->check(CLI::Range(2, 720));
    add_enum_option(c, "--placement", a->placement,
                    {{"periodic", fairness::NodePlacement::periodic},
                     {"endpoints", fairness::NodePlacement::endpoints},
                     {"midpoints", fairness::NodePlacement::midpoints}},
                    "angle nodes: periodic | endpoints | midpoints");
    add_enum_option(c, "--method", a->method,
                    {{"fast", fairness::TableMethod::fast}, {"reference", fairness::TableMethod::reference}},
                    "fast (Newton) | reference (Romberg + conjugate gradient)");
    c->add_option("--threads", a->threads, "worker threads")->check(CLI::Range(1, 64));
    c->add_option("--out", a->out, "table file (text, first line records grid, placement and method); - for stdout")
        ->required();
    return {c, [a] { return run_energy_table(*a); }};
}

}  // namespace cagd::cli
