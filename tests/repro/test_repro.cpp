// The harness: status classification, reference loading, number formatting.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "../support/committed_files.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "repro/artifact_run.hpp"
#include "repro/reference.hpp"

using namespace cagd;
using namespace cagd::repro;

TEST(Repro, ClassifiesReproducedDeviatesFailed) {
    ReferenceRow r;
    r.paper_value = 1.0;
    r.tolerance = 0.01;
    EXPECT_EQ(classify(r, 1.005, std::nullopt, false), ClaimStatus::reproduced);
    EXPECT_EQ(classify(r, 1.02, std::nullopt, false), ClaimStatus::failed);
    r.erratum = "E1";
    EXPECT_EQ(classify(r, 1.02, std::nullopt, false), ClaimStatus::failed) << "erratum must be documented";
    EXPECT_EQ(classify(r, 1.02, std::nullopt, true), ClaimStatus::failed) << "needs a corrected check";
    EXPECT_EQ(classify(r, 1.02, 1.001, true), ClaimStatus::deviates);
    EXPECT_EQ(classify(r, 1.02, 1.5, true), ClaimStatus::failed) << "corrected statement must hold";
    r.corrected_value = 1.02;
    EXPECT_EQ(classify(r, 1.021, std::nullopt, true), ClaimStatus::deviates);
    EXPECT_EQ(classify(r, 1.2, std::nullopt, true), ClaimStatus::failed);
    EXPECT_EQ(classify(r, std::nan(""), std::nullopt, true), ClaimStatus::failed);
}

TEST(Repro, ClaimDependsOnAChoiceOnlyWhenTheVerdictsDiffer) {
    // Every choice within tolerance, or every one outside it: the stated status stands.
    EXPECT_EQ(classify_over_choices(ClaimStatus::reproduced, {true, true, true}), ClaimStatus::reproduced);
    EXPECT_EQ(classify_over_choices(ClaimStatus::deviates, {false, false}), ClaimStatus::deviates);
    // The verdict changes with the choice, whichever way round.
    EXPECT_EQ(classify_over_choices(ClaimStatus::reproduced, {true, false}), ClaimStatus::depends);
    EXPECT_EQ(classify_over_choices(ClaimStatus::deviates, {false, true, false}), ClaimStatus::depends);
    // A failure at the stated choice is a failure, whatever other choices give.
    EXPECT_EQ(classify_over_choices(ClaimStatus::failed, {false, true}), ClaimStatus::failed);
    EXPECT_EQ(classify_over_choices(ClaimStatus::reproduced, {}), ClaimStatus::reproduced);
}

// The rule for `depends`: only readings the text allows and thresholds declared in the reference
// row before the run decide; a threshold chosen after the result cannot turn `deviates` into `depends`.
// docs/reproduction.md, the odds of a chance match: readings 20, 22, 22, 25 cover 3 of the 6
// integers 20..25 (chance 1/2); a note never counts; a non-integer reading is refused by name.
TEST(Repro, MatchOddsCountDistinctReadingsOverTheirRange) {
    using cagd::repro::ChoiceKind;
    const std::vector<cagd::repro::ChoiceValue> choices{
        {"a", 20}, {"b", 22}, {"c", 22}, {"d", 25}, {"tuned", 40, std::nullopt, ChoiceKind::note}};
    const cagd::repro::MatchOdds odds = cagd::repro::match_odds(choices, 22);
    EXPECT_EQ(odds.readings, 4);
    EXPECT_EQ(odds.matching, 2);
    EXPECT_EQ(odds.distinct, 3);
    EXPECT_EQ(odds.lowest, 20);
    EXPECT_EQ(odds.highest, 25);
    EXPECT_DOUBLE_EQ(odds.chance, 0.5);
    EXPECT_EQ(cagd::repro::match_odds(choices, 40).matching, 0) << "a note's value is no match";
    EXPECT_DOUBLE_EQ(cagd::repro::match_odds({{"only", 7}}, 7).chance, 1.0);
    try {
        cagd::repro::match_odds({{"half", 7.5}}, 7);
        ADD_FAILURE() << "a non-integer reading was accepted";
    } catch (const cagd::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("\"half\" has the value 7.5"), std::string::npos) << e.what();
    }
    EXPECT_THROW(cagd::repro::match_odds({{"tuned", 3, std::nullopt, ChoiceKind::note}}, 3), cagd::InvalidInput);
}

