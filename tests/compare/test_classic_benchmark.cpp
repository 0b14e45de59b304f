// The interpolant benchmark on classic data (compare/classic_benchmark.hpp) and the inflection
// measures of compare/truth_benchmark.hpp it reports: the manifest and its errors, the inflection
// counts against closed forms and against a second, sampled count, and the runs' classification.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/compare/classic_benchmark.hpp"
#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/errors.hpp"

using namespace cagd;
using namespace cagd::compare;

namespace {

const std::string kManifest = std::string(CAGD_SOURCE_DIR) + "/reference/benchmark/classic_data.csv";

// (t, sin t): κ = −sin t / (1 + cos² t)^(3/2) changes sign at every multiple of π.
class SineCurve : public Curve {
public:
    SineCurve(double a, double b) : a_(a), b_(b) {}
    int dimension() const override { return 2; }
    double t_min() const override { return a_; }
    double t_max() const override { return b_; }
    void evaluate_jet(double t, int first, cagd::JetSide, Eigen::Ref<Eigen::MatrixXd> out) const override {
        const int order = first + static_cast<int>(out.rows()) - 1;
        Eigen::MatrixXd j = Eigen::MatrixXd::Zero(order + 1, 2);
        for (int k = 0; k <= order; ++k) j(k, 1) = std::sin(t + k * std::numbers::pi / 2);
        j(0, 0) = t;
        if (order >= 1) j(1, 0) = 1.0;
        take_rows(j, first, out);
    }
    std::vector<double> breakpoints() const override { return {a_, b_}; }

private:
    double a_, b_;
};

// A manifest with `body` after the header line `header`, beside a 4-point file points.csv.
std::string write_manifest(const std::string& name, const std::string& header, const std::string& body) {
    const auto dir = std::filesystem::temp_directory_path() / ("cagd_classic_" + name);
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "points.csv") << "x,y\n0,0\n1,1\n2,0\n3,1\n";
    std::ofstream(dir / "manifest.csv") << "# a test manifest\n" << header << "\n" << body;
    return (dir / "manifest.csv").string();
}

