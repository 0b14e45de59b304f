#pragma once
/// @file
/// The files of a comparison folder, defined once: `cagd compare --out DIR` (cli/compare_command)
/// and the report's comparisons (repro/comparison_record) store these tables as they are, and
/// scripts/plot/compare_panels.gp reads them by column name.
///
///   measures.csv   comparison_header / comparison_rows: one row per method (seconds with timing)
///   points.csv     x, y[, z]: the data points
///   curves.csv     index, x, y[, z]: curve samples, method by method (FigureData::curves)
///   curvature.csv  index, s, kappa[, tau]: κ(s) (and τ(s) in space), method by method
///   combs.csv      index, x, y, tip_x, tip_y: curvature comb teeth (planar; header only in space)
///   methods.csv    figure_methods_header / rows: each method's first row and row count per file
///
/// `index` is the method's 1-based position in methods.csv. Numbers are written with the given
/// significant digits (format_number's "%.*g"); the measures with `measure_digits`.
#include <string>
#include <vector>

#include "cagd/compare/comparison_figure.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/points.hpp"

namespace cagd::compare {

/// The table: one row per method, numbers to `digits` significant digits, empty where undefined.
/// With timing = false the seconds column is left out (deterministic output).
/// `dimension` 3: the space columns (no area, no inflections, max_abs_torsion).
std::vector<std::string> comparison_header(bool closed, bool timing, int dimension = 2);
/// The table's rows, numbers to `digits` significant digits, empty where undefined.
std::vector<std::vector<std::string>> comparison_rows(const std::vector<MethodComparison>& c, bool closed, bool timing,
                                                      int digits = 8, int dimension = 2);
/// The table in Markdown.
std::string comparison_markdown(const std::vector<MethodComparison>& c, bool closed, bool timing, int digits = 6,
                                int dimension = 2);

/// The methods table of the figure data (methods.csv): index, method, and for each of curves,
/// curvature and combs the first data row of that method (0-based after the header) and its row
/// count; then comb_stride and comb_scale (0 for a method without a comb), and the status (as
/// the measures table's, spaces written as '-': one word for the plot script). A method's rows are consecutive, so the
/// plot script reads them with gnuplot's `every ::first::last`, which stops there — filtering whole files per panel
/// costs methods² rows.
std::vector<std::string> figure_methods_header();
/// The rows of methods.csv.
std::vector<std::vector<std::string>> figure_methods_rows(const std::vector<MethodComparison>& c, const FigureData& d);

/// One file of a comparison folder: its name, header and rows.
struct ComparisonTable {
    std::string file{};                 ///< "measures.csv", …
    std::vector<std::string> header{};  ///< column names
    /// A table's rows are its text rows (measures, methods) followed by its number rows: its own
    /// (points) or the figure data's (curves, curvature, combs).
    std::vector<std::vector<std::string>> text_rows{};              ///< rows given as text
    std::vector<std::vector<double>> number_rows{};                 ///< rows of numbers of its own
    const std::vector<std::vector<double>>* figure_rows = nullptr;  ///< the figure data, not copied
    int significant = 12;                                           ///< digits of the number rows

    /// The number rows: the figure data it refers to, or its own.
    const std::vector<std::vector<double>>& numbers() const { return figure_rows ? *figure_rows : number_rows; }
};

/// The digits and columns the writer asks for.
struct ComparisonTableOptions {
    bool timing = false;     ///< the seconds column of measures.csv (not deterministic)
    int measure_digits = 8;  ///< measures.csv
    int figure_digits = 12;  ///< curves, curvature, combs
    int point_digits = 17;   ///< points.csv (17: the data round-trip exactly)
};

/// The six tables of a comparison folder, in the order above. `figure` must outlive the result
/// (three tables refer to its rows).
std::vector<ComparisonTable> comparison_tables(const std::vector<MethodComparison>& c, const FigureData& figure,
                                               const PointList& points, bool closed,
                                               const ComparisonTableOptions& options);

}  // namespace cagd::compare
