#include "cagd/io/csv_writer.hpp"

#include <exception>
#include <utility>

#include "cagd/core/errors.hpp"

namespace cagd {

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& header)
    : path_(path),
      out_(std::make_unique<OutputFile>(path, "")),
      columns_(header.size()),
      uncaught_at_start_(std::uncaught_exceptions()) {
    row_text(header);
}

CsvWriter::CsvWriter(CsvWriter&& other) noexcept
    : path_(std::move(other.path_)),
      out_(std::move(other.out_)),
      columns_(other.columns_),
      uncaught_at_start_(other.uncaught_at_start_) {}

CsvWriter::~CsvWriter() noexcept(false) {
    // Unwinding: the OutputFile's destructor removes the temporary and keeps the old file.
    if (out_ && std::uncaught_exceptions() == uncaught_at_start_) close();
}

std::ostream& CsvWriter::stream() {
    if (!out_) fail_input("cagd::CsvWriter", path_ + ": written after close()");
    return out_->stream();
}

void CsvWriter::close() {
    if (!out_) return;
    const std::unique_ptr<OutputFile> out = std::move(out_);
    out->commit();
}

void CsvWriter::end_scan() { stream() << '\n'; }

void CsvWriter::row(const std::vector<double>& values, int significant) {
    std::vector<std::string> f;
    for (double v : values) f.push_back(format_number(v, significant));
    row_text(f);
}

void CsvWriter::row_text(const std::vector<std::string>& fields) {
    if (fields.size() != columns_)
        fail_input("cagd::CsvWriter", path_ + ": row has " + std::to_string(fields.size()) + " fields, header has " +
                                          std::to_string(columns_));
    std::ostream& out = stream();
    for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << csv_field(fields[i]);
    out << '\n';
}

}  // namespace cagd
