#pragma once
// Curve CSV written by `cagd interpolate`: the parameter (column `parameter_column`: t, the
// method's own, or u, the span index), position, 1st and 2nd derivative with respect to that
// parameter, `samples_per_span` samples between consecutive breakpoints (and the end). Checks the row count against
// kMaxOutputRows before writing and every value for finiteness (cli/output.hpp); the caller
// commits `out`.
#include <string>

#include "cli/output.hpp"
#include "cagd/core/curve.hpp"

namespace cagd::cli {

void write_curve(const Curve& c, int samples_per_span, OutputFile& out, const std::string& parameter_column);

}  // namespace cagd::cli
