#pragma once
/// @file
/// A CSV file written whole or not at all: the rows of core/csv.hpp's format (csv_field quoting,
/// format_number's stable rendering) through an OutputFile (io/output_file.hpp).
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "cagd/core/csv.hpp"
#include "cagd/io/output_file.hpp"

namespace cagd {

/// A CSV file written row by row under a header, numbers in the stable rendering of format_number.
/// It is written through an OutputFile (io/output_file.hpp): the rows go to a temporary file
/// beside `path`, published by close() or, when no exception is unwinding, by the destructor. A
/// failed write, flush or rename throws OutputError and keeps the previous file; a writer abandoned
/// by an exception publishes nothing.
class CsvWriter {
public:
    /// Checks `path` (InvalidInput for a directory, a link loop, a missing parent) and writes the header line.
    CsvWriter(const std::string& path, const std::vector<std::string>& header);
    /// Takes over the file being written (run.table() returns a writer by value).
    CsvWriter(CsvWriter&&) noexcept;
    CsvWriter& operator=(CsvWriter&&) = delete;
    /// Publishes the file unless an exception is unwinding (then removes the temporary): may throw OutputError.
    ~CsvWriter() noexcept(false);
    /// A row of numbers, each to `significant` digits; InvalidInput if the count differs from the header's.
    void row(const std::vector<double>& values, int significant = 12);
    /// A row of text fields (quoted where needed); InvalidInput if the count differs from the header's.
    void row_text(const std::vector<std::string>& fields);
    /// An empty line: ends a scan line of a gnuplot surface (splot draws each block as one line).
    void end_scan();
    /// Publishes the file now; OutputError if it could not be written whole. Once only; later rows are refused.
    void close();
    /// The file written.
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::unique_ptr<OutputFile> out_;
    std::size_t columns_;
    int uncaught_at_start_;
    std::ostream& stream();
};

}  // namespace cagd
