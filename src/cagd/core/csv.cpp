#include "cagd/core/csv.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>

#include "cagd/core/errors.hpp"

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

std::string csv_record(const std::vector<std::string>& fields) {
    std::string out;
    for (std::size_t i = 0; i < fields.size(); ++i) (out += i ? "," : "") += csv_field(fields[i]);
    return out + '\n';
}

std::string csv_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
    std::string out = csv_record(header);
    for (const auto& row : rows) out += csv_record(row);
    return out;
}

std::string format_number(double value, int significant) {
    if (std::isnan(value)) return "nan";
    if (value == 0.0) return "0";
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", significant, value);
    return buf;
}

bool parse_decimal(const std::string& text, double& value) {
    if (text.empty()) return false;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size()) return false;
    // ERANGE: an underflow keeps the subnormal (or 0) strtod returns, an overflow reads as ±inf.
    value = errno == ERANGE && std::abs(v) == HUGE_VAL ? std::copysign(std::numeric_limits<double>::infinity(), v) : v;
    return true;
}

bool read_line(std::istream& in, std::string& line, const std::string& source, int line_no) {
    line.clear();
    std::streambuf* buf = in.rdbuf();
    if (!buf || !in.good()) return false;
    for (;;) {
        const std::streambuf::int_type c = buf->sbumpc();
        if (std::streambuf::traits_type::eq_int_type(c, std::streambuf::traits_type::eof())) {
            in.setstate(std::ios::eofbit);
            return !line.empty();
        }
        const char ch = std::streambuf::traits_type::to_char_type(c);
        if (ch == '\n') return true;
        if (line.size() >= kMaxLineBytes)
            fail_input("cagd::read_line", source + ":" + std::to_string(line_no) + ": the line is longer than " +
                                              std::to_string(kMaxLineBytes) + " bytes (at most 1 MiB a line)");
        line += ch;
    }
}

double parse_number(const std::string& text) {
    const auto fail = [&]() -> double {
        fail_input("cagd::parse_number", "'" + text + "' is not a number or fraction a/b");
    };
    const auto slash = text.find('/');
    double v = 0.0;
    if (slash == std::string::npos) return parse_decimal(text, v) ? v : fail();
    double num = 0.0, den = 0.0;
    if (!parse_decimal(text.substr(0, slash), num) || !parse_decimal(text.substr(slash + 1), den) || den == 0.0)
        return fail();
    return num / den;
}

int NumericTable::column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return static_cast<int>(i);
    return -1;
}

std::string clean_csv_line(std::string line, int line_no) {
    if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 byte-order mark
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    const auto b = line.find_first_not_of(" \t\r"), e = line.find_last_not_of(" \t\r");
    return b == std::string::npos ? std::string() : line.substr(b, e - b + 1);
}

std::vector<std::string> split_fields(const std::string& line) {
    std::vector<std::string> fields{""};
    for (char c : line) {
        if (c == ',')
            fields.emplace_back();
        else
            fields.back() += c;
    }
    for (std::string& f : fields) {
        const auto b = f.find_first_not_of(" \t"), e = f.find_last_not_of(" \t");
        f = b == std::string::npos ? std::string() : f.substr(b, e - b + 1);
    }
    return fields;
}

bool is_column_name(const std::string& field) {
    if (field.empty() || !(std::isalpha(static_cast<unsigned char>(field[0])) || field[0] == '_')) return false;
    for (char c : field)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) return false;
    try {
        parse_number(field);
        return false;  // "nan", "inf", "infinity" read as numbers
    } catch (const InvalidInput&) {
        return true;
    }
}

std::string excerpt(const std::string& text) { return text.size() <= 40 ? text : text.substr(0, 37) + "..."; }

InputFile::InputFile(const std::string& path) : path_(path), name_(path == "-" ? "stdin" : path) {
    if (path == "-") {
        stdin_ = &std::cin;
        return;
    }
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        fail_input("cagd::InputFile", "'" + path + "' is a directory, not a file");
    file_.open(path);
    if (!file_) fail_input("cagd::InputFile", "cannot open '" + path + "'");
}

NumericTable read_numeric_table(const std::string& path) {
    InputFile in(path);
    return read_numeric_table(in.stream(), in.name());
}

NumericTable read_numeric_table(std::istream& stream, const std::string& name) {
    const char* who = "cagd::read_numeric_table";
    NumericTable t;
    std::string line;
    int line_no = 0;
    while (read_line(stream, line, name, line_no + 1)) {
        line = clean_csv_line(std::move(line), ++line_no);
        if (line.empty()) continue;
        const std::vector<std::string> fields = split_fields(line);
        const std::string where = name + ":" + std::to_string(line_no) + ": ";
        if (t.header.empty()) {
            for (const std::string& f : fields)
                if (!is_column_name(f))
                    fail_input(who, where + "needs a header line of column names, got '" + excerpt(line) + "'");
            t.header = fields;
            continue;
        }
        std::vector<double> row;
        for (const std::string& f : fields) {
            double v = 0.0;
            try {
                v = parse_number(f);
            } catch (const InvalidInput&) {
                fail_input(who, where + "'" + excerpt(f) + "' is not a number");
            }
            if (!std::isfinite(v)) fail_input(who, where + "'" + excerpt(f) + "' is not finite");
            row.push_back(v);
        }
        if (row.size() != t.header.size())
            fail_input(
                who, where + std::to_string(row.size()) + " fields, the header has " + std::to_string(t.header.size()));
        t.rows.push_back(std::move(row));
    }
    if (t.header.empty()) fail_input(who, name + ": empty (no header line)");
    return t;
}

}  // namespace cagd

namespace cagd {

const std::string& TextTable::at(std::size_t row, const std::string& name) const {
    for (std::size_t c = 0; c < header.size(); ++c)
        if (header[c] == name) return rows.at(row)[c];
    fail_input("cagd::TextTable::at", source + ": no column \"" + name + "\"");
}

std::string TextTable::where(std::size_t row) const { return source + ":" + std::to_string(lines.at(row)); }

TextTable read_text_table(const std::string& path, const std::vector<std::string>& columns) {
    const char* who = "cagd::read_text_table";
    InputFile file(path);
    TextTable t;
    t.source = file.name();
    std::string raw;
    for (int line_no = 1; read_line(file.stream(), raw, file.name(), line_no); ++line_no) {
        const std::string line = clean_csv_line(raw, line_no);
        if (line.empty()) continue;
        const std::string where = file.name() + ":" + std::to_string(line_no);
        std::vector<std::string> fields = split_csv_line(line);
        for (std::string& f : fields) {
            const auto b = f.find_first_not_of(" \t"), e = f.find_last_not_of(" \t");
            f = b == std::string::npos ? std::string() : f.substr(b, e - b + 1);
        }
        if (t.header.empty()) {
            t.header = fields;
            for (const std::string& name : columns)
                if (std::find(t.header.begin(), t.header.end(), name) == t.header.end()) {
                    std::string all;
                    for (const std::string& c : columns) all += (all.empty() ? "" : ", ") + c;
                    fail_input(who, where + ": the header \"" + excerpt(line) + "\" has no column \"" + name +
                                        "\" (needs " + all + ")");
                }
            continue;
        }
        if (fields.size() != t.header.size())
            fail_input(who, where + ": " + std::to_string(fields.size()) + " fields where the header has " +
                                std::to_string(t.header.size()) + ": \"" + excerpt(line) + "\"");
        t.rows.push_back(std::move(fields));
        t.lines.push_back(line_no);
    }
    if (t.header.empty()) fail_input(who, file.name() + ": no header line");
    return t;
}

}  // namespace cagd
