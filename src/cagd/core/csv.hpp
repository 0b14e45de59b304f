#pragma once
// Minimal CSV for the library, the harness and the command: RFC-4180-style quoting (fields with commas or quotes are
// quoted), '#' comment lines kept apart, stable number formatting for byte-stable results.
#include <fstream>
#include <string>
#include <vector>

namespace cagd {

std::vector<std::string> split_csv_line(const std::string& line);
std::string csv_field(const std::string& text);  // quotes when needed
// Stable rendering: "%.10g", with −0 printed as 0. Used for every number in results/.
std::string format_number(double value, int significant = 10);
// Parses a decimal or an exact fraction "a/b" (reference files print 1/6 as 1/6).
// Throws InvalidInput naming the text.
double parse_number(const std::string& text);

// The record rules of every reader (core/point_csv.hpp): a line with its byte-order mark (line 1),
// CR, '#' comment and surrounding blanks removed; its comma-separated fields, trimmed; whether a
// field is a name (a header field); an excerpt of a line for messages (at most 40 characters).
std::string clean_csv_line(std::string line, int line_no);
std::vector<std::string> split_fields(const std::string& line);
bool is_column_name(const std::string& field);
std::string excerpt(const std::string& text);
// `path`, or standard input for "-"; InvalidInput naming the path if it cannot be opened (or is a
// directory).
class InputFile {
public:
    explicit InputFile(const std::string& path);
    std::istream& stream() { return path_ == "-" ? *stdin_ : file_; }
    const std::string& name() const { return name_; }

private:
    std::string path_, name_;
    std::ifstream file_;
    std::istream* stdin_ = nullptr;
};

// A CSV of numbers under a header line of names, e.g. a curve written by `cagd interpolate`, read
// by the rules above (the header is required). InvalidInput names path:line and the field when a
// field is not a number or not finite, or a row's field count differs from the header's.
struct NumericTable {
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;
    int column(const std::string& name) const;  // −1 when absent
};
NumericTable read_numeric_table(const std::string& path);
NumericTable read_numeric_table(std::istream& in, const std::string& source_name);

class CsvWriter {
public:
    CsvWriter(const std::string& path, const std::vector<std::string>& header);
    void row(const std::vector<double>& values, int significant = 12);
    void row_text(const std::vector<std::string>& fields);
    // An empty line: ends a scan line of a gnuplot surface (splot draws each block as one line).
    void end_scan() { out_ << '\n'; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::ofstream out_;
    std::size_t columns_;
};

}  // namespace cagd
