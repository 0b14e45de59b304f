#include "cli/output.hpp"

#include <charconv>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <system_error>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"

namespace cagd::cli {

namespace {

bool quiet_flag = false;

// A fresh temporary file name in `dir` (created empty, so two runs never share one).
std::filesystem::path make_temp(const std::filesystem::path& dir, const std::string& stem, const std::string& path, const std::string& option) {
    std::string pattern = (dir / ("." + stem + ".cagd-XXXXXX")).string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) fail_input("cagd", option + " '" + path + "': cannot write in '" + dir.string() + "': " + std::error_code(errno, std::generic_category()).message());
    close(fd);
    return pattern;
}

}  // namespace

OutputFile::OutputFile(const std::string& path, const std::string& option) : path_(path), option_(option) {
    namespace fs = std::filesystem;
    if (path.empty()) fail_input("cagd", option + " is empty; give a file path or - for standard output");
    std::error_code ec;
    if (path == "-") {
        target_ = Target::standard_output;
        const char* tmp = std::getenv("TMPDIR");
        temp_path_ = make_temp(tmp && *tmp ? tmp : "/tmp", "stdout", path, option);
    } else {
        fs::path p = path;
        const fs::file_status status = fs::status(p, ec);  // follows symbolic links
        if (fs::is_directory(status)) fail_input("cagd", option + " '" + path + "' is a directory; give a file path");
        if (fs::exists(status) && !fs::is_regular_file(status)) {
            target_ = Target::special;  // a device or a pipe (also /dev/stdout on a pipe): written in place at commit()
            const char* tmp = std::getenv("TMPDIR");
            temp_path_ = make_temp(tmp && *tmp ? tmp : "/tmp", "special", path, option);
        } else {
            // A symbolic link (even a dangling one) keeps pointing where it did: its target is replaced.
            for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(p, ec)); ++hops) {
                const fs::path target = fs::read_symlink(p, ec);
                if (ec) break;
                p = (target.is_absolute() ? target : p.parent_path() / target).lexically_normal();
            }
            const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
            if (!fs::is_directory(dir, ec)) fail_input("cagd", option + " '" + path + "': the directory '" + dir.string() + "' does not exist");
            temp_path_ = make_temp(dir, p.filename().string(), path, option);
        }
        final_ = target_ == Target::special ? fs::path(path) : p;
        // mkstemp creates 0600: give the file the mode the replaced one had, or a new file's (0666 less the umask).
        const fs::file_status old_status = fs::status(final_, ec);
        fs::perms mode = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::group_write | fs::perms::others_read | fs::perms::others_write;
        if (target_ == Target::regular && fs::is_regular_file(old_status)) {
            mode = old_status.permissions();
        } else {
            const mode_t mask = umask(0);
            umask(mask);
            mode &= ~static_cast<fs::perms>(mask);
        }
        if (target_ == Target::regular) fs::permissions(temp_path_, mode, ec);
    }
    temp_.open(temp_path_, std::ios::binary | std::ios::trunc);
    if (!temp_) fail_input("cagd", option + " '" + path + "': cannot write the temporary file '" + temp_path_.string() + "'");
}

OutputFile::~OutputFile() {
    if (committed_) return;
    temp_.close();
    std::error_code ec;
    std::filesystem::remove(temp_path_, ec);
}

void OutputFile::commit() {
    temp_.close();
    if (!temp_) throw NoResult(option_ + " '" + path_ + "': writing failed (disk full?)");
    std::error_code ec;
    if (target_ == Target::regular) {
        std::filesystem::rename(temp_path_, final_, ec);
        if (ec) throw NoResult(option_ + " '" + path_ + "': cannot replace it: " + ec.message());
        committed_ = true;
        return;
    }
    std::ifstream in(temp_path_, std::ios::binary);
    if (target_ == Target::standard_output) {
        std::cout << in.rdbuf();
        std::cout.flush();
    } else {
        std::ofstream out(final_, std::ios::binary);  // opened for writing only: no truncation of a device matters
        if (!out) throw NoResult(option_ + " '" + path_ + "': cannot open it for writing");
        out << in.rdbuf();
    }
    in.close();
    std::filesystem::remove(temp_path_, ec);
    committed_ = true;
}

std::string finite_field(double value, int significant, const std::string& what) {
    if (!std::isfinite(value)) throw NoResult("the result is not representable: " + what + " is " + full_precision(value));
    return format_number(value, significant);
}

CsvOutput::CsvOutput(const std::string& path, std::vector<std::string> header, const std::string& option)
    : owned_(std::make_unique<OutputFile>(path, option)), file_(owned_.get()), header_(std::move(header)) {
    write_header();
}

CsvOutput::CsvOutput(OutputFile& file, std::vector<std::string> header) : file_(&file), header_(std::move(header)) { write_header(); }

void CsvOutput::write_header() {
    for (std::size_t i = 0; i < header_.size(); ++i) file_->stream() << (i ? "," : "") << csv_field(header_[i]);
    file_->stream() << '\n';
}

void CsvOutput::row(const std::vector<double>& values, int significant) {
    for (std::size_t i = 0; i < values.size(); ++i)  // the label is built only for the error
        if (!std::isfinite(values[i])) finite_field(values[i], significant, (i < header_.size() ? header_[i] : "a column") + " of row " + std::to_string(rows_ + 1));
    if (values.size() != header_.size())
        throw std::logic_error("cagd::cli::CsvOutput: a row of " + std::to_string(values.size()) + " fields under " + std::to_string(header_.size()));
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
        const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, values[i], std::chars_format::general, significant);
        out.write(buf, r.ptr - buf);
    }
    out.put('\n');
    ++rows_;
}

void CsvOutput::row_text(const std::vector<std::string>& fields) {
    if (fields.size() != header_.size())
        throw std::logic_error("cagd::cli::CsvOutput: a row of " + std::to_string(fields.size()) + " fields under " + std::to_string(header_.size()));
    for (std::size_t i = 0; i < fields.size(); ++i) file_->stream() << (i ? "," : "") << csv_field(fields[i]);
    file_->stream() << '\n';
    ++rows_;
}

void Quantities::add(const std::string& name, double value, int significant) { rows_.emplace_back(name, finite_field(value, significant, name)); }

void Quantities::add_text(const std::string& name, const std::string& value) { rows_.emplace_back(name, value); }

void Quantities::commit() {
    std::cout << "quantity,value\n";
    for (const auto& [name, value] : rows_) std::cout << csv_field(name) << ',' << csv_field(value) << '\n';
    std::cout.flush();
}

PointList read_data_points(const std::string& path) {
    PointList p = read_points_csv(path);
    const double largest = p.cwiseAbs().maxCoeff();
    if (largest > 1e150)
        throw NoResult(path + ": values up to " + full_precision(largest) + " overflow the arithmetic (at most 1e150: squares must stay finite); scale the data down");
    return p;
}

bool progress_enabled() { return !quiet_flag && isatty(fileno(stderr)); }

void set_quiet(bool quiet) { quiet_flag = quiet; }

void require_output_rows(double rows, const std::string& what) {
    if (!(rows <= static_cast<double>(kMaxOutputRows)))
        fail_input("cagd", what + " would write " + format_number(rows, 3) + " rows; at most " + std::to_string(kMaxOutputRows) + " (about 1 GB of CSV)");
}

}  // namespace cagd::cli
