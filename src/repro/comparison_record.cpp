#include "repro/comparison_record.hpp"

#include <cmath>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/compare/comparison_figure.hpp"
#include "cagd/compare/comparison_tables.hpp"

namespace cagd::repro {

std::vector<compare::MethodComparison> record_comparison(ArtifactRun& run, const std::string& prefix,
                                                         const PointList& points, bool closed) {
    compare::ComparisonOptions options;
    options.closed = closed;
    const std::vector<compare::MethodComparison> results = compare::compare_methods(points, options);
    const compare::FigureData fig = compare::comparison_figure_data(results, points, compare::FigureSampling{32, 1});
    // The report's digits: measures 8, figure data 10, points 12 (cagd compare writes more).
    const compare::ComparisonTableOptions digits{
        .timing = false, .measure_digits = 8, .figure_digits = 10, .point_digits = 12};
    for (const compare::ComparisonTable& t : compare::comparison_tables(results, fig, points, closed, digits)) {
        CsvWriter w = run.table(prefix + t.file, t.header);
        for (const auto& row : t.text_rows) w.row_text(row);
        for (const auto& row : t.numbers()) w.row(row, t.significant);
    }
    for (const compare::MethodComparison& c : results) {
        if (!c.interpolant) continue;
        const double reference = analysis::adaptive_arc_length(*c.interpolant->curve, 1e-12);
        run.validate(prefix + c.method + ".length",
                     "compare table length of " + c.method + " (Gauss-Legendre) vs adaptive Gauss-Kronrod", c.length,
                     reference, 5e-8 * reference,
                     "two quadratures of one curve; the table prints 8 significant digits, so it must be right to half "
                     "a unit in the 8th (5e-8 relative)");
    }
    return results;
}

}  // namespace cagd::repro
