#include "cagd/compare/classic_benchmark.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/core/point_csv.hpp"

namespace cagd::compare {

namespace {

// Overshoot samples per span (analysis/fairness_measures): the bounding box is left by a bulge at
// least a span wide, and 64 samples resolve it to 1/64 of the span; 2 quadrature pieces, since the
// energies it also computes are not used here.
constexpr analysis::FairnessSampling kOvershootSampling{.samples = 64, .quadrature_pieces = 2};

bool is_data_set_name(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
    });
}

}  // namespace

std::vector<ClassicDataSet> read_classic_data(const std::string& path) {
    const char* who = "cagd::compare::read_classic_data";
    const TextTable t = read_text_table(path, {"name", "group", "file", "closed", "source"});
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::vector<ClassicDataSet> sets;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        const std::string where = t.where(r);
        ClassicDataSet d;
        d.name = t.at(r, "name"), d.group = t.at(r, "group"), d.file = t.at(r, "file"), d.source = t.at(r, "source");
        const std::string& closed = t.at(r, "closed");
        if (!is_data_set_name(d.name))
            fail_input(who, where + ": name \"" + excerpt(d.name) + "\" is not letters, digits, '-', '_', '.'");
        for (const ClassicDataSet& other : sets)
            if (other.name == d.name) fail_input(who, where + ": the name \"" + d.name + "\" is used twice");
        if (closed != "0" && closed != "1")
            fail_input(who, where + ": closed \"" + excerpt(closed) + "\" is neither 0 nor 1");
        if (d.group.empty() || d.source.empty() || d.file.empty())
            fail_input(who, where + ": " + d.name + " needs a group, a file and a source");
        d.closed = closed == "1";
        d.points = read_points_csv((folder / d.file).string());
        sets.push_back(std::move(d));
    }
    if (sets.empty()) fail_input(who, t.source + ": no data set");
    return sets;
}

std::vector<ClassicRun> run_classic_benchmark(const std::vector<ClassicDataSet>& sets,
                                              const std::vector<std::string>& names, int threads,
                                              const WorkShare& share) {
    check_work_share(share, "compare::run_classic_benchmark");
    std::vector<methods::Configuration> configurations;
    for (const std::string& name : names) configurations.push_back(methods::find_configuration(name));
    if (names.empty()) configurations = methods::configurations();
    // The shared tables (the pseudo-spline's) are loaded once, before the workers start.
    for (const methods::Configuration& m : configurations)
        for (int d : {2, 3})
            if (m.method->prepare && m.claims.max_dimension >= d) m.method->prepare(m.values, d);
    std::vector<ClassicRun> runs(sets.size() * configurations.size());
    parallel_for(static_cast<long>(runs.size()), threads > 0 ? threads : hardware_threads(), [&](long index) {
        if (!share.owns(index)) return;
        const ClassicDataSet& d = sets[static_cast<std::size_t>(index) / configurations.size()];
        const methods::Configuration& m = configurations[static_cast<std::size_t>(index) % configurations.size()];
        ClassicRun& r = runs[static_cast<std::size_t>(index)];
        r.data_set = d.name, r.group = d.group, r.n = static_cast<int>(d.points.rows()), r.closed = d.closed,
        r.method = m.name;
        const InterpolationAttempt attempt = attempt_interpolation(m, d.points, d.closed);
        r.status = attempt.status;
        r.note = attempt.note;
        if (attempt.status != AttemptStatus::ok) return;
        const methods::Interpolant& in = *attempt.result.interpolant;
        r.shape = shape_measures(*in.curve, in.node_parameters, d.closed);
        const bool finite = std::isfinite(r.shape.bending) && std::isfinite(r.shape.variation) &&
                            std::isfinite(r.shape.max_curvature) && std::isfinite(r.shape.g2_defect);
        const auto cusp = [&r](const std::string& note) {
            r.status = AttemptStatus::cusp;
            r.note = note;
            r.shape = {};
        };
        if (!finite) return cusp("the curve has a point of zero speed, where its curvature is undefined");
        try {
            r.overshoot = analysis::fairness_measures(*in.curve, d.points, kOvershootSampling).overshoot;
        } catch (
            const InvalidInput& e) {  // its samples include the spans' ends, where Boost's pchip stops (x' = y' = 0)
            return cusp(in_user_terms(one_line(e.what())));
        }
        r.extensionality = extensionality(m, d.points, d.closed, in);
    });
    return runs;
}