TEST(Repro, AThresholdChosenAfterTheResultCannotTurnADeviationIntoDepends) {
    const std::filesystem::path root = std::filesystem::temp_directory_path() / "cagd_depends_rule";
    std::filesystem::create_directories(root / "reference" / "t");
    std::ofstream(root / "reference" / "ERRATA.md") << "## t-E1\n";
    std::ofstream(root / "reference" / "t" / "a.csv")
        << "# source: a "
           "test\nid,paper_value,tolerance,tolerance_reason,erratum,corrected_value,description,thresholds,note_"
           "thresholds\n"
           "t.same,1,0,yes/no,t-E1,0,nearly the same,0.01,0.05\n"
           "t.same_code,1,0,yes/no,t-E1,0,nearly the same,0.01,\n"
           "t.value,0,0.01,definition,t-E1,0.0216,a distance,0.01,\n"
           "t.value_note,0,0.01,definition,t-E1,0.0216,a distance,0.01,\n"
           "t.value_reading,0,0.01,definition,t-E1,0.0216,a distance,0.01;0.05,\n";
    const std::string root_text = root.string();
    const char* argv[] = {"test", "--check", "--root", root_text.c_str()};
    ArtifactRun run("t", "a", "1", "test", 4, const_cast<char**>(argv));
    // The row's stated threshold (1 %) decides; its note threshold (5 %) is shown, never deciding.
    run.check_threshold("same", 0.0216, "distance");
    EXPECT_EQ(run.records().back().status, ClaimStatus::deviates) << run.records().back().choices;
    EXPECT_NE(run.records().back().choices.find("Notes"), std::string::npos) << "the note is reported";
    // A reading of the text that the experiment declares may decide (an experiment must not encode a
    // threshold this way: thresholds go through check_threshold and the row).
    run.check_over_choices("same_code", 0.0, "reading A", {{"reading B", 1.0}});
    EXPECT_EQ(run.records().back().status, ClaimStatus::depends);
    // A tolerance given by the experiment that the row does not declare: failed.
    run.check_over_choices("value", 0.0216, "threshold 1 %", {{"threshold 5 %", 0.0216, 0.05}});
    EXPECT_EQ(run.records().back().status, ClaimStatus::failed)
        << "an undeclared threshold fails the claim: " << run.records().back().choices;
    EXPECT_NE(run.records().back().choices.find("not declared"), std::string::npos) << run.records().back().choices;
    // As a note, it is shown and the deviation stands; declared in the row, it may decide.
    run.check_over_choices("value_note", 0.0216, "threshold 1 %", {{"threshold 5 %", 0.0216, 0.05, ChoiceKind::note}});
    EXPECT_EQ(run.records().back().status, ClaimStatus::deviates) << run.records().back().choices;
    run.check_over_choices("value_reading", 0.0216, "threshold 1 %", {{"threshold 5 %", 0.0216, 0.05}});
    EXPECT_EQ(run.records().back().status, ClaimStatus::depends) << run.records().back().choices;
    std::filesystem::remove_all(root);
}

TEST(Repro, LoadsReferenceWithProvenanceAndFractions) {
    const auto path = std::filesystem::temp_directory_path() / "cagd_ref_test.csv";
    std::ofstream(path) << "# source: eq (18)\nid,paper_value,tolerance,tolerance_reason,description\n"
                           "p.a,56/41,1e-9,exact fraction,\"weight, rationalised\"\n";
    const Reference ref = load_reference(path.string());
    ASSERT_EQ(ref.rows.size(), 1u);
    EXPECT_NEAR(ref.rows[0].paper_value, 56.0 / 41.0, 1e-16);
    EXPECT_EQ(ref.rows[0].paper_text, "56/41");
    EXPECT_EQ(ref.rows[0].description, "weight, rationalised");
    EXPECT_EQ(ref.provenance.at(0), "source: eq (18)");
}

