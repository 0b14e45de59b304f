// compare/peer_curves and compare/peer_identity: the peer protocol through a launcher of this test
// (a shell script speaking it), the manifest and claims read with their faults named, and the
// piecewise difference with its bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../support/messages.hpp"
#include "../support/scratch_directory.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/compare/peer_identity.hpp"

using namespace cagd;
using namespace cagd::compare;

namespace {

// The peers of tests/data/peers/run (see there): echoer, absent, crash, liar.
struct FakePeers {
    PeerLauncher launcher{.run = std::string(CAGD_SOURCE_DIR) + "/tests/data/peers/run", .programs = "/nonexistent"};
};

PeerConfiguration configuration(const std::string& peer, const std::string& name) {
    return {.peer = peer,
            .configuration = name,
            .open = true,
            .closed = true,
            .library = "test",
            .licence = "MIT",
            .output = "exact",
            .call = "a test"};
}

ClassicDataSet data_set(const std::string& name, bool closed) {
    PointList p(5, 2);
    p << 0, 0, 1, 2, 3, 1, 4, 3, 6, 0;
    return {.name = name, .group = "test", .file = "", .closed = closed, .source = "a test", .points = p};
}

exports::BezierPieces pieces(int degree, const Eigen::MatrixXd& control) {
    exports::BezierPieces b;
    b.degree = degree;
    b.control = control;
    for (int i = 0; i <= control.rows() / (degree + 1); ++i) b.breaks.push_back(i);
    return b;
}

}  // namespace

TEST(PeerCurves, TheProtocolCarriesEachRequestAndItsAnswer) {
    FakePeers peers;
    const ClassicDataSet open = data_set("open", false), closed = data_set("closed", true);
    const PeerRun run = run_peer(peers.launcher, "echoer",
                                 {{.configuration = "a", .points = open.points, .closed = false},
                                  {.configuration = "refuse", .points = open.points, .closed = false},
                                  {.configuration = "b", .points = closed.points, .closed = true}});
    ASSERT_TRUE(run.installed) << run.reason;
    EXPECT_EQ(run.version, "echoer 1.0");
    ASSERT_EQ(run.answers.size(), 3u);
    ASSERT_TRUE(run.answers[0].curve) << run.answers[0].error;
    EXPECT_EQ(run.answers[0].curve->form.pieces.pieces(), 4);
    EXPECT_EQ(run.answers[0].curve->provenance.points, open.points);
    EXPECT_FALSE(run.answers[1].curve);
    EXPECT_EQ(run.answers[1].error, "refused by the test peer");
    ASSERT_TRUE(run.answers[2].curve) << run.answers[2].error;
    EXPECT_EQ(run.answers[2].curve->form.pieces.pieces(), 5);
    EXPECT_TRUE(run.answers[2].curve->provenance.closed);
}

TEST(PeerCurves, APeerNotInstalledIsSkippedAndAFailedRunIsThePeers) {
    FakePeers peers;
    const PointList p = data_set("x", false).points;
    const PeerRun absent = run_peer(peers.launcher, "absent", {{.configuration = "a", .points = p}});
    EXPECT_FALSE(absent.installed);
    EXPECT_EQ(absent.reason, "absent: not installed here (a test)");
    const PeerRun crash =
        run_peer(peers.launcher, "crash", {{.configuration = "a", .points = p}, {.configuration = "a", .points = p}});
    ASSERT_TRUE(crash.installed);
    EXPECT_NE(crash.reason.find("crash: 1 answers to 2 requests; its adapter exit status 1: crashed"),
              std::string::npos)
        << crash.reason;
    ASSERT_EQ(crash.answers.size(), 2u);
    for (const PeerAnswer& a : crash.answers) EXPECT_EQ(a.error, crash.reason);
}

TEST(PeerCurves, RequestsAreWrittenAtFullPrecision) {
    PointList p(2, 2);
    p << 0.1, 1.0 / 3.0, -2e-300, 1e300;
    EXPECT_EQ(peer_request_text({{.configuration = "c", .points = p, .closed = true}}),
              "curve c closed 2 2\n0.10000000000000001 0.33333333333333331\n-2.0000000000000001e-300 "
              "1.0000000000000001e+300\n");
}

