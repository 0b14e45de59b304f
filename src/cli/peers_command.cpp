// `cagd peers --peers DIR --identities FILE --classic FILE --out DIR [--programs DIR]`: the peers
// of the benchmark (compare/peer_curves.hpp), each run by its adapter under DIR (peers/run, the
// manifest DIR/peers.csv), and the identity table (compare/peer_identity.hpp): every claim of
// FILE measured on the classic data sets of MANIFEST. --out receives, as a whole or not at all:
//   peers.md              the peers (version, licence, configurations, call; those skipped and why)
//                         and the identity table with its verdicts
//   peer_identities.csv   one row per claim and data set: the sampled difference and its bound
//   peer_truth_runs.csv, peer_convergence_orders.csv
//                         every installed peer on the benchmark's truths (compare/peer_truths.hpp),
//                         ranked in peers.md as leaderboard.md ranks the methods
// A peer that is not installed here is skipped and named; nothing fails for it. Deterministic as
// long as the peers' versions are. `cagd peers --peers DIR --list-markdown` prints the manifest as a
// Markdown table instead (docs/methods.md's, written by scripts/update-docs-methods.sh).
#include <cmath>
#include <iostream>
#include <memory>

#include "cagd/compare/peer_identity.hpp"
#include "cagd/compare/peer_truths.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cli/benchmark_options.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

struct PeersArgs {
    std::string peers, identities, classic, out, programs, truth_sizes = "6,12,24,48,96,192,384,768";
    bool list_markdown = false;
};

int run_peers(const PeersArgs& a) {
    const std::vector<compare::PeerConfiguration> manifest = peer_manifest(a.peers);
    if (a.list_markdown) {
        std::cout << compare::peer_manifest_markdown(manifest);
        return std::cout.flush() ? 0 : 1;
    }
    for (const auto& [value, option] :
         {std::pair{&a.identities, "--identities"}, {&a.classic, "--classic"}, {&a.out, "--out"}})
        if (value->empty()) fail_input("cagd peers", std::string(option) + " is required (unless --list-markdown)");
    const std::vector<compare::IdentityClaim> claims = compare::read_identity_claims(a.identities);
    const std::vector<compare::ClassicDataSet> sets = compare::read_classic_data(a.classic);
    const std::vector<int> sizes = parse_sizes("--truth-sizes", a.truth_sizes);
    compare::check_truth_sizes(sizes, "--truth-sizes");  // none at all, too
    OutputDirectory out(a.out);                          // checked before the work
    const compare::PeerLauncher launcher = peer_launcher(a.peers, a.programs);
    const compare::IdentityResults results = compare::measure_identities(claims, sets, manifest, launcher);
    for (const compare::PeerStatus& s : results.peers)
        if (!s.installed) std::cerr << "cagd peers: skipped " << s.peer << ": " << s.reason << "\n";
    // Every installed peer against the truths, measured as the benchmark measures the methods.
    std::vector<compare::CurveSubject> subjects;
    for (const compare::PeerConfiguration& c : manifest)
        for (const compare::PeerStatus& p : results.peers)
            if (p.peer == c.peer && p.installed) subjects.push_back(compare::peer_subject(launcher, c));
    const std::vector<compare::TruthRun> runs = compare::subject_truth_runs(subjects, sizes);
    const std::vector<compare::ConvergenceOrder> orders = compare::convergence_orders(runs);
    const std::string truths =
        "\n## Against the truths\n\nEvery installed peer on the benchmark's points with a known answer, measured and "
        "ranked as the benchmark ranks the methods (`leaderboard.md`; docs/benchmark.md): the same truths, uniform "
        "in arc length, at the same sizes. Data: [`peer_truth_runs.csv`](peer_truth_runs.csv), "
        "[`peer_convergence_orders.csv`](peer_convergence_orders.csv).\n" +
        compare::truth_leaderboard_markdown(runs, orders);
    stage_benchmark_files(
        out, {{"peers.md", compare::peers_markdown(claims, manifest, results) + truths},
              {"peer_identities.csv", compare::identity_measures_csv(claims, results)},
              {"peer_truth_runs.csv", csv_table(compare::truth_runs_header(), compare::truth_runs_rows(runs))},
              {"peer_convergence_orders.csv",
               csv_table(compare::convergence_orders_header(), compare::convergence_orders_rows(orders))}});
    out.commit();
    return 0;
}

}  // namespace

Command add_peers_command(CLI::App& app) {
    auto a = std::make_shared<PeersArgs>();
    auto* c = app.add_subcommand(
        "peers", "Other libraries' interpolants run as their users run them, and the identities between them and ours");
    c->add_option("--peers", a->peers, "the peers' folder (peers/: the launcher run and the manifest peers.csv)")
        ->required();
    c->add_option(
        "--identities", a->identities,
        "the claims (CSV: left, right, closed, ends, expected, reason; reference/benchmark/peer_identities.csv)");
    c->add_option("--classic", a->classic,
                  "manifest of classic data sets the claims are measured on (reference/benchmark/classic_data.csv)");
    c->add_option("--out", a->out, "directory for peers.md and peer_identities.csv");
    add_peer_programs_option(c, a->programs);
    c->add_option("--truth-sizes", a->truth_sizes, "numbers of points of the peers' truth runs, increasing")
        ->capture_default_str();
    c->add_flag("--list-markdown", a->list_markdown,
                "print the manifest's configurations as a Markdown table and stop (no peer is run)");
    return {c, [a] { return run_peers(*a); }};
}

}  // namespace cagd::cli
