// `cagd scorecard --out DIR [--classic FILE] [--peers DIR [--programs DIR]] [--polygons N]
// [--only NAMES] [--threads T]`: Levien's properties as numbers (compare/scorecard.hpp) for every
// configuration of the registry and, with --peers, every configuration of every installed peer (the
// manifest DIR/peers.csv, run by DIR/run). --out receives, as a whole or not at all:
//   scorecard.md            the properties per subject with their 95 % intervals, the failure rates
//                           by largest turning angle, the peers skipped
//   scorecard.csv           every summary: subject,kind,property,quantity,sets,value,low,high
//   scorecard_classic.csv   every subject on every classic data set (with --classic)
//   scorecard_locality.dat  the figure's data (scripts/plot/benchmark_fig_scorecard.gp)
// A peer that is not installed is skipped and named. Deterministic for any --threads, as long as
// the peers' versions are.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <memory>

#include "cagd/compare/scorecard.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"
#include "cli/benchmark_options.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

struct ScorecardArgs {
    std::string out, classic, peers, programs, only;
    int polygons = 10000, threads = 0;
};

// The largest --polygons: ten million curves per subject.
constexpr int kMaxPolygons = 1'000'000;

int run_scorecard(const ScorecardArgs& a) {
    if (a.polygons < 1 || a.polygons > kMaxPolygons)
        fail_input("--polygons", std::to_string(a.polygons) + " outside 1.." + std::to_string(kMaxPolygons));
    if (a.threads < 0) fail_input("--threads", std::to_string(a.threads) + " must be at least 0");
    const std::vector<std::string> only = a.only.empty() ? std::vector<std::string>{} : split_csv_line(a.only);
    const auto wanted = [&](const std::string& name) {
        return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
    };
    std::vector<compare::CurveSubject> subjects;
    for (const methods::Configuration& c : methods::configurations())
        if (wanted(c.name)) subjects.push_back(compare::method_subject(c, 1));
    std::vector<std::string> skipped, absent;  // why each absent peer was skipped; the configurations absent
    if (!a.peers.empty()) {
        compare::InstalledPeers peers =
            compare::installed_peer_subjects(peer_launcher(a.peers, a.programs), peer_manifest(a.peers), wanted);
        for (compare::CurveSubject& s : peers.subjects) subjects.push_back(std::move(s));
        skipped = std::move(peers.skipped);
        absent = std::move(peers.absent);
    }
    for (const std::string& name : only)
        if (std::none_of(subjects.begin(), subjects.end(), [&](const auto& s) { return s.name == name; }) &&
            std::find(absent.begin(), absent.end(), name) == absent.end())
            fail_input("--only", "no configuration or peer configuration \"" + name + "\"");
    compare::ScorecardOptions options{.polygons = a.polygons, .threads = a.threads};
    if (!a.classic.empty()) options.classic = compare::read_classic_data(a.classic);
    OutputDirectory out(a.out);  // checked before the work
    for (const std::string& s : skipped) std::cerr << "cagd scorecard: skipped " << s << "\n";
    // The subjects side by side, each on one thread (a peer's adapter runs while another subject is
    // measured); the results in the subjects' order, whatever finishes first.
    std::vector<compare::SubjectScores> scores(subjects.size());
    std::vector<std::vector<compare::ScorecardRow>> summaries(subjects.size());
    compare::ScorecardOptions one = options;
    one.threads = 1;
    parallel_for(
        static_cast<long>(subjects.size()), a.threads > 0 ? a.threads : hardware_threads(),
        [&](long k) {
            const auto i = static_cast<std::size_t>(k);
            scores[i] = compare::run_scorecard(subjects[i], one);
            summaries[i] = compare::scorecard_rows(scores[i]);
            scores[i].polygons.clear();  // only the classic data's scores are written per case
        },
        [](long done, long count) {
            if (progress_enabled()) std::cerr << "cagd scorecard: " << done << " of " << count << " subjects\n";
        });
    std::vector<compare::ScorecardRow> rows;
    for (const auto& r : summaries) rows.insert(rows.end(), r.begin(), r.end());
    std::vector<std::pair<std::string, std::string>> files{
        {"scorecard.md", compare::scorecard_markdown(rows, a.polygons, skipped)},
        {"scorecard.csv", compare::scorecard_csv(rows)},
        {"scorecard_locality.dat", compare::scorecard_figure_data(rows)}};
    if (!options.classic.empty())
        files.emplace_back("scorecard_classic.csv", compare::scorecard_classic_csv(scores, options.classic));
    stage_benchmark_files(out, files);
    out.commit();
    return 0;
}

}  // namespace

Command add_scorecard_command(CLI::App& app) {
    auto a = std::make_shared<ScorecardArgs>();
    auto* c = app.add_subcommand("scorecard",
                                 "Levien's properties of an interpolating spline, and four more, as numbers with 95 % "
                                 "intervals, for every method and peer");
    c->add_option("--out", a->out,
                  "directory for scorecard.md, scorecard.csv, scorecard_classic.csv and "
                  "scorecard_locality.dat")
        ->required();
    c->add_option("--classic", a->classic,
                  "manifest of classic data sets scored as well (reference/benchmark/classic_data.csv)");
    c->add_option("--peers", a->peers, "the peers' folder (peers/); absent: the registry's configurations only");
    add_peer_programs_option(c, a->programs);
    c->add_option("--polygons", a->polygons,
                  "random polygons, and co-circular sets of each kind (1.." + std::to_string(kMaxPolygons) + ")")
        ->capture_default_str();
    c->add_option("--only", a->only,
                  "subjects to score, comma-separated: configurations, peers' as peer:configuration (absent: all)");
    c->add_option("--threads", a->threads, "cases measured at once (0: the hardware's); results do not depend on it")
        ->capture_default_str();
    return {c, [a] { return run_scorecard(*a); }};
}

}  // namespace cagd::cli
