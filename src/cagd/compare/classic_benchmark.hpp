#pragma once
/// @file
/// The interpolant benchmark on classic data (`cagd benchmark --classic MANIFEST`): point sets that
/// have no true curve but a history — the papers' own data, data sets from the interpolation
/// literature, the on-curve points of glyph outlines — each interpolated by every configuration of
/// the registry and measured by the scale-free shape measures of truth_benchmark.hpp, with the
/// overshoot and extensionality beside them.
///
/// The manifest is a CSV file (core/csv.hpp's rules: '#' comments, quoted fields) with the columns
///   name     the data set's name (unique; letters, digits, '-', '_', '.')
///   group    what kind of data it is ("paper", "literature", "glyph": free text, not empty)
///   file     a point CSV (core/point_csv.hpp), relative to the manifest's folder
///   closed   0 (an open curve) or 1 (closed)
///   source   where the points come from, cited bibliographically (not empty)
/// in any order after the header. Errors (InvalidInput) name the manifest, the line and the value.
///
/// Per run (classic_runs.csv): the status of interpolation_attempt.hpp; when ok, the shape measures
/// (L ∫κ² ds, L³ ∫κ'² ds, max |κ|·L, curvature extrema, G2 defect, inflections and those the polygon
/// does not imply), the overshoot (how far the curve leaves the points' bounding box, ÷ its diagonal;
/// analysis/fairness_measures at 64 samples per span) and the extensionality (truth_benchmark.hpp).
/// Deterministic: no timing; the same for any thread count.
#include <optional>
#include <string>
#include <vector>

#include "cagd/compare/truth_benchmark.hpp"
#include "cagd/compare/work_share.hpp"
#include "cagd/core/points.hpp"

namespace cagd::compare {

/// One classic data set (see above).
struct ClassicDataSet {
    std::string name;     ///< unique name
    std::string group;    ///< "paper", "literature", "glyph", …
    std::string file;     ///< the point file as the manifest names it
    bool closed = false;  ///< interpolated as a closed curve
    std::string source;   ///< bibliographic provenance
    PointList points;     ///< the points read from `file`
};
/// The data sets of the manifest at `path` (see above), their points read.
std::vector<ClassicDataSet> read_classic_data(const std::string& path);

/// One configuration on one classic data set.
struct ClassicRun {
    std::string data_set;                      ///< ClassicDataSet::name
    std::string group;                         ///< ClassicDataSet::group
    int n = 0;                                 ///< number of points
    bool closed = false;                       ///< closed curve
    std::string method;                        ///< configuration name
    AttemptStatus status = AttemptStatus::ok;  ///< what became of it (interpolation_attempt.hpp)
    std::string note;                          ///< why not ok
    ShapeMeasures shape;                       ///< when ok
    double overshoot = 0.0;                    ///< when ok: outside the points' bounding box ÷ its diagonal
    std::optional<double> extensionality;      ///< when ok (truth_benchmark.hpp's extensionality)
};
/// Every data set × configuration (`methods`: configuration or method names; empty: every one),
/// data sets in the given order; `threads` runs at once (0: the hardware's). With a share of the
/// work, the runs outside it (by their index in the result) are left empty (ClassicRun{}).
std::vector<ClassicRun> run_classic_benchmark(const std::vector<ClassicDataSet>& sets,
                                              const std::vector<std::string>& methods, int threads = 0,
                                              const WorkShare& share = {});

/// classic_runs.csv's columns: data_set, group, n, closed, method, status, the shape measures
/// (shape_measure_names), overshoot, extensionality, note.
std::vector<std::string> classic_runs_header();
/// One row per run, numbers to `digits` significant digits (empty unless ok).
std::vector<std::vector<std::string>> classic_runs_rows(const std::vector<ClassicRun>& runs, int digits = 6);
/// classic.md: per data set its provenance and every configuration's measures, ordered by the
/// bending energy (lowest first; the runs without a curve last, with their status).
std::string classic_tables_markdown(const std::vector<ClassicRun>& runs, const std::vector<ClassicDataSet>& sets);
/// The leaderboard's summary: per data set the lowest bending energy, the configurations with
/// inflections the polygon does not imply, and the largest overshoot.
std::string classic_summary_markdown(const std::vector<ClassicRun>& runs, const std::vector<ClassicDataSet>& sets);

}  // namespace cagd::compare