TEST(PeerCurves, AConfigurationThatWouldBreakItsLineIsRefused) {
    const PointList p = data_set("x", false).points;
    for (const std::string bad : {"", "two words", "line\nbreak"})
        EXPECT_NE(test::invalid_input_message([&] {
                      peer_request_text({{.configuration = bad, .points = p}});
                  }).find("is not a name (no blanks)"),
                  std::string::npos)
            << bad;
}

TEST(PeerIdentity, TheDifferenceLiesBetweenItsSampleAndItsBound) {
    // Two cubic pieces; the second curve's middle control points moved by (0, 3) and (0, −3): the
    // difference is 3 (B1 − B2)(w), whose largest value 3·(2/3)(1/3)·… lies below the bound 3.
    Eigen::MatrixXd a(8, 2), b(8, 2);
    a << 0, 0, 1, 1, 2, 1, 3, 0, 3, 0, 4, -1, 5, -1, 6, 0;
    b = a;
    b(5, 1) += 3, b(6, 1) -= 3;
    const PieceDifference d = piecewise_difference(pieces(3, a), pieces(3, b), 2.0);
    EXPECT_DOUBLE_EQ(d.bound, 1.5);
    // The supremum of 9 w (1 − w)(1 − 2w) / 2 is √3/4 = 0.4330 at w = (3 − √3)/6; sampled at j/64 just below.
    EXPECT_LE(d.sampled, std::sqrt(3.0) / 4);
    EXPECT_GT(d.sampled, std::sqrt(3.0) / 4 - 1e-3);
    EXPECT_EQ(d.compared, 2);
    EXPECT_EQ(d.over, 1);
    EXPECT_EQ(d.farthest, 0);  // the last piece: at an end
    // With both pieces left out as end pieces nothing is compared, and the pair is not comparable
    // (never a vacuous "identical").
    EXPECT_EQ(piecewise_difference(pieces(3, a), pieces(3, b), 2.0, 1).incomparable,
              "2 pieces: none between the 1 left out at each end");
    // A line as degree 1 and raised to degree 3 is the same curve.
    Eigen::MatrixXd line(2, 2), cubic(4, 2);
    line << 0, 0, 3, 3;
    cubic << 0, 0, 1, 1, 2, 2, 3, 3;
    EXPECT_EQ(piecewise_difference(pieces(1, line), pieces(3, cubic), 1.0).bound, 0.0);
    // Different piece counts are not compared.
    EXPECT_EQ(piecewise_difference(pieces(3, a), pieces(3, cubic), 1.0).incomparable, "2 and 1 pieces");
}

TEST(PeerIdentity, ClaimsAreMeasuredOnTheirDataSetsWithEveryFailureNamed) {
    FakePeers peers;
    std::vector<PeerConfiguration> manifest{configuration("echoer", "a"),      configuration("echoer", "b"),
                                            configuration("echoer", "refuse"), configuration("absent", "a"),
                                            configuration("liar", "a"),        configuration("echoer", "approximate")};
    manifest.back().output = "samples";  // a peer that gives samples only: its pieces approximate its curve
    const std::vector<ClassicDataSet> sets{data_set("open", false), data_set("closed", true)};
    const std::vector<IdentityClaim> claims{
        {.left = "echoer:a", .right = "echoer:b", .closed = false, .identical = true, .reason = "the same polygon"},
        {.left = "echoer:a", .right = "cagd:cubic-b", .closed = true, .identical = false, .reason = "a polygon"},
        {.left = "echoer:refuse", .right = "echoer:a", .closed = false, .identical = true, .reason = "r"},
        {.left = "echoer:a", .right = "absent:a", .closed = false, .identical = true, .reason = "s"},
        {.left = "liar:a", .right = "echoer:a", .closed = false, .identical = true, .reason = "t"},
        {.left = "echoer:a", .right = "echoer:approximate", .closed = false, .identical = true, .reason = "u"}};
    const IdentityResults r = measure_identities(claims, sets, manifest, peers.launcher);
    ASSERT_EQ(r.peers.size(), 3u);
    EXPECT_TRUE(r.peers[0].installed);
    EXPECT_FALSE(r.peers[1].installed);
    ASSERT_EQ(r.measures.size(), 6u);  // each claim on the one data set of its closedness
    EXPECT_EQ(r.measures[0].failure, "");
    EXPECT_EQ(r.measures[0].difference.bound, 0.0);
    EXPECT_EQ(r.measures[1].data_set, "closed");
    EXPECT_EQ(r.measures[1].failure, "");
    EXPECT_GT(r.measures[1].difference.sampled, kIdentityTolerance);
    EXPECT_EQ(r.measures[2].failure, "left: refused by the test peer");
    EXPECT_EQ(r.measures[3].failure, "right: skipped: absent: not installed here (a test)");
    EXPECT_EQ(r.measures[4].failure, "left: the peer answered with the curve of other points");
    EXPECT_EQ(r.measures[5].failure, "right: the peer gives samples, not its pieces");
    const std::string md = peers_markdown(claims, manifest, r);
    EXPECT_NE(
        md.find("| echoer:a | echoer:b | open | 0 | identical | 1 of 1 | 0 | 0 | nowhere | holds | the same polygon |"),
        std::string::npos)
        << md;
    EXPECT_NE(md.find("| absent | skipped: absent: not installed here (a test) |"), std::string::npos) << md;
    EXPECT_NE(md.find("| echoer | echoer 1.0 | a, b, refuse, approximate (*samples*) |"), std::string::npos) << md;
    EXPECT_NE(identity_measures_csv(claims, r).find(
                  "echoer:refuse,echoer:a,0,0,identical,open,left: refused by the test peer,,,,,\n"),
              std::string::npos);
}

