// compare/peer_truths: subjects (a method, a peer) against the truths, measured as the benchmark
// measures the registry's configurations.
#include <gtest/gtest.h>

#include "cagd/compare/peer_truths.hpp"

using namespace cagd;
using namespace cagd::compare;

TEST(PeerTruths, AMethodAsASubjectMeasuresAsTheBenchmarkDoes) {
    const std::vector<int> sizes{6, 12};
    const std::vector<TruthRun> mine =
        subject_truth_runs({method_subject(methods::find_configuration("cubic-b"), 1)}, sizes, 2);
    const std::vector<TruthRun> theirs =
        run_truth_benchmark({.sizes = sizes, .families = {}, .methods = {"cubic-b"}, .threads = 2, .share = {}});
    int compared = 0;
    for (const TruthRun& a : mine) {
        EXPECT_EQ(a.spacing, TruthSpacing::uniform);
        for (const TruthRun& b : theirs)
            if (b.family == a.family && b.closed == a.closed && b.n == a.n && b.spacing == a.spacing) {
                ++compared;
                EXPECT_EQ(a.status, b.status) << a.family << " " << a.n;
                for (int e = 0; e < 5; ++e)
                    EXPECT_EQ(truth_error(a.errors, e), truth_error(b.errors, e)) << a.family << " " << a.n << " " << e;
                EXPECT_EQ(a.shape.bending, b.shape.bending) << a.family << " " << a.n;
                EXPECT_EQ(a.extensionality, b.extensionality) << a.family << " " << a.n;
            }
    }
    EXPECT_EQ(compared, static_cast<int>(mine.size()));
    EXPECT_EQ(mine.size(), 2u * 12u);  // 8 families, 4 of them closed also as open arcs; 2 sizes
}

TEST(PeerTruths, APeersRunsFollowItsOwnCurve) {
    // The echoer draws the polygon: the line exactly, every other truth at a distance; closed curves
    // it does not draw are not applicable.
    const PeerLauncher launcher{.run = std::string(CAGD_SOURCE_DIR) + "/tests/data/peers/run",
                                .programs = "/nonexistent"};
    const PeerConfiguration echo{.peer = "echoer", .configuration = "polygon", .open = true, .closed = false};
    const std::vector<TruthRun> runs = subject_truth_runs({peer_subject(launcher, echo)}, {6, 12}, 1);
    for (const TruthRun& r : runs) {
        EXPECT_EQ(r.method, "echoer:polygon");
        if (r.closed) {
            EXPECT_EQ(r.status, AttemptStatus::not_applicable) << r.family;
        } else if (r.family == "line") {
            EXPECT_LT(r.errors.distance, 1e-15);
        } else if (r.status == AttemptStatus::ok) {
            EXPECT_GT(r.errors.distance, 1e-4) << r.family;
            EXPECT_LT(r.extensionality.value_or(1.0), 1e-15) << r.family;  // a point on a polyline changes nothing
        }
    }
    const auto orders = convergence_orders(runs);
    EXPECT_FALSE(orders.empty());
}
