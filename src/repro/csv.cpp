#include "repro/csv.hpp"

#include <cmath>
#include <cstdio>

#include "core/errors.hpp"

namespace cagd::repro {

std::vector<std::string> split_csv_line(const std::string& line) {
    std::vector<std::string> out;
    std::string cur;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') { cur += '"'; ++i; }
            else if (c == '"') quoted = false;
            else cur += c;
        } else if (c == '"') quoted = true;
        else if (c == ',') { out.push_back(cur); cur.clear(); }
        else if (c != '\r') cur += c;
    }
    out.push_back(cur);
    return out;
}

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string q = "\"";
    for (char c : text) { if (c == '"') q += '"'; q += c; }
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
    const auto fail = [&]() -> double {
        fail_input("cagd::repro::parse_number", "'" + text + "' is not a number or fraction a/b");
    };
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

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& header)
    : path_(path), out_(path), columns_(header.size()) {
    if (!out_) fail_input("cagd::repro::CsvWriter", "cannot open '" + path + "' for writing");
    row_text(header);
}

void CsvWriter::row(const std::vector<double>& values, int significant) {
    std::vector<std::string> f;
    for (double v : values) f.push_back(format_number(v, significant));
    row_text(f);
}

void CsvWriter::row_text(const std::vector<std::string>& fields) {
    if (fields.size() != columns_)
        fail_input("cagd::repro::CsvWriter", path_ + ": row has " + std::to_string(fields.size()) +
                                                 " fields, header has " + std::to_string(columns_));
    for (std::size_t i = 0; i < fields.size(); ++i) out_ << (i ? "," : "") << csv_field(fields[i]);
    out_ << '\n';
}

}  // namespace cagd::repro