TEST(Repro, RejectsMalformedReferenceFiles) {
    const auto path = std::filesystem::temp_directory_path() / "cagd_ref_bad.csv";
    std::ofstream(path) << "id,paper_value,tolerance,tolerance_reason\np.a,1,0.1,x\n";
    EXPECT_THROW(load_reference(path.string()), cagd::InvalidInput) << "no provenance";
    std::ofstream(path) << "# s\nid,paper_value,tolerance,tolerance_reason\np.a,one,0.1,x\n";
    EXPECT_THROW(load_reference(path.string()), cagd::InvalidInput) << "unparsable number";
    std::ofstream(path) << "# s\nid,paper_value,tolerance,tolerance_reason\np.a,1,0.1,x\np.a,1,0.1,x\n";
    EXPECT_THROW(load_reference(path.string()), cagd::InvalidInput) << "duplicate id";
    std::ofstream(path) << "# s\nid,paper_value,tolerance\np.a,1,0.1\n";
    EXPECT_THROW(load_reference(path.string()), cagd::InvalidInput) << "no tolerance reason";
}

TEST(Repro, EveryReferenceFileOfTheRepositoryLoads) {
    int files = 0;
    // Not claims: data/ holds point tables; benchmark/ the benchmark's classic data sets and their
    // manifest (read by compare::read_classic_data, tests/compare/test_classic_benchmark.cpp).
    const std::filesystem::path benchmark = std::filesystem::path(CAGD_SOURCE_DIR) / "reference" / "benchmark";
    for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(CAGD_SOURCE_DIR) + "/reference"))
        if (e.path().extension() == ".csv" && e.path().parent_path().filename() != "data" &&
            std::mismatch(benchmark.begin(), benchmark.end(), e.path().begin(), e.path().end()).first !=
                benchmark.end()) {
            EXPECT_NO_THROW(load_reference(e.path().string())) << e.path();
            ++files;
        }
    EXPECT_GT(files, 0);
    EXPECT_FALSE(load_erratum_ids(std::string(CAGD_SOURCE_DIR) + "/reference/ERRATA.md").empty());
}

TEST(Repro, EveryErratumHeadingSaysWhatIsWrongAndKeepsItsAnchor) {
    // "## <id> — <what is wrong>", after an explicit anchor <a id="<id in lower case>">, so that the
    // report's links (ERRATA.md#<id>) do not depend on the heading's words.
    const std::string path = std::string(CAGD_SOURCE_DIR) + "/reference/ERRATA.md";
    const std::vector<Erratum> errata = load_errata(path);
    ASSERT_GT(errata.size(), 30u);
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const Erratum& e : errata) {
        EXPECT_GE(e.title.size(), 20u) << e.id << ": the heading says what is wrong, not only the id";
        std::string lower = e.id;
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        EXPECT_NE(text.find("<a id=\"" + lower + "\"></a>\n\n## " + e.id + " — "), std::string::npos) << e.id;
    }
}

TEST(Repro, NumberFormattingIsStable) {
    EXPECT_EQ(format_number(-0.0), "0");
    EXPECT_EQ(format_number(1.0 / 3.0), "0.3333333333");
    EXPECT_EQ(format_number(1e-20), "1e-20");
    EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
    EXPECT_EQ(split_csv_line("a,\"b,c\",d").size(), 3u);
}

// reference/ERRATA.md (pseudo_energy-E4) says which matches of Tables 5–6's equivalent points are
// consistent with chance and which are not: the committed odds table must say the same.
TEST(Repro, ErratumE4StatesTheOddsTheExperimentComputed) {
    std::set<std::string> chance, evidence;
    for (auto& row : cagd::test::committed_csv("results/pseudo_energy/table5_table6_match_odds.csv")) {
        const std::string cell = "n" + row["n"] + (row["table"][0] == '5' ? " length" : " area");
        if (row["what_a_match_shows"] == "consistent with chance") chance.insert(cell);
        if (row["what_a_match_shows"] == "evidence for the matching readings") evidence.insert(cell);
    }
    EXPECT_EQ(chance, (std::set<std::string>{"n3 length", "n3 area", "n4 length", "n4 area", "n5 length", "n5 area"}));
    EXPECT_EQ(evidence, (std::set<std::string>{"n10 length", "n6 area", "n9 area"}));
    const std::string text = cagd::test::committed_text("reference/ERRATA.md");
    EXPECT_NE(text.find("the matches at\n   n = 3, 4 and 5 are consistent with chance"), std::string::npos);
    EXPECT_NE(text.find("those of n = 10's length and of the areas at n = 6 and 9 are below\n   1/20"),
              std::string::npos);
}
