#include "cagd/compare/comparison_tables.hpp"

namespace cagd::compare {

std::vector<ComparisonTable> comparison_tables(const std::vector<MethodComparison>& c, const FigureData& figure, const PointList& points, bool closed,
                                               const ComparisonTableOptions& options) {
    const int dimension = static_cast<int>(points.cols());
    const bool space = dimension == 3;
    std::vector<ComparisonTable> tables;
    tables.push_back({.file = "measures.csv",
                      .header = comparison_header(closed, options.timing, dimension),
                      .text_rows = comparison_rows(c, closed, options.timing, options.measure_digits, dimension)});
    ComparisonTable data{.file = "points.csv", .header = space ? std::vector<std::string>{"x", "y", "z"} : std::vector<std::string>{"x", "y"}, .significant = options.point_digits};
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const Eigen::RowVectorXd p = points.row(i);
        data.number_rows.emplace_back(p.data(), p.data() + p.size());
    }
    tables.push_back(std::move(data));
    const auto figure_table = [&](std::string file, std::vector<std::string> header, const std::vector<std::vector<double>>& rows) {
        tables.push_back({.file = std::move(file), .header = std::move(header), .figure_rows = &rows, .significant = options.figure_digits});
    };
    figure_table("curves.csv", space ? std::vector<std::string>{"index", "x", "y", "z"} : std::vector<std::string>{"index", "x", "y"}, figure.curves);
    figure_table("curvature.csv", space ? std::vector<std::string>{"index", "s", "kappa", "tau"} : std::vector<std::string>{"index", "s", "kappa"}, figure.profiles);
    figure_table("combs.csv", {"index", "x", "y", "tip_x", "tip_y"}, figure.combs);
    tables.push_back({.file = "methods.csv", .header = figure_methods_header(), .text_rows = figure_methods_rows(c, figure)});
    return tables;
}

}  // namespace cagd::compare
