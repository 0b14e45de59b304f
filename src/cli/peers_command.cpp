// `cagd peers --peers DIR --identities FILE --classic FILE --out DIR [--programs DIR]`: the peers
// of the benchmark (compare/peer_curves.hpp), each run by its adapter under DIR (peers/run, the
// manifest DIR/peers.csv), and the identity table (compare/peer_identity.hpp): every claim of
// FILE measured on the classic data sets of MANIFEST. --out receives, as a whole or not at all:
//   peers.md              the peers (version, licence, configurations, call; those skipped and why)
//                         and the identity table with its verdicts
//   peer_identities.csv   one row per claim and data set: the sampled difference and its bound
// A peer that is not installed here is skipped and named; nothing fails for it. Deterministic as
// long as the peers' versions are. `cagd peers --peers DIR --list-markdown` prints the manifest as a
// Markdown table instead (docs/methods.md's, written by scripts/update-docs-methods.sh).
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cagd/compare/peer_identity.hpp"
#include "cagd/core/errors.hpp"
#include "cli/benchmark_options.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

struct PeersArgs {
    std::string peers, identities, classic, out, programs;
    bool list_markdown = false;
};

int run_peers(const PeersArgs& a) {
    const std::filesystem::path folder(a.peers);
    if (!std::filesystem::is_regular_file(folder / "run"))
        fail_input("cagd peers", "--peers " + a.peers + ": no launcher " + (folder / "run").string());
    const std::vector<compare::PeerConfiguration> manifest =
        compare::read_peer_manifest((folder / "peers.csv").string());
    if (a.list_markdown) {
        std::cout << compare::peer_manifest_markdown(manifest);
        return std::cout.flush() ? 0 : 1;
    }
    for (const auto& [value, option] :
         {std::pair{&a.identities, "--identities"}, {&a.classic, "--classic"}, {&a.out, "--out"}})
        if (value->empty()) fail_input("cagd peers", std::string(option) + " is required (unless --list-markdown)");
    const std::vector<compare::IdentityClaim> claims = compare::read_identity_claims(a.identities);
    const std::vector<compare::ClassicDataSet> sets = compare::read_classic_data(a.classic);
    // The adapter programs: --programs, else CAGD_PEER_PROGRAMS, else peers/ beside this executable
    // (the build tree's, where peers/CMakeLists.txt puts them).
    std::string programs = a.programs;
    if (programs.empty() && std::getenv("CAGD_PEER_PROGRAMS")) programs = std::getenv("CAGD_PEER_PROGRAMS");
    if (programs.empty()) {
        std::error_code ec;
        programs = (std::filesystem::read_symlink("/proc/self/exe", ec).parent_path() / "peers").string();
    }
    OutputDirectory out(a.out);  // checked before the work
    const compare::PeerLauncher launcher{.run = std::filesystem::absolute(folder / "run").string(),
                                         .programs = programs};
    const compare::IdentityResults results = compare::measure_identities(claims, sets, manifest, launcher);
    for (const compare::PeerStatus& s : results.peers)
        if (!s.installed) std::cerr << "cagd peers: skipped " << s.peer << ": " << s.reason << "\n";
    stage_benchmark_files(out, {{"peers.md", compare::peers_markdown(claims, manifest, results)},
                                {"peer_identities.csv", compare::identity_measures_csv(claims, results)}});
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
    c->add_option("--programs", a->programs,
                  "where the adapter programs were built (absent: $CAGD_PEER_PROGRAMS, else peers/ beside this "
                  "executable)");
    c->add_flag("--list-markdown", a->list_markdown,
                "print the manifest's configurations as a Markdown table and stop (no peer is run)");
    return {c, [a] { return run_peers(*a); }};
}

}  // namespace cagd::cli
