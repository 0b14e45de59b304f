#include "cli/compare_command.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/compare_panels_script.hpp"
#include "compare/method_comparison.hpp"
#include "core/errors.hpp"
#include "core/point_csv.hpp"
#include "repro/csv.hpp"

namespace cagd::cli {

namespace {

void write_rows(const std::string& path, const std::vector<std::string>& header, const std::vector<std::vector<double>>& rows) {
    repro::CsvWriter w(path, header);
    for (const auto& r : rows) w.row(r, 12);
}

// A gnuplot string literal in single quotes ('' is a quote inside).
std::string gnuplot_quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
    return q + "'";
}

// A shell word in single quotes.
std::string shell_quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

int run_compare(const CompareArgs& a) {
    const char* who = "cagd compare";
    const PointList points = read_points_csv(a.in);
    compare::ComparisonOptions options;
    options.closed = a.closed;
    if (!a.methods.empty()) {
        std::stringstream ss(a.methods);
        std::string m;
        while (std::getline(ss, m, ',')) options.methods.push_back(compare::method_info(m).name);
    }
    if (points.cols() != 2) fail_input(who, a.in + ": compares planar curves, the points have " + std::to_string(points.cols()) + " columns");
    std::error_code ec;
    std::filesystem::create_directories(a.out, ec);
    if (!std::filesystem::is_directory(a.out)) fail_input(who, "cannot create the output directory '" + a.out + "'");
    std::cerr << "cagd compare: " << points.rows() << " points, " << (options.methods.empty() ? compare::interpolation_methods().size() : options.methods.size())
              << " methods\n";
    const std::vector<compare::MethodComparison> results = compare::compare_methods(points, options);
    for (const auto& r : results)
        std::cerr << "cagd compare: " << r.method << ": " << r.status << (r.note.empty() ? "" : " (" + r.note + ")") << ", "
                  << repro::format_number(r.seconds, 3) << " s\n";

    const std::string dir = a.out + "/";
    {
        repro::CsvWriter w(dir + "measures.csv", compare::comparison_header(a.closed, true));
        for (const auto& row : compare::comparison_rows(results, a.closed, true)) w.row_text(row);
    }
    const std::string md = compare::comparison_markdown(results, a.closed, true);
    std::ofstream(dir + "measures.md") << md;
    std::cout << md;

    // Figure data: at most about 10^4 samples per method whatever the input length (drawing time
    // grows with the samples: 10^5 points at 4·10^4 samples per method take gnuplot 35 s).
    const int spans = static_cast<int>(points.rows()) - (a.closed ? 0 : 1);
    const compare::FigureData fig = compare::comparison_figure_data(results, points, compare::figure_sampling(std::max(spans, 1), 10000));
    {
        repro::CsvWriter w(dir + "points.csv", {"x", "y"});
        for (Eigen::Index i = 0; i < points.rows(); ++i) w.row({points(i, 0), points(i, 1)}, 17);
    }
    write_rows(dir + "curves.csv", {"index", "x", "y"}, fig.curves);
    write_rows(dir + "curvature.csv", {"index", "s", "kappa"}, fig.profiles);
    write_rows(dir + "combs.csv", {"index", "x", "y", "tip_x", "tip_y"}, fig.combs);
    {
        repro::CsvWriter w(dir + "methods.csv", compare::figure_methods_header());
        for (const auto& row : compare::figure_methods_rows(results, fig)) w.row_text(row);
    }
    std::ofstream(dir + "compare_panels.gp") << kComparePanelsScript;
    if (!a.plot) return 0;
    const std::string settings = "datadir=" + gnuplot_quoted(a.out) + "; prefix=''; heading=" +
                                 gnuplot_quoted(std::filesystem::path(a.in).filename().string()) + "; formats='png'; point_every=" +
                                 std::to_string(std::max<Eigen::Index>(1, points.rows() / 5000));   // ≤ ~5000 dots per panel
    const std::string command = "gnuplot -e " + shell_quoted(settings) + " " + shell_quoted(dir + "compare_panels.gp");
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
        std::cerr << "cagd compare: gnuplot not found; the figure data and compare_panels.gp are in " << a.out << "\n";
        return 0;
    }
    if (std::system(command.c_str()) != 0) {
        std::cerr << "cagd compare: gnuplot failed: " << command << "\n";
        return 1;
    }
    std::cerr << "cagd compare: figures " << dir << "{curves,combs,curvature}.png\n";
    return 0;
}

}  // namespace cagd::cli
