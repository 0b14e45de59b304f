#pragma once
// How the `cagd` command writes: through cagd::OutputFile and cagd::OutputDirectory
// (io/output_file.hpp), which state the contract: `-`, /dev/stdout and open descriptors written
// through, devices and pipes written in place, regular files replaced atomically, every write
// checked (a failure is OutputError: exit 1, the old file kept), bad places found before any work.
// CsvOutput is a CSV result of finite numbers: a non-finite value is a numerical outcome (NoResult,
// exit 1), naming its column and row, and nothing is written. Results on standard output go through
// print_standard_output, so a full or closed standard output is an error too.
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cagd/core/points.hpp"
#include "cagd/export/curve_formats.hpp"
#include "cagd/io/output_file.hpp"

namespace cagd::cli {

// A numerical outcome for valid input (no solution, no convergence, a value that is not
// representable): main.cpp prints "cagd: no result: …" and exits 1.
class NoResult : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

using cagd::OutputFile;

// `text` on standard output, every byte checked (OutputError otherwise).
void print_standard_output(const std::string& text);

// `value` formatted to `significant` digits (core/csv.hpp format_number), or NoResult naming
// `what` when it is not finite.
std::string finite_field(double value, int significant, const std::string& what);

class CsvOutput {
public:
    // Owns its file (checked now, published by commit()).
    CsvOutput(const std::string& path, std::vector<std::string> header, const std::string& option = "--out");
    // Writes into `file`, opened (and so checked) before the work; commit() publishes it.
    CsvOutput(OutputFile& file, std::vector<std::string> header);
    void row(const std::vector<double>& values, int significant = 15);
    void row_text(const std::vector<std::string>& fields);
    void end_scan() { file_->stream() << '\n'; }  // a blank line: ends a gnuplot scan line
    void commit() { file_->commit(); }
    long rows() const { return rows_; }

private:
    void write_header();
    std::unique_ptr<OutputFile> owned_;
    OutputFile* file_;
    std::vector<std::string> header_;
    long rows_ = 0;
};

// "quantity,value" lines for standard output, printed at commit() — after success only.
class Quantities {
public:
    void add(const std::string& name, double value, int significant = 12);
    void add_text(const std::string& name, const std::string& value);
    void commit();

private:
    std::vector<std::pair<std::string, std::string>> rows_;
};

// The points of the file `path` (core/point_csv.hpp rules). With `closed`, a last point equal to
// the first is the closing point: dropped, and one line on stderr says so. The points' lines are
// kept for user_message.
PointList read_user_points(const std::string& path, bool closed);
// A message in the user's terms (in_user_terms), with "(row i)" of a point read by
// read_user_points given as "(line L)" of its file.
std::string user_message(const std::string& message);

// The points of a data file (core/point_csv.hpp rules), with coordinates at most 1e150 in
// magnitude: beyond, the surfaces' and smoothers' arithmetic overflows, so larger data is a
// numerical outcome (NoResult naming the largest value), not bad input.
PointList read_data_points(const std::string& path);

// Progress on standard error for work longer than a second: only when stderr is a terminal and
// `--quiet` was not given (set_quiet).
bool progress_enabled();
void set_quiet(bool on);
bool quiet();  // --quiet was given
// The user's table cache (io/user_cache.hpp) as the command uses it: off with --no-cache; one
// line on stderr when a table is built into it (unless --quiet), and its progress (as above).
void set_up_table_cache(bool no_cache);

// Sizes are checked before anything is allocated: rows of output at most kMaxOutputRows (about a
// gigabyte of CSV; the limits of --samples and --grid in --help follow from it).
constexpr long kMaxOutputRows = 10'000'000;
// A typical Bézier curve costs O(degree) per sample (Bernstein form above degree 60; lac3d adds
// torsion): `cagd lac` and `cagd lac3d` bound degree × samples so that a run stays within seconds.
constexpr double kMaxDegreeTimesSamples = 2e8;
void require_output_rows(double rows, const std::string& what);

/// A surface command's output format, from --format (`format`, may be empty) or the extension of
/// `path`: csv (the grid of samples), json or step; bad input for svg, dxf or an unknown one, and
/// for step without OpenCASCADE, before any work.
exports::CurveFormat surface_output_format(const std::string& format, const std::string& path, const std::string& who);
/// The names --format takes for a surface, for CLI::IsMember.
std::vector<std::string> surface_format_names();

}  // namespace cagd::cli