TEST(PeerIdentity, TheManifestAndTheClaimsAreReadWithTheirFaultsNamed) {
    const std::vector<PeerConfiguration> manifest =
        read_peer_manifest(std::string(CAGD_SOURCE_DIR) + "/peers/peers.csv");
    EXPECT_GE(manifest.size(), 20u);
    const std::vector<IdentityClaim> claims =
        read_identity_claims(std::string(CAGD_SOURCE_DIR) + "/reference/benchmark/peer_identities.csv");
    EXPECT_GE(claims.size(), 20u);
    test::ScratchDirectory scratch;
    const auto manifest_fault = [&](const std::string& row) {
        std::ofstream(scratch.path("m.csv")) << "peer,configuration,closed,library,licence,output,call\n"
                                             << row << "\n";
        return test::invalid_input_message([&] { read_peer_manifest(scratch.path("m.csv")); });
    };
    EXPECT_NE(manifest_fault("p,c,sometimes,l,MIT,exact,x").find("m.csv:2: closed \"sometimes\""), std::string::npos);
    EXPECT_NE(manifest_fault("p,c,open,l,MIT,drawn,x").find("output \"drawn\""), std::string::npos);
    EXPECT_NE(manifest_fault("../p,c,open,l,MIT,exact,x").find("\"../p\" is not a name"), std::string::npos);
    const auto claim_fault = [&](const std::string& row) {
        std::ofstream(scratch.path("c.csv")) << "left,right,closed,ends,expected,reason\n" << row << "\n";
        return test::invalid_input_message([&] { read_identity_claims(scratch.path("c.csv")); });
    };
    EXPECT_NE(claim_fault("a:b,c:d,2,0,identical,r").find("closed \"2\""), std::string::npos);
    EXPECT_NE(claim_fault("a:b,c:d,1,1,identical,r").find("ends \"1\""), std::string::npos);
    EXPECT_NE(claim_fault("a:b,c:d,0,0,same,r").find("expected \"same\""), std::string::npos);
    EXPECT_NE(claim_fault("a:b,c:d,0,0,identical,").find("needs its reason"), std::string::npos);
    // A side that names nothing known is refused when measured.
    EXPECT_NE(test::invalid_input_message([&] {
                  measure_identities({{.left = "nobody:x", .right = "cagd:cubic-b", .reason = "r"}}, {}, {}, {});
              }).find("\"nobody:x\" is neither"),
              std::string::npos);
}

