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

// A CSV of numbers under a header line of names ('#' comments and blank lines skipped), e.g. a
// curve written by `cagd interpolate`. InvalidInput names path:line and the field when a field is
// not a number or a row's field count differs from the header's.
struct NumericTable {
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;
    int column(const std::string& name) const;  // −1 when absent
};
NumericTable read_numeric_table(const std::string& path);

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
