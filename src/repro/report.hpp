#pragma once
// Generates results/claims.csv and results/REPORT.md from the per-artifact files that the
// experiments wrote (results/<paper>/<artifact>.checks.csv and .meta). Deterministic: papers in
// the order of docs/papers.md, artifacts by section, rows in the order the experiments recorded them.
#include <string>

namespace cagd::repro {

// Returns the number of failed claims and validations found (the report is written anyway).
int write_report(const std::string& root);

}  // namespace cagd::repro