TEST(PeerCurves, MethodsPageListsTheManifest) {
    std::ifstream in(std::string(CAGD_SOURCE_DIR) + "/docs/methods.md");
    std::stringstream page;
    page << in.rdbuf();
    const std::vector<PeerConfiguration> manifest =
        read_peer_manifest(std::string(CAGD_SOURCE_DIR) + "/peers/peers.csv");
    const std::string table = peer_manifest_markdown(manifest);
    EXPECT_NE(page.str().find("<!-- peers:begin -->\n" + table + "<!-- peers:end -->"), std::string::npos)
        << "docs/methods.md's table of the peers differs from peers/peers.csv: run scripts/update-docs-methods.sh "
           "(make "
           "reproduce does)";
    for (const PeerConfiguration& c : manifest) EXPECT_NE(table.find("`" + c.configuration + "`"), std::string::npos);
}

TEST(PeerCurves, OnlyTheInstalledPeersBecomeSubjects) {
    FakePeers peers;
    const InstalledPeers installed =
        installed_peer_subjects(peers.launcher,
                                {configuration("echoer", "a"), configuration("absent", "x"),
                                 configuration("echoer", "refuse"), configuration("absent", "y")},
                                [](const std::string& name) { return name != "echoer:refuse"; });
    ASSERT_EQ(installed.subjects.size(), 1u);
    EXPECT_EQ(installed.subjects[0].name, "echoer:a");
    EXPECT_EQ(installed.subjects[0].kind, "peer");
    EXPECT_EQ(installed.skipped, std::vector<std::string>{"absent: not installed here (a test)"});
    EXPECT_EQ(installed.absent, (std::vector<std::string>{"absent:x", "absent:y"}));
}

TEST(PeerCurves, ComparedPeersAreMeasuredAsTheMethodsAre) {
    // The echoer draws the polygon: its length is the polygon's, it bends nowhere, and moving the middle
    // point moves the two spans beside it. A refusal is the row's "no result" with the peer's message,
    // a crashed adapter the row's failure; the registry's rows come first.
    FakePeers peers;
    const PointList p = data_set("open", false).points;
    ComparisonOptions options;
    options.methods = {"cubic-b"};
    options.peers = {peer_subject(peers.launcher, configuration("echoer", "polygon")),
                     peer_subject(peers.launcher, configuration("echoer", "refuse")),
                     peer_subject(peers.launcher, configuration("crash", "a"))};
    options.threads = 2;
    const std::vector<MethodComparison> rows = compare_methods(p, options);
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[0].method, "cubic-b");
    const MethodComparison& polygon = find_comparison(rows, "echoer:polygon");
    EXPECT_EQ(&polygon, &rows[1]);
    EXPECT_FALSE(rows[0].peer);
    EXPECT_TRUE(polygon.peer && rows[2].peer && rows[3].peer);
    ASSERT_EQ(polygon.status, AttemptStatus::ok) << polygon.note;
    double perimeter = 0.0;
    for (Eigen::Index i = 0; i + 1 < p.rows(); ++i) perimeter += (p.row(i + 1) - p.row(i)).norm();
    EXPECT_NEAR(polygon.length, perimeter, 1e-12 * perimeter);
    ASSERT_TRUE(polygon.fairness);
    EXPECT_EQ(polygon.fairness->bending_energy, 0.0);
    EXPECT_EQ(polygon.spans, 4);
    EXPECT_EQ(polygon.locality_footprint, 2);
    ASSERT_TRUE(polygon.provenance);
    EXPECT_EQ(polygon.provenance->method, "echoer:polygon");
    EXPECT_EQ(rows[2].status, AttemptStatus::no_result);
    EXPECT_EQ(rows[2].note, "echoer: refused by the test peer");
    EXPECT_EQ(rows[3].status, AttemptStatus::failed);
    EXPECT_NE(rows[3].note.find("crash: "), std::string::npos) << rows[3].note;
    // Peers alone: no registry row.
    options.methods.clear();
    options.peers.resize(1);
    const std::vector<MethodComparison> alone = compare_methods(p, options);
    ASSERT_EQ(alone.size(), 1u);
    EXPECT_EQ(alone[0].method, "echoer:polygon");
}

