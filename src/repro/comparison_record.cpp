#include "repro/comparison_record.hpp"

#include <cmath>

#include "cagd/analysis/curve_measures.hpp"

namespace cagd::repro {

std::vector<compare::MethodComparison> record_comparison(ArtifactRun& run, const std::string& prefix, const PointList& points, bool closed) {
    compare::ComparisonOptions options;
    options.closed = closed;
    const std::vector<compare::MethodComparison> results = compare::compare_methods(points, options);
    const int dimension = static_cast<int>(points.cols());
    const bool space = dimension == 3;
    {
        CsvWriter w = run.table(prefix + "measures.csv", compare::comparison_header(closed, false, dimension));
        for (const auto& row : compare::comparison_rows(results, closed, false, 8, dimension)) w.row_text(row);
    }
    {
        CsvWriter w = run.table(prefix + "points.csv", space ? std::vector<std::string>{"x", "y", "z"} : std::vector<std::string>{"x", "y"});
        for (Eigen::Index i = 0; i < points.rows(); ++i) {
            const Eigen::RowVectorXd p = points.row(i);
            w.row(std::vector<double>(p.data(), p.data() + p.size()));
        }
    }
    const compare::FigureData fig = compare::comparison_figure_data(results, points, compare::FigureSampling{32, 1});
    const auto write = [&](const std::string& name, const std::vector<std::string>& header, const std::vector<std::vector<double>>& rows) {
        CsvWriter w = run.table(prefix + name, header);
        for (const auto& r : rows) w.row(r, 10);
    };
    write("curves.csv", space ? std::vector<std::string>{"index", "x", "y", "z"} : std::vector<std::string>{"index", "x", "y"}, fig.curves);
    write("curvature.csv", space ? std::vector<std::string>{"index", "s", "kappa", "tau"} : std::vector<std::string>{"index", "s", "kappa"}, fig.profiles);
    write("combs.csv", {"index", "x", "y", "tip_x", "tip_y"}, fig.combs);
    {
        CsvWriter w = run.table(prefix + "methods.csv", compare::figure_methods_header());
        for (const auto& row : compare::figure_methods_rows(results, fig)) w.row_text(row);
    }
    for (const compare::MethodComparison& c : results) {
        if (!c.interpolant) continue;
        const double reference = analysis::adaptive_arc_length(*c.interpolant->curve, 1e-12);
        run.validate(prefix + c.method + ".length", "compare table length of " + c.method + " (Gauss-Legendre) vs adaptive Gauss-Kronrod", c.length, reference, 5e-8 * reference,
                     "two quadratures of one curve; the table prints 8 significant digits, so it must be right to half a unit in the 8th (5e-8 relative)");
    }
    return results;
}

}  // namespace cagd::repro