std::vector<std::string> classic_runs_header() {
    std::vector<std::string> h{"data_set", "group", "n", "closed", "method", "status"};
    for (const std::string& m : shape_measure_names()) h.push_back(m);
    h.push_back("overshoot");
    h.push_back("extensionality");
    h.push_back("note");
    return h;
}

std::vector<std::vector<std::string>> classic_runs_rows(const std::vector<ClassicRun>& runs, int digits) {
    std::vector<std::vector<std::string>> rows;
    for (const ClassicRun& r : runs) {
        const bool ok = r.status == AttemptStatus::ok;
        std::vector<std::string> row{r.data_set,           r.group,  std::to_string(r.n),
                                     r.closed ? "1" : "0", r.method, to_string(r.status)};
        const ShapeMeasures& s = r.shape;
        for (const double v :
             {s.bending, s.variation, s.max_curvature, static_cast<double>(s.curvature_extrema), s.g2_defect,
              static_cast<double>(s.inflections), static_cast<double>(s.unimplied_inflections), r.overshoot})
            row.push_back(ok ? format_number(v, digits) : "");
        row.push_back(ok && r.extensionality ? format_number(*r.extensionality, digits) : "");
        std::string note = r.note;
        std::replace(note.begin(), note.end(), '\n', ' ');
        row.push_back(note);
        rows.push_back(row);
    }
    return rows;
}

namespace {

std::string number(double v) { return format_number(v, 3); }

// The runs of one data set, the ok ones first by bending energy, then the others in their order.
std::vector<const ClassicRun*> ordered_runs(const std::vector<ClassicRun>& runs, const std::string& name) {
    std::vector<const ClassicRun*> rows;
    for (const ClassicRun& r : runs)
        if (r.data_set == name) rows.push_back(&r);
    std::stable_sort(rows.begin(), rows.end(), [](const ClassicRun* a, const ClassicRun* b) {
        if ((a->status == AttemptStatus::ok) != (b->status == AttemptStatus::ok)) return a->status == AttemptStatus::ok;
        return a->status == AttemptStatus::ok && a->shape.bending < b->shape.bending;
    });
    return rows;
}

std::string points_text(const ClassicDataSet& d) {
    return std::to_string(d.points.rows()) + (d.closed ? " points, closed" : " points, open");
}

}  // namespace