std::string refusal(const std::string& path) {
    try {
        read_classic_data(path);
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

TEST(ClassicBenchmark, TheManifestReadsEveryDataSetWithItsProvenance) {
    const std::vector<ClassicDataSet> sets = read_classic_data(kManifest);
    ASSERT_GE(sets.size(), 10u);
    int papers = 0, literature = 0, glyphs = 0;
    for (const ClassicDataSet& d : sets) {
        EXPECT_GE(d.points.rows(), 4) << d.name;
        EXPECT_EQ(d.points.cols(), 2) << d.name;
        EXPECT_FALSE(d.source.empty()) << d.name;
        papers += d.group == "paper", literature += d.group == "literature", glyphs += d.group == "glyph";
        if (d.group == "glyph") {
            EXPECT_TRUE(d.closed) << d.name << ": a glyph contour is closed";
        }
    }
    EXPECT_GE(papers, 3);
    EXPECT_GE(literature, 2);
    EXPECT_GE(glyphs, 5);
    // The papers' files are read where the experiments read them: Newbery and Garrett's 13 points.
    const auto table1 =
        std::find_if(sets.begin(), sets.end(), [](const ClassicDataSet& d) { return d.name == "newbery-garrett"; });
    ASSERT_NE(table1, sets.end());
    EXPECT_EQ(table1->points.rows(), 13);
    EXPECT_EQ(table1->points(1, 0), 0.3);
}

TEST(ClassicBenchmark, ABadManifestIsRefusedNamingTheLineAndTheValue) {
    const std::string header = "name,group,file,closed,source";
    EXPECT_NE(refusal(write_manifest("column", "name,group,file,source", "x,paper,points.csv,a source\n"))
                  .find("no column \"closed\""),
              std::string::npos);
    const std::string two = refusal(write_manifest("closed", header, "x,paper,points.csv,2,a source\n"));
    EXPECT_NE(two.find("manifest.csv:3"), std::string::npos) << two;
    EXPECT_NE(two.find("closed \"2\""), std::string::npos) << two;
    EXPECT_NE(refusal(write_manifest("twice", header, "x,paper,points.csv,0,s\nx,paper,points.csv,1,s\n"))
                  .find("\"x\" is used twice"),
              std::string::npos);
    EXPECT_NE(refusal(write_manifest("name", header, "a b,paper,points.csv,0,s\n")).find("name \"a b\""),
              std::string::npos);
    EXPECT_NE(
        refusal(write_manifest("source", header, "x,paper,points.csv,0,\n")).find("needs a group, a file and a source"),
        std::string::npos);
    EXPECT_NE(refusal(write_manifest("missing", header, "x,paper,absent.csv,0,s\n")).find("absent.csv"),
              std::string::npos);
    EXPECT_NE(
        refusal(write_manifest("fields", header, "x,paper,points.csv,0\n")).find("4 fields where the header has 5"),
        std::string::npos);
    EXPECT_NE(refusal(write_manifest("empty", header, "")).find("no data set"), std::string::npos);
    // Quoted sources hold commas.
    const auto sets = read_classic_data(
        write_manifest("quoted", header, "x,paper,points.csv,1,\"A. Author, B. Author, J. Curves 1 (2000) 1-2\"\n"));
    ASSERT_EQ(sets.size(), 1u);
    EXPECT_EQ(sets[0].source, "A. Author, B. Author, J. Curves 1 (2000) 1-2");
    EXPECT_TRUE(sets[0].closed);
}

TEST(InflectionMeasures, TheSineHasItsInflectionsAtTheMultiplesOfPi) {
    constexpr double pi = std::numbers::pi;
    // Nodes at the crests π/2, 3π/2, 5π/2, 7π/2: the polygon zigzags (turns +, −: one change) and the
    // curve inflects at π, 2π, 3π; two of the three are not implied.
    const SineCurve crests(pi / 2, 7 * pi / 2);
    const ShapeMeasures m = shape_measures(crests, {pi / 2, 3 * pi / 2, 5 * pi / 2, 7 * pi / 2}, false);
    EXPECT_EQ(m.inflections, 3);
    EXPECT_EQ(m.unimplied_inflections, 2);
    // Nodes at the zeros 0, 2π, 4π: collinear points, no turn, every inflection unimplied.
    const SineCurve zeros(0, 4 * pi);
    const ShapeMeasures z = shape_measures(zeros, {0, 2 * pi, 4 * pi}, false);
    EXPECT_EQ(z.inflections, 3);
    EXPECT_EQ(z.unimplied_inflections, 3);
    // Nodes every π/2 from π/4: the polygon turns with the curve, so all three are implied.
    std::vector<double> dense;
    for (double t = pi / 4; t <= 15 * pi / 4 + 1e-12; t += pi / 2) dense.push_back(t);
    const SineCurve quarters(pi / 4, 15 * pi / 4);
    const ShapeMeasures q = shape_measures(quarters, dense, false);
    EXPECT_EQ(q.inflections, 3);
    EXPECT_EQ(q.unimplied_inflections, 0);
}

TEST(InflectionMeasures, TheCountAgreesWithTheSampledSignChangesOnEveryClassicSet) {
    // A second computation: analysis/fairness_measures counts the sign changes of κ on 512 samples per
    // piece (not around a closed curve, hence at most one less there).
    for (const ClassicDataSet& d : read_classic_data(kManifest))
        for (const char* method : {"cubic-b", "pseudo-spline-none", "s-spline-m1"}) {
            const InterpolationAttempt a =
                attempt_interpolation(methods::find_configuration(method), d.points, d.closed);
            ASSERT_EQ(a.status, AttemptStatus::ok) << d.name << " " << method << ": " << a.note;
            const ShapeMeasures m =
                shape_measures(*a.result.interpolant->curve, a.result.interpolant->node_parameters, d.closed);
            const int sampled =
                analysis::fairness_measures(*a.result.interpolant->curve, d.points, 512).curvature_sign_changes;
            if (d.closed)
                EXPECT_TRUE(m.inflections == sampled || m.inflections == sampled + 1)
                    << d.name << " " << method << ": " << m.inflections << " vs " << sampled;
            else
                EXPECT_EQ(m.inflections, sampled) << d.name << " " << method;
            EXPECT_LE(m.unimplied_inflections, m.inflections);
        }
}

TEST(ClassicBenchmark, RunsAreClassifiedAndMeasuredAsTheirCurvesAre) {
    const std::vector<ClassicDataSet> all = read_classic_data(kManifest);
    std::vector<ClassicDataSet> sets;
    for (const ClassicDataSet& d : all)
        if (d.name == "knot" || d.name == "glyph-C") sets.push_back(d);
    ASSERT_EQ(sets.size(), 2u);
    const std::vector<ClassicRun> runs =
        run_classic_benchmark(sets, {"cubic-b", "boost-pchip", "curvature-profile"}, 2);
    ASSERT_EQ(runs.size(), 6u);
    for (const ClassicRun& r : runs) {
        if (r.method == "boost-pchip" && r.data_set == "glyph-C") {
            EXPECT_EQ(r.status, cagd::compare::AttemptStatus::not_applicable) << "pchip is not periodic";
            continue;
        }
        if (r.method == "boost-pchip") {
            // Its x(u) and y(u) are flat together at the knot's middle points: zero speed.
            EXPECT_EQ(r.status, cagd::compare::AttemptStatus::cusp) << r.note;
            EXPECT_NE(r.note.find("zero speed"), std::string::npos) << r.note;
            continue;
        }
        ASSERT_EQ(r.status, cagd::compare::AttemptStatus::ok) << r.data_set << " " << r.method << ": " << r.note;
        // The same curve measured directly.
        const ClassicDataSet& d = r.data_set == "knot" ? sets[0] : sets[1];
        const methods::InterpolationResult c =
            methods::interpolate(methods::find_configuration(r.method), d.points, d.closed);
        const ShapeMeasures direct = shape_measures(*c.interpolant->curve, c.interpolant->node_parameters, d.closed);
        EXPECT_DOUBLE_EQ(r.shape.bending, direct.bending);
        EXPECT_EQ(r.shape.inflections, direct.inflections);
        EXPECT_GE(r.overshoot, 0.0);
        ASSERT_TRUE(r.extensionality.has_value());
        // The clothoid spline is extensional (a point on it leaves it in place), the chordal cubic is not.
        if (r.method == "curvature-profile") {
            EXPECT_LT(*r.extensionality, 1e-9);
        }
        if (r.method == "cubic-b") {
            EXPECT_GT(*r.extensionality, 1e-6);
        }
    }
    // Rows: one per run, the numbers empty unless ok.
    const auto rows = classic_runs_rows(runs);
    ASSERT_EQ(rows.size(), runs.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        ASSERT_EQ(rows[i].size(), classic_runs_header().size());
        EXPECT_EQ(rows[i][6].empty(), runs[i].status != cagd::compare::AttemptStatus::ok);
    }
    // The tables name every data set with its source.
    const std::string md = classic_tables_markdown(runs, sets);
    EXPECT_NE(md.find("## knot"), std::string::npos);
    EXPECT_NE(md.find(sets[1].source), std::string::npos);
}

TEST(ClassicBenchmark, NoClosedDataSetGivesALoopingCurve) {
    // compare flags a closed curve that loops where its points do not ("loops"); the direct methods'
    // curves through every closed data set of the manifest are not flagged.
    const ComparisonOptions o{.methods = {"cubic-b", "pseudo-spline-exact"}, .closed = true, .locality = false};
    int closed_sets = 0;
    for (const ClassicDataSet& d : read_classic_data(kManifest)) {
        if (!d.closed) continue;
        ++closed_sets;
        for (const MethodComparison& m : compare_methods(d.points, o))
            EXPECT_NE(m.status, cagd::compare::AttemptStatus::loops) << d.name << ", " << m.method << ": " << m.note;
    }
    EXPECT_GT(closed_sets, 0);
}