TEST(PeerCurves, APeersApproximationIsMeasuredWithItsBoundStated) {
    // A peer that gives samples only hands back pieces that approximate its curve, within a bound
    // its document states (exact false, max_distance): the row measures the pieces and says so.
    FakePeers peers;
    const PointList p = data_set("open", false).points;
    ComparisonOptions options;
    options.peers = {peer_subject(peers.launcher, configuration("echoer", "approximate")),
                     peer_subject(peers.launcher, configuration("echoer", "polygon"))};
    const std::vector<MethodComparison> rows = compare_methods(p, options);
    ASSERT_EQ(rows.size(), 2u);
    ASSERT_EQ(rows[0].status, AttemptStatus::ok) << rows[0].note;
    EXPECT_EQ(rows[0].approximation, 0.25);
    EXPECT_EQ(rows[0].note,
              "its pieces approximate echoer:approximate's curve within 0.25 (the peer gives samples only)");
    EXPECT_EQ(rows[0].length, rows[1].length);  // the same polygon, measured alike
    EXPECT_FALSE(rows[1].approximation);
    EXPECT_EQ(rows[1].note, "");
    const DrawnCurve drawn = peer_drawn_curve(
        run_peer(peers.launcher, "echoer", {{.configuration = "approximate", .points = p, .closed = false}}).answers[0],
        "echoer", p, false);
    EXPECT_EQ(drawn.approximation, 0.25);
}

TEST(PeerCurves, ALargeBatchIsDrawnInRunsAndAnsweredInOrder) {
    // A peer's adapter runs once per thousand requests (its output is bounded): 2500 requests, each
    // a triangle of its own size, come back as 2500 curves in order, the polygon of each.
    FakePeers peers;
    std::vector<CurveRequest> requests;
    for (int k = 0; k < 2500; ++k) {
        PointList p(3, 2);
        p << 0, 0, k + 1, 0, 0, 1;
        requests.push_back({.points = p, .closed = k % 2 == 1});
    }
    const std::vector<DrawnCurve> drawn =
        peer_subject(peers.launcher, configuration("echoer", "polygon")).draw(requests);
    ASSERT_EQ(drawn.size(), requests.size());
    for (std::size_t k = 0; k < drawn.size(); ++k) {
        ASSERT_EQ(drawn[k].status, AttemptStatus::ok) << k << ": " << drawn[k].note;
        const double a = static_cast<double>(k) + 1.0;
        const double open = a + std::hypot(a, 1.0), length = requests[k].closed ? open + 1.0 : open;
        ASSERT_NEAR(analysis::arc_length(*drawn[k].interpolant->curve), length, 1e-12 * length) << k;
    }
}

TEST(PeerCurves, CurvesDrawnElsewhereAreASubject) {
    // The viewer's peers draw in the browser: their answers become a subject's curves, a refusal
    // the peer's message, a request beyond the answers none.
    const PointList p = data_set("open", false).points;
    FakePeers peers;
    const PeerRun run = run_peer(peers.launcher, "echoer",
                                 {{.configuration = "a", .points = p}, {.configuration = "refuse", .points = p}});
    ASSERT_EQ(run.answers.size(), 2u);
    const DrawnCurve drawn = peer_drawn_curve(run.answers[0], "echoer", p, false);
    ASSERT_EQ(drawn.status, AttemptStatus::ok) << drawn.note;
    ASSERT_TRUE(drawn.interpolant && drawn.provenance);
    EXPECT_EQ(drawn.interpolant->node_parameters, (std::vector<double>{0, 1, 2, 3, 4}));
    EXPECT_EQ(drawn.provenance->method, "echoer:a");
    const DrawnCurve refused = peer_drawn_curve(run.answers[1], "echoer", p, false);
    EXPECT_EQ(refused.status, AttemptStatus::no_result);
    EXPECT_EQ(refused.note, "echoer: refused by the test peer");
    PointList other = p;
    other(2, 1) += 1.0;  // points the curve does not pass through
    const DrawnCurve missed = peer_drawn_curve(run.answers[0], "echoer", other, false);
    EXPECT_EQ(missed.status, AttemptStatus::no_result);
    EXPECT_NE(missed.note.find("does not pass through"), std::string::npos) << missed.note;
    const CurveSubject subject = drawn_subject("echoer:a", {drawn});
    EXPECT_EQ(subject.kind, "peer");
    const std::vector<DrawnCurve> answers =
        subject.draw({{.points = p, .closed = false}, {.points = p, .closed = false}});
    ASSERT_EQ(answers.size(), 2u);
    EXPECT_EQ(answers[0].status, AttemptStatus::ok);
    EXPECT_EQ(answers[1].status, AttemptStatus::no_result);
    EXPECT_EQ(answers[1].note, "not drawn");
}