std::string classic_tables_markdown(const std::vector<ClassicRun>& runs, const std::vector<ClassicDataSet>& sets) {
    std::ostringstream md;
    md << "# The interpolant benchmark on classic data\n\n"
          "Generated by `cagd benchmark --classic` (`src/cagd/compare/classic_benchmark.hpp`); do not edit. Data with "
          "no true curve: per data set every "
          "configuration's scale-free shape measures, ordered by the bending energy (lowest first). bending L∫κ² ds; "
          "variation L³∫κ'² ds; max |κ|·L; "
          "κ extrema: sign changes of κ'; G2 defect: the largest curvature jump at a point × L; inflections: sign "
          "changes of κ, (+u): u of them not implied "
          "by the polygon through the points; overshoot: how far the curve leaves the points' bounding box ÷ its "
          "diagonal; extension: how far the curve "
          "moves, ÷ L, when a point taken on it is added. Data: [`classic_runs.csv`](classic_runs.csv).\n";
    for (const ClassicDataSet& d : sets) {
        const std::vector<const ClassicRun*> rows = ordered_runs(runs, d.name);
        if (rows.empty()) continue;
        md << "\n## " << d.name << "\n\n"
           << points_text(d) << " (" << d.group << "). Source: " << d.source << ".\n\n"
           << "| method | bending | variation | max κ·L | κ extrema | G2 defect | inflections | overshoot | extension "
              "|\n"
           << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const ClassicRun* r : rows) {
            if (r->status != AttemptStatus::ok) {
                md << "| `" << r->method << "` | " << to_string(r->status) << " | | | | | | | |\n";
                continue;
            }
            const ShapeMeasures& s = r->shape;
            md << "| `" << r->method << "` | " << number(s.bending) << " | " << number(s.variation) << " | "
               << number(s.max_curvature) << " | " << s.curvature_extrema << " | " << number(s.g2_defect) << " | "
               << inflections_text(s, d.points.cols() == 3) << " | " << number(r->overshoot) << " | "
               << (r->extensionality ? number(*r->extensionality) : "no curve") << " |\n";
        }
    }
    return md.str();
}

std::string classic_summary_markdown(const std::vector<ClassicRun>& runs, const std::vector<ClassicDataSet>& sets) {
    if (runs.empty()) return "";
    std::ostringstream md;
    md << "\n#### Classic data\n\nData with a history and no true curve: the papers' data, data sets from the "
          "interpolation literature and glyph outlines "
          "(every configuration's measures in [`classic.md`](classic.md), the data in "
          "[`classic_runs.csv`](classic_runs.csv)). Per data set the lowest "
          "bending energy L∫κ² ds, the configurations whose curve has inflections the polygon through the points does "
          "not imply (how many), and the "
          "largest overshoot beyond the points' bounding box (÷ its diagonal):\n\n"
          "| data set | points | lowest bending | unimplied inflections | largest overshoot | no curve "
          "|\n|---|---|---|---|---|---|\n";
    for (const ClassicDataSet& d : sets) {
        const std::vector<const ClassicRun*> rows = ordered_runs(runs, d.name);
        if (rows.empty()) continue;
        std::string lowest = "—", overshoot = "—", failed;
        std::vector<const ClassicRun*> with, without;  // ok runs with and without unimplied inflections
        const ClassicRun* worst = nullptr;
        for (const ClassicRun* r : rows) {
            if (r->status != AttemptStatus::ok) {
                if (r->status != AttemptStatus::not_applicable)
                    failed += (failed.empty() ? "`" : ", `") + r->method + "` (" + to_string(r->status) + ")";
                continue;
            }
            if (lowest == "—") lowest = "`" + r->method + "` " + number(r->shape.bending);
            (r->shape.unimplied_inflections > 0 ? with : without).push_back(r);
            if (!worst || r->overshoot > worst->overshoot) worst = r;
        }
        if (worst) overshoot = worst->overshoot > 0 ? "`" + worst->method + "` " + number(worst->overshoot) : "none";
        // The shorter list: the configurations with unimplied inflections (how many), or those without.
        std::string unimplied = with.empty()                    ? "none"
                                : without.empty()               ? "every one"
                                : with.size() <= without.size() ? ""
                                                                : "every one but ";
        const std::vector<const ClassicRun*>& listed = with.size() <= without.size() ? with : without;
        for (std::size_t i = 0; i < listed.size(); ++i)
            unimplied += (i ? ", `" : "`") + listed[i]->method + "`" +
                         (listed[i]->shape.unimplied_inflections > 0
                              ? " (" + std::to_string(listed[i]->shape.unimplied_inflections) + ")"
                              : "");
        md << "| " << d.name << " | " << points_text(d) << " | " << lowest << " | " << unimplied << " | " << overshoot
           << " | " << (failed.empty() ? "—" : failed) << " |\n";
    }
    return md.str();
}

}  // namespace cagd::compare
