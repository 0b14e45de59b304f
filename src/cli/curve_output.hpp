#pragma once
// Curve CSV written by `cagd interpolate`: u, position, 1st and 2nd derivative, `samples_per_span`
// samples between consecutive breakpoints (and the end).
#include <string>

#include "core/curve.hpp"

namespace cagd::cli {

void write_curve(const Curve& c, int samples_per_span, const std::string& path);

}  // namespace cagd::cli
