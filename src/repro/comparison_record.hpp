#pragma once
// The method comparison of `cagd compare` recorded in an experiment (the report's comparisons on
// the papers' data): writes the comparison folder's tables (compare/comparison_tables.hpp) as
// <prefix>measures.csv (no timing column: deterministic), <prefix>points.csv and the figure data
// <prefix>{curves,curvature,combs,methods}.csv that scripts/plot/compare_panels.gp draws, and
// validates every curve's length (Gauss–Legendre, as the table) against Boost's adaptive
// Gauss–Kronrod to 10⁻¹² relative — an independent quadrature of the same curve.
#include <string>
#include <vector>

#include "cagd/compare/method_comparison.hpp"
#include "repro/artifact_run.hpp"

namespace cagd::repro {

std::vector<compare::MethodComparison> record_comparison(ArtifactRun& run, const std::string& prefix,
                                                         const PointList& points, bool closed);

}  // namespace cagd::repro
