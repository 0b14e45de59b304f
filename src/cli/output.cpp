#include "cli/output.hpp"

#include <charconv>

#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/io/user_cache.hpp"

namespace cagd::cli {

namespace {

bool quiet_flag = false;

// The lines of the points file read last (read_user_points), for user_message.
std::vector<long> point_lines;

}  // namespace

void print_standard_output(const std::string& text) {
    OutputFile out("-", "");
    out.stream() << text;
    out.commit();
}

std::string finite_field(double value, int significant, const std::string& what) {
    if (!std::isfinite(value))
        throw NoResult("the result is not representable: " + what + " is " + full_precision(value));
    return format_number(value, significant);
}

CsvOutput::CsvOutput(const std::string& path, std::vector<std::string> header, const std::string& option)
    : owned_(std::make_unique<OutputFile>(path, option)), file_(owned_.get()), header_(std::move(header)) {
    write_header();
}

CsvOutput::CsvOutput(OutputFile& file, std::vector<std::string> header) : file_(&file), header_(std::move(header)) {
    write_header();
}

void CsvOutput::write_header() {
    for (std::size_t i = 0; i < header_.size(); ++i) file_->stream() << (i ? "," : "") << csv_field(header_[i]);
    file_->stream() << '\n';
}

void CsvOutput::row(const std::vector<double>& values, int significant) {
    for (std::size_t i = 0; i < values.size(); ++i)  // the label is built only for the error
        if (!std::isfinite(values[i]))
            finite_field(values[i], significant,
                         (i < header_.size() ? header_[i] : "a column") + " of row " + std::to_string(rows_ + 1));
    if (values.size() != header_.size())
        throw std::logic_error("cagd::cli::CsvOutput: a row of " + std::to_string(values.size()) + " fields under " +
                               std::to_string(header_.size()));
    // format_number's text ("%.*g", 0 as "0"), by std::to_chars, which the standard defines as printf's
    // conversion: the same bytes without a string per field (a 10^5-point compare writes 2·10^6 numbers).
    std::ostream& out = file_->stream();
    char buf[64];
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i) out.put(',');
        if (values[i] == 0.0) {
            out.put('0');
            continue;
        }
        const std::to_chars_result r =
            std::to_chars(buf, buf + sizeof buf, values[i], std::chars_format::general, significant);
        out.write(buf, r.ptr - buf);
    }
    out.put('\n');
    ++rows_;
}

void CsvOutput::row_text(const std::vector<std::string>& fields) {
    if (fields.size() != header_.size())
        throw std::logic_error("cagd::cli::CsvOutput: a row of " + std::to_string(fields.size()) + " fields under " +
                               std::to_string(header_.size()));
    for (std::size_t i = 0; i < fields.size(); ++i) file_->stream() << (i ? "," : "") << csv_field(fields[i]);
    file_->stream() << '\n';
    ++rows_;
}

void Quantities::add(const std::string& name, double value, int significant) {
    rows_.emplace_back(name, finite_field(value, significant, name));
}

void Quantities::add_text(const std::string& name, const std::string& value) { rows_.emplace_back(name, value); }

void Quantities::commit() {
    std::string text = "quantity,value\n";
    for (const auto& [name, value] : rows_) text += csv_field(name) + ',' + csv_field(value) + '\n';
    print_standard_output(text);
}

PointList read_user_points(const std::string& path, bool closed) {
    PointList p = read_points_csv(path, point_lines);
    const Eigen::Index n = p.rows();
    if (closed && n >= 3 && p.row(n - 1) == p.row(0)) {
        std::cerr << "cagd: " << (path == "-" ? std::string("stdin") : path) << ":" << point_lines.back()
                  << ": the last point repeats the first; with --closed it is the closing point and is dropped\n";
        p.conservativeResize(n - 1, Eigen::NoChange);
        point_lines.pop_back();
    }
    return p;
}

std::string user_message(const std::string& message) {
    std::string m = in_user_terms(message);
    // "(row i)" of point_label becomes "(line L)" of the points file.
    std::string out;
    std::size_t at = 0;
    for (std::size_t k; (k = m.find("(row ", at)) != std::string::npos;) {
        std::size_t end = k + 5;
        while (end < m.size() && std::isdigit(static_cast<unsigned char>(m[end]))) ++end;
        out += m.substr(at, k - at);
        const std::string digits = m.substr(k + 5, end - k - 5);
        std::size_t row = 0;
        if (end < m.size() && m[end] == ')' && !digits.empty() && digits.size() < 10 &&
            (row = std::stoul(digits)) < point_lines.size()) {
            out += "(line " + std::to_string(point_lines[row]) + ")";
            at = end + 1;
        } else {
            out += "(row ";
            at = k + 5;
        }
    }
    return out + m.substr(at);
}

PointList read_data_points(const std::string& path) {
    PointList p = read_user_points(path, false);
    const double largest = p.cwiseAbs().maxCoeff();
    if (largest > 1e150)
        throw NoResult(path + ": values up to " + full_precision(largest) +
                       " overflow the arithmetic (at most 1e150: squares must stay finite); scale the data down");
    return p;
}

bool progress_enabled() { return !quiet_flag && isatty(fileno(stderr)); }

void set_quiet(bool on) { quiet_flag = on; }

bool quiet() { return quiet_flag; }

namespace {
void note_cache_build(const std::string& path, const std::string& what) {
    if (!quiet_flag)
        std::cerr << "cagd: building " << what << " once, into the user's cache '" << path
                  << "' (--no-cache or CAGD_NO_CACHE=1: build it in memory each time)\n";
}
}  // namespace

void set_up_table_cache(bool no_cache) {
    if (no_cache) set_user_cache_enabled(false);
    set_cache_build_notice(note_cache_build);
    if (progress_enabled())
        set_cache_build_progress([](long done, long total) {
            std::fprintf(stderr, "\rcagd: %ld / %ld table nodes", done, total);
            if (done == total) std::fprintf(stderr, "\n");
        });
}

void require_output_rows(double rows, const std::string& what) {
    if (!(rows <= static_cast<double>(kMaxOutputRows)))
        fail_input("cagd", what + " would write " + format_number(rows, 3) + " rows; at most " +
                               std::to_string(kMaxOutputRows) + " (about 1 GB of CSV)");
}

exports::CurveFormat surface_output_format(const std::string& format, const std::string& path, const std::string& who) {
    const exports::CurveFormat f =
        format.empty() ? exports::curve_format_of_path(path) : exports::curve_format_named(format);
    const exports::CurveFormatInfo& info = exports::curve_format_info(f);
    if (!info.surfaces)
        fail_input(who, path + ": " + info.name +
                            " takes no surfaces; write csv (a grid of samples), json (the exact patches) or step");
    if (f == exports::CurveFormat::step && !exports::step_available())
        fail_input(who, path +
                            ": STEP needs a cagd built with OpenCASCADE (Debian libocct-data-exchange-dev); this one "
                            "was built without it");
    return f;
}

std::vector<std::string> surface_format_names() {
    std::vector<std::string> names;
    for (const exports::CurveFormatInfo& i : exports::curve_formats())
        if (i.surfaces) names.push_back(i.name);
    return names;
}

}  // namespace cagd::cli
