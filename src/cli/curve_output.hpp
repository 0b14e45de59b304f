#pragma once
// Curve CSV written by `cagd interpolate`: u, position, 1st and 2nd derivative, `samples_per_span`
// samples between consecutive breakpoints (and the end). Checks the row count against
// kMaxOutputRows before writing and every value for finiteness (cli/output.hpp); the caller
// commits `out`.
#include "cli/output.hpp"
#include "cagd/core/curve.hpp"

namespace cagd::cli {

void write_curve(const Curve& c, int samples_per_span, OutputFile& out);

}  // namespace cagd::cli
