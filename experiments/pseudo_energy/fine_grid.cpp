// pseudo_energy section 4.1 and section 2: the minimum exists at every node of a 1° grid
// (361 × 361, −180° … 180°), and the interpolation error of the lookup tables (the paper's
// same-type bilinear rule, and plain bilinear for comparison) against the exact minimum over a
// seeded random sample, for grids of 36, 72, 180 (periodic) and 361 (endpoints) nodes per axis.
// Also the fast path against the reference path on a random sample (not only at nodes).
#include <cmath>
#include <numbers>
#include <random>

#include "cagd/fairness/pseudo_energy_table.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::fairness;

namespace {
struct ErrorStats {
    double max = 0, sum2 = 0;
    long n = 0;
    void add(double e) {
        max = std::max(max, std::abs(e));
        sum2 += e * e;
        ++n;
    }
    double rms() const { return n ? std::sqrt(sum2 / static_cast<double>(n)) : 0.0; }
};
}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run("pseudo_energy", "fine_grid", "4.1",
                           "Fine grids: existence of the minimum and table interpolation error", argc, argv);
    const AngleGrid one_degree{361, NodePlacement::endpoints};
    const PseudoEnergyTable fine =
        PseudoEnergyTable::load_or_build(run.cache_path("table361_fast.txt"), one_degree, TableMethod::fast);
    int no_minimum = 0;
    double r_min = INFINITY, r_max = 0;
    for (int i = 0; i < one_degree.n; ++i)
        for (int j = 0; j < one_degree.n; ++j) {
            const PseudoEnergyMinimum& m = fine.node(i, j);
            if (is_undefined_node(m.theta0, m.theta1)) continue;
            if (!m.outcome.ok()) ++no_minimum;
            r_min = std::min({r_min, m.r0, m.r1});
            r_max = std::max({r_max, m.r0, m.r1});
        }
    run.check("sec2.minimum_exists_1deg", no_minimum);
    run.note("1° grid (361 × 361 nodes, fast path, one node per symmetry orbit): minimisers range over r ∈ [" +
             format_number(r_min, 4) + ", " + format_number(r_max, 4) +
             "]; the smallest occur next to the undefined nodes (±180°, 0), where r0 → 0 as θ1 → 0.");

    // Seeded random sample of direction pairs and their exact minima (fast path).
    std::mt19937_64 rng(20261121);
    std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
    const int samples = 2000;
    std::vector<PseudoEnergyMinimum> exact;
    while (static_cast<int>(exact.size()) < samples) {
        const double a = angle(rng), b = angle(rng);
        const PseudoEnergyMinimum m = minimize_pseudo_energy(a, b);
        if (m.outcome.ok()) exact.push_back(m);
    }
    CsvWriter out = run.table("interpolation_error.csv",
                              {"nodes_per_axis", "placement", "rule", "quantity", "max_error", "rms_error"});
    CsvWriter fig =
        run.table("fig_interpolation_error.csv", {"nodes_per_axis", "spacing_deg", "max_rel_J_same_type",
                                                  "rms_rel_J_same_type", "max_rel_J_plain", "rms_rel_J_plain"});
    const std::pair<int, NodePlacement> grids[] = {{36, NodePlacement::periodic},
                                                   {72, NodePlacement::periodic},
                                                   {180, NodePlacement::periodic},
                                                   {361, NodePlacement::endpoints}};
    for (const auto& [n, placement] : grids) {
        const AngleGrid g{n, placement};
        const PseudoEnergyTable t =
            n == 361 ? fine
                     : PseudoEnergyTable::load_or_build(run.cache_path("table" + std::to_string(n) + "_fast.txt"), g,
                                                        TableMethod::fast);
        double fig_row[4] = {0, 0, 0, 0};
        for (bool same : {true, false}) {
            ErrorStats ej, er0, er1, el, es;
            for (const PseudoEnergyMinimum& m : exact) {
                const TableValue v = t.lookup(m.theta0, m.theta1, same);
                ej.add((v.pseudo_energy - m.pseudo_energy) / std::max(1.0, m.pseudo_energy));
                er0.add(v.r0 - m.r0);
                er1.add(v.r1 - m.r1);
                el.add(v.length - m.length);
                es.add(v.area - m.area);
            }
            const std::string rule = same ? "same_type" : "plain_bilinear";
            const std::pair<const char*, const ErrorStats*> rows[] = {
                {"J_relative", &ej}, {"r0", &er0}, {"r1", &er1}, {"L", &el}, {"S", &es}};
            for (const auto& [q, st] : rows)
                out.row_text({std::to_string(n), to_string(placement), rule, q, format_number(st->max, 6),
                              format_number(st->rms(), 6)});
            fig_row[same ? 0 : 2] = ej.max;
            fig_row[same ? 1 : 3] = ej.rms();
            if (n == 36 && same)
                run.note("36-node table, same-type bilinear rule, " + std::to_string(samples) +
                         " random pairs: max relative error of J " + format_number(ej.max, 3) + " (RMS " +
                         format_number(ej.rms(), 3) + "), of r0 " + format_number(er0.max, 3) + " (RMS " +
                         format_number(er0.rms(), 3) + ").");
        }
        const double spacing = placement == NodePlacement::endpoints ? 360.0 / (n - 1) : 360.0 / n;
        fig.row({double(n), spacing, fig_row[0], fig_row[1], fig_row[2], fig_row[3]});
    }
    run.figure("fig_interpolation_error",
               "Interpolation error of J (relative to max(1, J)) against grid spacing, 2000 random direction pairs: "
               "the paper's same-type rule and plain bilinear interpolation.");

    // Fast vs reference off the nodes.
    double dj = 0, dr = 0;
    for (int k = 0; k < 200; ++k) {
        const PseudoEnergyMinimum& f = exact[static_cast<std::size_t>(k)];
        const PseudoEnergyMinimum r = minimize_pseudo_energy_reference(f.theta0, f.theta1);
        dj = std::max(dj, std::abs(f.pseudo_energy - r.pseudo_energy) / std::max(1.0, r.pseudo_energy));
        dr = std::max({dr, std::abs(f.r0 - r.r0), std::abs(f.r1 - r.r1)});
    }
    run.validate("random.fast_vs_reference_J",
                 "fast vs reference minimum at 200 random direction pairs: max |ΔJ| / max(1, J)", dj, 0.0, 1e-10,
                 "required agreement of the fast path with the reference path");
    run.validate("random.fast_vs_reference_r", "fast vs reference minimiser at 200 random direction pairs: max |Δr|",
                 dr, 0.0, 1e-8, "required agreement of the fast path with the reference path");
    return run.finish();
}
