#include "core/csv.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/errors.hpp"

namespace cagd {

std::vector<std::string> split_csv_line(const std::string& line) {
    std::vector<std::string> out;
    std::string cur;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                cur += '"';
                ++i;
            } else if (c == '"')
                quoted = false;
            else
                cur += c;
        } else if (c == '"')
            quoted = true;
        else if (c == ',') {
            out.push_back(cur);
            cur.clear();
        } else if (c != '\r')
            cur += c;
    }
    out.push_back(cur);
    return out;
}

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string q = "\"";
    for (char c : text) {
        if (c == '"') q += '"';
        q += c;
    }
    return q + "\"";
}

std::string format_number(double value, int significant) {
    if (std::isnan(value)) return "nan";
    if (value == 0.0) return "0";
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", significant, value);
    return buf;
}

double parse_number(const std::string& text) {
    const auto fail = [&]() -> double { fail_input("cagd::parse_number", "'" + text + "' is not a number or fraction a/b"); };
    if (text.empty()) return fail();
    const auto slash = text.find('/');
    try {
        std::size_t used = 0;
        if (slash == std::string::npos) {
            const double v = std::stod(text, &used);
            return used == text.size() ? v : fail();
        }
        const std::string a = text.substr(0, slash), b = text.substr(slash + 1);
        std::size_t ua = 0, ub = 0;
        const double num = std::stod(a, &ua), den = std::stod(b, &ub);
        if (ua != a.size() || ub != b.size() || den == 0.0) return fail();
        return num / den;
    } catch (const std::invalid_argument&) {
        return fail();
    } catch (const std::out_of_range&) {
        return fail();
    }
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& header) : path_(path), out_(path), columns_(header.size()) {
    if (!out_) fail_input("cagd::CsvWriter", "cannot open '" + path + "' for writing");
    row_text(header);
}

void CsvWriter::row(const std::vector<double>& values, int significant) {
    std::vector<std::string> f;
    for (double v : values) f.push_back(format_number(v, significant));
    row_text(f);
}

void CsvWriter::row_text(const std::vector<std::string>& fields) {
    if (fields.size() != columns_) fail_input("cagd::CsvWriter", path_ + ": row has " + std::to_string(fields.size()) + " fields, header has " + std::to_string(columns_));
    for (std::size_t i = 0; i < fields.size(); ++i) out_ << (i ? "," : "") << csv_field(fields[i]);
    out_ << '\n';
}

int NumericTable::column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return static_cast<int>(i);
    return -1;
}

NumericTable read_numeric_table(const std::string& path) {
    const char* who = "cagd::read_numeric_table";
    std::ifstream in(path);
    if (!in) fail_input(who, "cannot open '" + path + "'");
    NumericTable t;
    std::string line;
    int line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 byte-order mark
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> fields = split_csv_line(line);
        if (t.header.empty()) {
            t.header = fields;
            continue;
        }
        std::vector<double> row;
        for (const std::string& f : fields) {
            try {
                row.push_back(parse_number(f));
            } catch (const InvalidInput&) {
                fail_input(who, path + ":" + std::to_string(line_no) + ": '" + f + "' is not a number");
            }
        }
        if (row.size() != t.header.size())
            fail_input(who, path + ":" + std::to_string(line_no) + ": " + std::to_string(row.size()) + " fields, header has " + std::to_string(t.header.size()));
        t.rows.push_back(std::move(row));
    }
    return t;
}

}  // namespace cagd
