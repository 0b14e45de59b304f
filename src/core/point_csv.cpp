#include "core/point_csv.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/errors.hpp"

namespace cagd {

namespace {
std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

bool parse_double(const std::string& s, double& v) {
    if (s.empty()) return false;
    std::size_t used = 0;
    try {
        v = std::stod(s, &used);
    } catch (const std::exception&) {
        return false;
    }
    return used == s.size();
}
}  // namespace

namespace {
// Rows of min_cols..max_cols finite numbers (an optional header line of names, # comments).
PointList read_number_rows(std::istream& in, const std::string& name, std::size_t min_cols, std::size_t max_cols, const std::string& who, const std::string& what) {
    std::vector<std::vector<double>> rows;
    std::string line;
    int line_no = 0;
    bool header_allowed = true;
    while (std::getline(in, line)) {
        ++line_no;
        const auto hash = line.find('#');
        if (hash != std::string::npos) line = line.substr(0, hash);
        line = trim(line);
        if (line.empty()) continue;
        std::vector<std::string> fields;
        std::stringstream ss(line);
        std::string f;
        while (std::getline(ss, f, ',')) fields.push_back(trim(f));
        if (line.back() == ',') fields.push_back("");
        std::vector<double> values;
        bool numeric = true;
        for (const auto& field : fields) {
            double v = 0;
            numeric = numeric && parse_double(field, v);
            values.push_back(v);
        }
        if (!numeric) {
            if (header_allowed) {
                header_allowed = false;
                continue;
            }  // a header of names
            fail_input(who, name + ":" + std::to_string(line_no) + ": cannot read '" + line + "' as " + what);
        }
        header_allowed = false;
        if (values.size() < min_cols || values.size() > max_cols)
            fail_input(who, name + ":" + std::to_string(line_no) + ": " + std::to_string(values.size()) + " columns in '" + line + "'; expected " + what);
        if (!rows.empty() && values.size() != rows.front().size())
            fail_input(who, name + ":" + std::to_string(line_no) + ": " + std::to_string(values.size()) + " columns, earlier lines have " + std::to_string(rows.front().size()));
        for (double v : values)
            if (!std::isfinite(v)) fail_input(who, name + ":" + std::to_string(line_no) + ": coordinate " + full_precision(v) + " is not finite");
        rows.push_back(values);
    }
    if (rows.empty()) fail_input(who, name + ": no data rows (no points)");
    PointList p(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(rows.front().size()));
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (std::size_t k = 0; k < rows[i].size(); ++k) p(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = rows[i][k];
    return p;
}
}  // namespace

PointList read_points_csv(std::istream& in, const std::string& name) {
    return read_number_rows(in, name, 2, 3, "cagd::read_points_csv", "2 or 3 comma-separated numbers (points need 2 or 3)");
}

std::vector<double> read_values_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) fail_input("cagd::read_values_csv", "cannot open '" + path + "'");
    const PointList v = read_number_rows(in, path, 1, 1, "cagd::read_values_csv", "one number per line");
    return std::vector<double>(v.data(), v.data() + v.rows());
}

PointList read_points_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) fail_input("cagd::read_points_csv", "cannot open '" + path + "'");
    return read_points_csv(in, path);
}

}  // namespace cagd
