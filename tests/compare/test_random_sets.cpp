// compare/random_sets: the benchmark's seeded random sets, their outcome counts and run times.
#include <gtest/gtest.h>

#include <algorithm>

#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/compare/random_sets.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/random_walk.hpp"

using namespace cagd;
using namespace cagd::compare;

TEST(RandomSets, SetsAreSeededWalksAndPointsInTheUnitSquare) {
    EXPECT_EQ(random_set(RandomSetKind::walk, 40, 7), random_walk(40, 7, 0.1, 2.0, 1.0));
    EXPECT_EQ(random_set(RandomSetKind::scatter, 40, 7), random_set(RandomSetKind::scatter, 40, 7));
    EXPECT_NE(random_set(RandomSetKind::scatter, 40, 7), random_set(RandomSetKind::scatter, 40, 8));
    const PointList s = random_set(RandomSetKind::scatter, 500, 3);
    EXPECT_GE(s.minCoeff(), 0.0);
    EXPECT_LT(s.maxCoeff(), 1.0);
    EXPECT_GT(s.maxCoeff(), 0.99) << "500 points fill the square";
    EXPECT_THROW(random_set(RandomSetKind::walk, 1, 0), InvalidInput);
}

TEST(RandomSets, CountsAddUpAndDoNotDependOnTheThreads) {
    RandomSetOptions o;
    o.sizes = {8, 16};
    o.sets = 40;
    o.methods = {"cubic-b", "hermite-b", "spiro", "eigen-spline-3"};
    o.threads = 1;
    const std::vector<RandomSetSummary> one = run_random_sets(o);
    o.threads = 2;
    const std::vector<RandomSetSummary> two = run_random_sets(o);
    ASSERT_EQ(one.size(), 2u * 2 * 4);
    EXPECT_EQ(random_sets_rows(one), random_sets_rows(two));
    for (const RandomSetSummary& s : one) {
        EXPECT_EQ(s.ok + s.no_result() + s.refused + s.not_applicable, s.sets) << s.method;
        EXPECT_EQ(s.seconds.size(), static_cast<std::size_t>(s.sets - s.not_applicable));
        EXPECT_DOUBLE_EQ(s.failure_rate(),
                         static_cast<double>(s.no_result() + s.refused) / (s.sets - s.not_applicable));
        if (s.method == "cubic-b") {
            EXPECT_EQ(s.ok, s.sets) << "a linear system with a unique solution";
        }
    }
    // Spiro has no solution on some scattered points (about a third at 16 points); walks turning
    // at most 1 rad are easier.
    const auto find = [&](RandomSetKind kind, int n, const std::string& m) {
        return *std::find_if(one.begin(), one.end(),
                             [&](const RandomSetSummary& s) { return s.kind == kind && s.n == n && s.method == m; });
    };
    EXPECT_GT(find(RandomSetKind::scatter, 16, "spiro").no_result(), 0);
    // Each failure is counted in its class: the statuses of the same sets tried one by one.
    for (const std::string m : {"spiro", "curvature-profile"}) {
        RandomSetOptions single = o;
        single.sizes = {16};
        single.methods = {m};
        const std::vector<RandomSetSummary> runs = run_random_sets(single);
        const RandomSetSummary& s = runs.at(1);  // scatter, 16 points
        ASSERT_EQ(s.kind, RandomSetKind::scatter);
        RandomSetSummary tally;
        for (int set = 0; set < o.sets; ++set) {
            const InterpolationAttempt a = attempt_interpolation(methods::find_configuration(m),
                                                                 random_set(RandomSetKind::scatter, 16, set), false);
            if (a.status != AttemptStatus::no_result) continue;
            const Status st = a.result.outcome.status;
            ++(st == Status::no_solution      ? tally.no_solution
               : st == Status::no_convergence ? tally.no_convergence
                                              : tally.not_representable);
        }
        EXPECT_EQ(s.no_solution, tally.no_solution) << m;
        EXPECT_EQ(s.no_convergence, tally.no_convergence) << m;
        EXPECT_EQ(s.not_representable, tally.not_representable) << m;
        EXPECT_GT(s.no_result(), 0) << m << ": the classes were exercised";
    }
    EXPECT_LT(find(RandomSetKind::walk, 16, "spiro").failure_rate(),
              find(RandomSetKind::scatter, 16, "spiro").failure_rate());
}

TEST(RandomSets, TimingRowsAreOrderedQuantiles) {
    RandomSetOptions o;
    o.sizes = {12};
    o.sets = 25;
    o.methods = {"hermite-a", "curvature-profile"};
    const std::vector<RandomSetSummary> runs = run_random_sets(o);
    const std::vector<std::vector<std::string>> rows = random_set_timing_rows(runs);
    ASSERT_EQ(rows.size(), runs.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        ASSERT_EQ(rows[i].size(), random_set_timing_header().size());
        EXPECT_EQ(rows[i][3], std::to_string(runs[i].seconds.size()));
        const double median = std::stod(rows[i][4]), p90 = std::stod(rows[i][5]), most = std::stod(rows[i][6]);
        EXPECT_GT(median, 0.0);
        EXPECT_LE(median, p90);
        EXPECT_LE(p90, most);
        const double largest = *std::max_element(runs[i].seconds.begin(), runs[i].seconds.end());
        EXPECT_NEAR(most, largest, 6e-4 * largest) << "the largest run's time, to 4 digits";
    }
}

TEST(RandomSets, MarkdownListsFailuresAndTheMethodsThatNeverFail) {
    RandomSetOptions o;
    o.sizes = {16};
    o.sets = 30;
    o.methods = {"cubic-b", "spiro"};
    const std::vector<RandomSetSummary> runs = run_random_sets(o);
    const std::string md = random_sets_markdown(runs);
    EXPECT_NE(md.find("#### Failure rates on seeded random sets"), std::string::npos);
    EXPECT_NE(md.find("| spiro |"), std::string::npos);
    // Spiro's failures over all sizes, by class, as the summaries count them.
    for (const RandomSetSummary& s : runs)
        if (s.method == "spiro" && s.kind == RandomSetKind::scatter) {
            const std::string classes = std::to_string(s.no_solution) + " no solution, " +
                                        std::to_string(s.no_convergence) + " no convergence, " +
                                        std::to_string(s.refused) + " refused |";
            EXPECT_NE(md.find(classes), std::string::npos) << classes << "\n" << md;
            EXPECT_GT(s.no_result(), 0);
        }
    EXPECT_NE(md.find("Never failed: cubic-b"), std::string::npos);
    EXPECT_EQ(random_sets_markdown({}), "");
}

TEST(RandomSets, BadOptionsAreRefused) {
    RandomSetOptions o;
    o.sets = 0;
    EXPECT_THROW(run_random_sets(o), InvalidInput);
    o.sets = 1;
    o.sizes = {2};
    EXPECT_THROW(run_random_sets(o), InvalidInput);
    o.sizes = {8};
    o.methods = {"no-such-method"};
    EXPECT_THROW(run_random_sets(o), InvalidInput);
}
