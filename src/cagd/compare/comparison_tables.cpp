#include "cagd/compare/comparison_tables.hpp"

#include <algorithm>
#include <sstream>
#include <string>

#include "cagd/core/csv.hpp"

namespace cagd::compare {

std::vector<ComparisonTable> comparison_tables(const std::vector<MethodComparison>& c, const FigureData& figure,
                                               const PointList& points, bool closed,
                                               const ComparisonTableOptions& options) {
    const int dimension = static_cast<int>(points.cols());
    const bool space = dimension == 3;
    std::vector<ComparisonTable> tables;
    tables.push_back({.file = "measures.csv",
                      .header = comparison_header(closed, options.timing, dimension),
                      .text_rows = comparison_rows(c, closed, options.timing, options.measure_digits, dimension)});
    ComparisonTable data{.file = "points.csv",
                         .header = space ? std::vector<std::string>{"x", "y", "z"} : std::vector<std::string>{"x", "y"},
                         .significant = options.point_digits};
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const Eigen::RowVectorXd p = points.row(i);
        data.number_rows.emplace_back(p.data(), p.data() + p.size());
    }
    tables.push_back(std::move(data));
    const auto figure_table = [&](std::string file, std::vector<std::string> header,
                                  const std::vector<std::vector<double>>& rows) {
        tables.push_back({.file = std::move(file),
                          .header = std::move(header),
                          .figure_rows = &rows,
                          .significant = options.figure_digits});
    };
    figure_table("curves.csv",
                 space ? std::vector<std::string>{"index", "x", "y", "z"} : std::vector<std::string>{"index", "x", "y"},
                 figure.curves);
    figure_table("curvature.csv",
                 space ? std::vector<std::string>{"index", "s", "kappa", "tau"}
                       : std::vector<std::string>{"index", "s", "kappa"},
                 figure.profiles);
    figure_table("combs.csv", {"index", "x", "y", "tip_x", "tip_y"}, figure.combs);
    tables.push_back(
        {.file = "methods.csv", .header = figure_methods_header(), .text_rows = figure_methods_rows(c, figure)});
    return tables;
}

std::vector<std::string> comparison_header(bool closed, bool timing, int dimension) {
    std::vector<std::string> h{"method", "status", "spans", "length"};
    if (closed && dimension == 2) h.push_back("area");
    if (dimension == 2)
        for (const char* n : {"bending_energy", "pseudo_energy", "inflections", "max_abs_curvature",
                              "max_abs_dcurvature_ds", "overshoot", "locality_footprint"})
            h.push_back(n);
    else
        for (const char* n : {"bending_energy", "pseudo_energy", "max_abs_curvature", "max_abs_dcurvature_ds",
                              "max_abs_torsion", "overshoot", "locality_footprint"})
            h.push_back(n);
    if (timing) h.push_back("seconds"), h.push_back("shared_seconds");
    h.push_back("note");
    return h;
}

std::vector<std::vector<std::string>> comparison_rows(const std::vector<MethodComparison>& cs, bool closed, bool timing,
                                                      int digits, int dimension) {
    std::vector<std::vector<std::string>> rows;
    const auto num = [&](double v) { return format_number(v, digits); };
    for (const MethodComparison& c : cs) {
        const bool built = c.interpolant.has_value();
        std::vector<std::string> r{c.method, to_string(c.status), built ? std::to_string(c.spans) : "",
                                   built ? num(c.length) : ""};
        if (closed && dimension == 2) r.push_back(built ? num(c.area) : "");
        if (c.fairness && dimension == 2) {
            const analysis::FairnessMeasures& f = *c.fairness;
            for (const std::string& v :
                 {num(f.bending_energy), num(c.pseudo_energy), std::to_string(f.curvature_sign_changes),
                  num(f.max_abs_curvature), num(f.max_abs_curvature_derivative), num(f.overshoot)})
                r.push_back(v);
        } else if (c.fairness) {
            const analysis::FairnessMeasures& f = *c.fairness;
            for (const std::string& v : {num(f.bending_energy), num(c.pseudo_energy), num(f.max_abs_curvature),
                                         num(f.max_abs_curvature_derivative), num(f.max_abs_torsion), num(f.overshoot)})
                r.push_back(v);
        } else {
            r.insert(r.end(), 6, "");
        }
        r.push_back(c.locality_footprint ? std::to_string(*c.locality_footprint) : "");
        if (timing)
            r.push_back(built ? format_number(c.seconds, 3) : ""),
                r.push_back(c.status == AttemptStatus::not_applicable || c.peer ? ""
                                                                                : format_number(c.shared_seconds, 3));
        r.push_back(c.note);
        rows.push_back(std::move(r));
    }
    return rows;
}

std::string comparison_markdown(const std::vector<MethodComparison>& cs, bool closed, bool timing, int digits,
                                int dimension) {
    const std::vector<std::string> header = comparison_header(closed, timing, dimension);
    std::ostringstream md;
    md << "|";
    for (const std::string& h : header) md << " " << h << " |";
    md << "\n|";
    for (std::size_t i = 0; i < header.size(); ++i)
        md << (i == 0 || i + 1 == header.size() || i == 1 ? "---|" : "---:|");
    md << "\n";
    for (const auto& row : comparison_rows(cs, closed, timing, digits, dimension)) {
        md << "|";
        for (std::string f : row) {
            std::replace(f.begin(), f.end(), '|', '/');
            md << " " << f << " |";
        }
        md << "\n";
    }
    return md.str();
}

std::vector<std::string> figure_methods_header() {
    return {"index",       "method",      "curves_first", "curves_count", "curvature_first", "curvature_count",
            "combs_first", "combs_count", "comb_stride",  "comb_scale",   "status"};
}

std::vector<std::vector<std::string>> figure_methods_rows(const std::vector<MethodComparison>& cs,
                                                          const FigureData& d) {
    std::vector<std::vector<std::string>> out;
    for (std::size_t i = 0; i < cs.size(); ++i) out.push_back({std::to_string(i), cs[i].method});
    for (const std::vector<std::vector<double>>* rows : {&d.curves, &d.profiles, &d.combs}) {
        std::vector<std::size_t> first(cs.size(), 0), count(cs.size(), 0);
        for (std::size_t r = 0; r < rows->size(); ++r) {
            const auto m = static_cast<std::size_t>((*rows)[r][0]);
            if (count[m] == 0)
                first[m] = r;
            else if (first[m] + count[m] != r)
                throw std::logic_error("cagd::compare::figure_methods_rows: rows of method " + std::to_string(m) +
                                       " are not consecutive");
            ++count[m];
        }
        for (std::size_t i = 0; i < cs.size(); ++i) {
            out[i].push_back(std::to_string(first[i]));
            out[i].push_back(std::to_string(count[i]));
        }
    }
    for (std::size_t i = 0; i < cs.size(); ++i) {
        const bool comb = i < d.comb_stride.size() && d.comb_stride[i] > 0;
        out[i].push_back(comb ? std::to_string(d.comb_stride[i])
                              : "0");  // 0 (not empty): the plot script reads the column as words
        out[i].push_back(comb ? format_number(d.comb_scale[i], 6) : "0");
        std::string status =
            to_string(cs[i].status);  // one word for the plot script: "not applicable" → "not-applicable"
        std::replace(status.begin(), status.end(), ' ', '-');
        out[i].push_back(status);
    }
    return out;
}

}  // namespace cagd::compare
