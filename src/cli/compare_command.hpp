#pragma once
// `cagd compare --in P.csv [--closed] [--methods a,b,…] [--no-plot] --out DIR`: every interpolation
// method on the user's points (compare/method_comparison). Writes DIR/measures.csv and
// DIR/measures.md (one row per method), the figure data DIR/{points,curves,curvature,combs}.csv,
// DIR/compare_panels.gp, and with gnuplot on the PATH the figures DIR/{curves,combs,curvature}.png.
// Prints the Markdown table on stdout and one progress line per method on stderr.
#include <string>

namespace cagd::cli {

struct CompareArgs {
    std::string in, out, methods;
    bool closed = false, plot = true;
};

int run_compare(const CompareArgs& args);

}  // namespace cagd::cli
