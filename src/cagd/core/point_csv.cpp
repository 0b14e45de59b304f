#include "cagd/core/point_csv.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"

namespace cagd {

namespace {

// Records of min_cols..max_cols finite numbers by the rules of point_csv.hpp.
// `lines`, when given, receives the line number of each row.
PointList read_number_rows(std::istream& in, const std::string& name, std::size_t min_cols, std::size_t max_cols,
                           const std::string& who, const std::string& what, std::vector<long>* lines = nullptr) {
    std::vector<std::vector<double>> rows;
    std::string line;
    int line_no = 0;
    bool first_record = true;
    while (read_line(in, line, name, line_no + 1)) {
        line = clean_csv_line(std::move(line), ++line_no);
        if (line.empty()) continue;
        const std::vector<std::string> fields = split_fields(line);
        const std::string where = name + ":" + std::to_string(line_no) + ": ";
        std::vector<double> values;
        bool numeric = true, names = true;
        for (const auto& field : fields) {
            double v = 0;
            numeric = numeric && parse_decimal(field, v);
            names = names && is_column_name(field);
            values.push_back(v);
        }
        const bool header = first_record && names;
        first_record = false;
        if (header) continue;
        if (!numeric) {
            for (const auto& field : fields) {
                double v = 0;
                if (!parse_decimal(field, v))
                    fail_input(who, where + "'" + excerpt(field) + "' in '" + excerpt(line) + "' is not a number (" +
                                        what + (line_no == 1 || rows.empty() ? "; a header line has names only" : "") +
                                        ")");
            }
        }
        if (values.size() < min_cols || values.size() > max_cols)
            fail_input(who,
                       where + std::to_string(values.size()) + " columns in '" + excerpt(line) + "'; expected " + what);
        if (!rows.empty() && values.size() != rows.front().size())
            fail_input(who, where + std::to_string(values.size()) + " columns, earlier lines have " +
                                std::to_string(rows.front().size()));
        for (double v : values)
            if (!std::isfinite(v)) fail_input(who, where + "coordinate " + full_precision(v) + " is not finite");
        rows.push_back(values);
        if (lines) lines->push_back(line_no);
    }
    if (rows.empty()) fail_input(who, name + ": no data rows (no points)");
    PointList p(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(rows.front().size()));
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (std::size_t k = 0; k < rows[i].size(); ++k)
            p(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = rows[i][k];
    return p;
}

}  // namespace

PointList read_points_csv(std::istream& in, const std::string& name) {
    return read_number_rows(in, name, 2, 3, "cagd::read_points_csv",
                            "2 or 3 comma-separated numbers (points need 2 or 3)");
}

std::vector<double> read_values_csv(std::istream& in, const std::string& name) {
    const PointList v = read_number_rows(in, name, 1, 1, "cagd::read_values_csv", "one number per line");
    return std::vector<double>(v.data(), v.data() + v.rows());
}

std::vector<double> read_values_csv(const std::string& path) {
    InputFile in(path);
    return read_values_csv(in.stream(), in.name());
}

PointList read_points_csv(const std::string& path) {
    InputFile in(path);
    return read_points_csv(in.stream(), in.name());
}

PointList read_points_csv(const std::string& path, std::vector<long>& lines) {
    InputFile in(path);
    lines.clear();
    return read_number_rows(in.stream(), in.name(), 2, 3, "cagd::read_points_csv",
                            "2 or 3 comma-separated numbers (points need 2 or 3)", &lines);
}

}  // namespace cagd
