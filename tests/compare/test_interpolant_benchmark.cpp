// compare/interpolant_benchmark: the benchmark as a plan, split into shares whose parts merge into
// exactly the whole run's files, and the parts' damage, mix-ups and gaps refused by name.
#include <gtest/gtest.h>

#include <cstring>

#include "cagd/compare/interpolant_benchmark.hpp"
#include "cagd/core/checksum.hpp"
#include "cagd/core/errors.hpp"

using namespace cagd;
using namespace cagd::compare;

namespace {

// A small plan touching every kind of unit: truth runs (open, closed, planar, space; a method that
// refuses closed input), classic data and random sets.
BenchmarkPlan small_plan() {
    BenchmarkPlan p;
    p.truth.sizes = {6, 12};
    p.truth.families = {"circle", "helix"};
    p.truth.methods = {"cubic-b", "spiro", "boost-pchip"};
    p.random.sizes = {8};
    p.random.sets = 7;
    p.random.methods = p.truth.methods;
    PointList zigzag(5, 2);
    zigzag << 0, 0, 1, 1, 2, 0, 3, 1, 4, 0;
    p.classic.push_back({.name = "zigzag",
                         .group = "test",
                         .file = "zigzag.csv",
                         .closed = false,
                         .source = "a zigzag, 100% made up",
                         .points = zigzag});
    return p;
}

// The parts of `count` shares of `plan`, named "part k".
std::vector<std::pair<std::string, std::string>> parts_of(const BenchmarkPlan& plan, int count) {
    std::vector<std::pair<std::string, std::string>> parts;
    for (int k = 0; k < count; ++k) {
        const WorkShare share{k, count};
        parts.emplace_back("part " + std::to_string(k + 1),
                           benchmark_part_text(plan, share, run_benchmark(plan, share, 1)));
    }
    return parts;
}

// The InvalidInput message of merging `parts`, or "" when the merge succeeds.
std::string merge_error(const BenchmarkPlan& plan, const std::vector<std::pair<std::string, std::string>>& parts) {
    try {
        merge_benchmark_parts(plan, parts);
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "";
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(InterpolantBenchmark, PartsOfAnyShareCountMergeIntoTheWholeRunsFiles) {
    const BenchmarkPlan plan = small_plan();
    const BenchmarkResults whole = run_benchmark(plan, {}, 2);
    const auto files = benchmark_files(plan, whole);
    ASSERT_GE(files.size(), 7u)
        << "truth_runs, convergence_orders, leaderboard, random_sets, classic_runs, classic.md, convergence .dat";
    for (const int count : {1, 2, 3, 5}) {
        auto parts = parts_of(plan, count);
        std::swap(parts.front(), parts.back());  // any order
        const BenchmarkResults merged = merge_benchmark_parts(plan, parts);
        EXPECT_EQ(benchmark_files(plan, merged), files) << count << " shares";
        ASSERT_EQ(merged.random.size(), whole.random.size());
        for (std::size_t i = 0; i < merged.random.size(); ++i)
            EXPECT_EQ(merged.random[i].seconds.size(), whole.random[i].seconds.size()) << "every run time travels";
    }
}

TEST(InterpolantBenchmark, APartCarriesEveryValueBitForBit) {
    const BenchmarkPlan plan = small_plan();
    const BenchmarkResults whole = run_benchmark(plan, {}, 2);
    const BenchmarkResults back = merge_benchmark_parts(plan, {{"whole", benchmark_part_text(plan, {}, whole)}});
    ASSERT_EQ(back.truth.size(), whole.truth.size());
    int ok = 0;
    for (std::size_t i = 0; i < whole.truth.size(); ++i) {
        const TruthRun &a = whole.truth[i], &b = back.truth[i];
        EXPECT_EQ(b.method, a.method);
        EXPECT_EQ(b.note, a.note);
        for (int e = 0; e < 5; ++e)
            EXPECT_TRUE(same_bits(truth_error(a.errors, e), truth_error(b.errors, e)))
                << a.method << " " << truth_error_names()[static_cast<std::size_t>(e)];
        EXPECT_TRUE(same_bits(a.shape.bending, b.shape.bending) &&
                    same_bits(a.truth_shape.variation, b.truth_shape.variation));
        EXPECT_EQ(a.extensionality.has_value(), b.extensionality.has_value());
        if (a.extensionality) {
            EXPECT_TRUE(same_bits(*a.extensionality, *b.extensionality));
        }
        ok += a.status == cagd::compare::AttemptStatus::ok;
    }
    EXPECT_GT(ok, 0);
    ASSERT_EQ(back.classic.size(), 3u);
    EXPECT_TRUE(same_bits(back.classic[0].overshoot, whole.classic[0].overshoot));
    EXPECT_EQ(back.classic[0].group, "test");
}

TEST(InterpolantBenchmark, NotesWithLineBreaksAndPercentSignsTravel) {
    const BenchmarkPlan plan = small_plan();
    BenchmarkResults r = run_benchmark(plan, {}, 2);
    r.truth[0].note = "two\nlines, 100%0A \"quoted\"\r";
    r.classic[1].group = "%25";
    const BenchmarkResults back = merge_benchmark_parts(plan, {{"whole", benchmark_part_text(plan, {}, r)}});
    EXPECT_EQ(back.truth[0].note, r.truth[0].note);
    EXPECT_EQ(back.classic[1].group, "%25");
}

TEST(InterpolantBenchmark, MissingTwiceForeignAndDamagedPartsAreRefusedByName) {
    const BenchmarkPlan plan = small_plan();
    auto parts = parts_of(plan, 3);
    EXPECT_EQ(merge_error(plan, parts), "");
    EXPECT_NE(merge_error(plan, {parts[0], parts[2]}).find("part 2 of 3 is missing"), std::string::npos)
        << merge_error(plan, {parts[0], parts[2]});
    EXPECT_NE(merge_error(plan, {parts[0], parts[2], parts[2]}).find("part 3 of 3 again"), std::string::npos);
    const std::string twice = merge_error(plan, {parts[0], parts[1], parts[1], parts[2]});
    EXPECT_NE(twice.find("part 2 of 3 again (first in part 2)"), std::string::npos) << twice;
    BenchmarkPlan other = plan;
    other.truth.sizes = {6, 13};
    const std::string foreign = merge_error(other, parts);
    EXPECT_NE(foreign.find("part 1:3: \"plan,"), std::string::npos) << foreign;
    EXPECT_NE(foreign.find("another plan"), std::string::npos) << foreign;
    other = plan;
    other.classic[0].points(2, 1) = 1e-300;  // one coordinate of the classic data differs
    EXPECT_NE(merge_error(other, parts).find("another plan"), std::string::npos);
    auto damaged = parts;
    damaged[1].second[damaged[1].second.size() / 2] ^= 1;  // one flipped bit
    const std::string flipped = merge_error(plan, damaged);
    EXPECT_NE(flipped.find("part 2: its checksum does not match"), std::string::npos) << flipped;
    const std::string of_two = merge_error(plan, {parts[0], parts_of(plan, 2)[1], parts[2]});
    EXPECT_NE(of_two.find("a part of 2, the others of 3"), std::string::npos) << of_two;
    EXPECT_NE(merge_error(plan, {}).find("no parts"), std::string::npos);
    EXPECT_NE(merge_error(plan, {{"notes.txt", "hello\n"}}).find("notes.txt: no checksum line"), std::string::npos);
}

TEST(InterpolantBenchmark, ARecordOutsideItsShareIsRefused) {
    const BenchmarkPlan plan = small_plan();
    const BenchmarkResults whole = run_benchmark(plan, {}, 2);
    // Share 1 of 2 claiming every run: the text of the whole run relabelled as part 1 of 2.
    std::string text = benchmark_part_text(plan, {}, whole);
    text = text.substr(0, text.rfind("# checksum"));
    text.replace(text.find("part,1,1"), 8, "part,1,2");
    const std::string error = merge_error(plan, {{"greedy", text + checksum_line(text)}, parts_of(plan, 2)[1]});
    EXPECT_NE(error.find("greedy:4: units,36,3,6 declares 18 truth, 2 classic and 6 random records for part 1 of 2; "
                         "it holds 36, 3 and 6"),
              std::string::npos)
        << error;
    // As many records as its share, one of them another share's.
    const auto halves = parts_of(plan, 2);
    std::string swapped = halves[0].second.substr(0, halves[0].second.rfind("# checksum"));
    swapped.replace(swapped.find("\ntruth,0,"), 9, "\ntruth,1,");
    const std::string outside = merge_error(plan, {{"swapped", swapped + checksum_line(swapped)}, halves[1]});
    EXPECT_NE(outside.find("swapped:5: truth run 1 is not part 1's"), std::string::npos) << outside;
    // A units line claiming ten million runs is refused before anything is sized from it.
    std::string inflated = halves[0].second.substr(0, halves[0].second.rfind("# checksum"));
    inflated.replace(inflated.find("units,36,"), 9, "units,10000000,");
    const std::string big = merge_error(plan, {{"inflated", inflated + checksum_line(inflated)}, halves[1]});
    EXPECT_NE(big.find("inflated:4: units,10000000,3,6 declares 5000000 truth"), std::string::npos) << big;
}

// Every value of a part is finite: a resealed nan, inf or overflowing hex float is refused by field.
TEST(InterpolantBenchmark, NonFiniteValuesAreRefused) {
    const BenchmarkPlan plan = small_plan();
    const auto whole = parts_of(plan, 1)[0];
    std::string text = whole.second.substr(0, whole.second.rfind("# checksum"));
    const std::size_t record = text.find("\ntruth,0,");
    ASSERT_NE(record, std::string::npos);
    // The distance: the first number after the record's nine leading fields.
    std::size_t at = record + 1;
    for (int field = 0; field < 9; ++field) at = text.find(',', at) + 1;
    const std::size_t end = text.find(',', at);
    for (const std::string bad : {"nan", "inf", "-inf", "0x1p+2000"}) {
        std::string t = text;
        t.replace(at, end - at, bad);
        const std::string error = merge_error(plan, {{"resealed", t + checksum_line(t)}});
        EXPECT_NE(error.find("\"" + bad + "\" is not a finite number"), std::string::npos) << bad << ": " << error;
    }
}

TEST(InterpolantBenchmark, ASharesRunsOutsideItAreLeftEmpty) {
    const BenchmarkPlan plan = small_plan();
    const BenchmarkResults half = run_benchmark(plan, {1, 2}, 1);
    for (std::size_t i = 0; i < half.truth.size(); ++i) EXPECT_EQ(half.truth[i].method.empty(), i % 2 == 0) << i;
    for (std::size_t i = 0; i < half.classic.size(); ++i) EXPECT_EQ(half.classic[i].method.empty(), i % 2 == 0) << i;
    int sets = 0;
    for (const RandomSetSummary& s : half.random) sets += s.sets;
    EXPECT_EQ(sets, 7 * 3)
        << "the odd tasks of 14 (walk and scatter, 7 sets each): 7 sets for each of 3 configurations";
    try {
        run_benchmark(plan, {2, 2});
        ADD_FAILURE() << "share 2 of 2 accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("share 2 of 2"), std::string::npos) << e.what();
    }
}
