#pragma once
// Reading point lists from CSV (the `cagd` tool's input format).
// One point per line, 2 or 3 comma-separated numbers; an optional header line of names
// before the first point; '#' comments and blank lines ignored; spaces around fields
// ignored. Every data line must have the same number of columns.
// Errors (InvalidInput) name the source, the line number and the offending text.
#include <istream>
#include <string>
#include <vector>

#include "core/points.hpp"

namespace cagd {

PointList read_points_csv(std::istream& in, const std::string& source_name);
PointList read_points_csv(const std::string& path);
// One finite number per line (optional header, # comments), e.g. per-point smoothing weights.
std::vector<double> read_values_csv(const std::string& path);

}  // namespace cagd
