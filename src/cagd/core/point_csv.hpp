#pragma once
/// @file
/// Reading point lists and value lists from CSV (the `cagd` command's input format). The rules,
/// shared by every reader (also read_numeric_table in core/csv.hpp):
///   - one record per line; fields separated by commas, spaces and tabs around a field ignored
///     (a line of whitespace-separated numbers is therefore one unreadable field, an error);
///   - a UTF-8 byte-order mark at the start of line 1 is stripped; CRLF line ends are accepted;
///   - '#' starts a comment (to the end of the line); blank lines are skipped;
///   - the first record is a header only if every field is a name: a letter or '_' first, then
///     letters, digits, '_', '-', '.', and not a number itself (so "nan" or "inf" is not a name);
///     any other record that is not all numbers is an error, the first one included;
///   - every record has the same number of fields; every number is finite.
/// Errors (InvalidInput) name the source, the line number and (the first 40 characters of) the
/// offending text. The path "-" reads standard input (named "stdin" in messages).
#include <istream>
#include <string>
#include <vector>

#include "cagd/core/points.hpp"

namespace cagd {

/// Points from a stream by the rules above; `source_name` names the source in messages.
PointList read_points_csv(std::istream& in, const std::string& source_name);
/// Points from the file `path` ("-": standard input) by the rules above.
PointList read_points_csv(const std::string& path);
/// The same, and in `lines` the line of the file each point (row) was read from, 1-based.
PointList read_points_csv(const std::string& path, std::vector<long>& lines);
/// One finite number per line (optional header, # comments), e.g. per-point smoothing weights.
std::vector<double> read_values_csv(const std::string& path);
/// One number per line from a stream by the same rules; `source_name` names the source in messages.
std::vector<double> read_values_csv(std::istream& in, const std::string& source_name);

}  // namespace cagd
