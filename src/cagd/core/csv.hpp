#pragma once
/// @file
/// Minimal CSV for the library, the harness and the command: RFC-4180-style quoting (fields with commas or quotes are
/// quoted), '#' comment lines kept apart, stable number formatting for byte-stable results.
#include <fstream>
#include <string>
#include <vector>

namespace cagd {

/// The fields of one CSV line, unquoted (RFC 4180: quoted fields may hold commas and doubled quotes).
std::vector<std::string> split_csv_line(const std::string& line);
std::string csv_field(const std::string& text);  ///< quotes when needed
/// One CSV line of `fields` (each csv_field), ended by a newline.
std::string csv_record(const std::vector<std::string>& fields);
/// A CSV table: the header's line, then one line per row (csv_record).
std::string csv_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
/// Stable rendering: "%.10g", with −0 printed as 0. Used for every number in results/.
std::string format_number(double value, int significant = 10);
/// Parses a decimal or an exact fraction "a/b" (reference files print 1/6 as 1/6).
/// Throws InvalidInput naming the text.
double parse_number(const std::string& text);
/// The whole of `text` as a double (strtod's syntax, "nan" and "inf" included): true and `value`
/// set, or false. Every finite double is a number, subnormals (1e-310) included; a magnitude beyond
/// the largest double reads as ±inf (which the readers then refuse as not finite).
bool parse_decimal(const std::string& text, double& value);

/// The longest line a reader accepts (1 MiB): a record of a point or a table row is far shorter,
/// and a stream without line breaks (/dev/zero) is refused instead of growing one line until
/// memory runs out.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;
/// The next line of `in` without its '\n' (std::getline bounded by kMaxLineBytes): false at the
/// end of the stream; InvalidInput naming `source`:`line_no` for a longer line.
bool read_line(std::istream& in, std::string& line, const std::string& source, int line_no);

/// The record rules of every reader (core/point_csv.hpp): a line with its byte-order mark (line 1),
/// CR, '#' comment and surrounding blanks removed; its comma-separated fields, trimmed; whether a
/// field is a name (a header field); an excerpt of a line for messages (at most 40 characters).
std::string clean_csv_line(std::string line, int line_no);
/// The trimmed comma-separated fields of a cleaned line.
std::vector<std::string> split_fields(const std::string& line);
/// Whether a field is a column name: a letter or '_' first, and not a number such as "nan" or "inf".
bool is_column_name(const std::string& field);
/// The line, cut to at most 40 characters with "…", for messages.
std::string excerpt(const std::string& text);
/// `path`, or standard input for "-"; InvalidInput naming the path if it cannot be opened (or is a
/// directory).
class InputFile {
public:
    /// Opens `path` ("-": standard input); InvalidInput naming the path if it cannot be read.
    explicit InputFile(const std::string& path);
    /// The stream to read.
    std::istream& stream() { return path_ == "-" ? *stdin_ : file_; }
    /// The name for messages: the path, or "standard input".
    const std::string& name() const { return name_; }

private:
    std::string path_, name_;
    std::ifstream file_;
    std::istream* stdin_ = nullptr;
};

/// A CSV of numbers under a header line of names, e.g. a curve written by `cagd interpolate`, read
/// by the rules above (the header is required). InvalidInput names path:line and the field when a
/// field is not a number or not finite, or a row's field count differs from the header's.
struct NumericTable {
    std::vector<std::string> header;            ///< the column names of the first line
    std::vector<std::vector<double>> rows;      ///< one vector of numbers per data line, as many as the header's names
    int column(const std::string& name) const;  ///< −1 when absent
};
/// The table in the file `path` ("-": standard input) by the rules above.
NumericTable read_numeric_table(const std::string& path);
/// The table in a stream; `source_name` names the source in messages.
NumericTable read_numeric_table(std::istream& in, const std::string& source_name);

/// A CSV of text records under a header of column names (a manifest: the benchmark's classic data,
/// the peers), read by the rules above: quoted fields may hold commas, each field trimmed.
struct TextTable {
    std::string source;                          ///< the file's name, for messages
    std::vector<std::string> header;             ///< the column names
    std::vector<std::vector<std::string>> rows;  ///< the records, each as long as the header
    std::vector<int> lines;                      ///< each record's line number
    /// Record `row`'s field in column `name` (a column read_text_table was asked for).
    const std::string& at(std::size_t row, const std::string& name) const;
    /// "source:line" of record `row`, for messages.
    std::string where(std::size_t row) const;
};
/// The table of the file `path`; InvalidInput naming path:line when there is no header, it lacks
/// one of `columns`, or a record's field count differs from the header's.
TextTable read_text_table(const std::string& path, const std::vector<std::string>& columns);

}  // namespace cagd
