#pragma once
// `cagd lac` and `cagd monotone` (typical_curves): registered on the app by main.cpp.
#include <CLI/CLI.hpp>
#include <string>

namespace cagd::cli {

struct LacArgs {
    double alpha = 0.0, length = 1.0, fit_from = 0.05, fit_to = 0.95;
    int degree = 0, samples = 200;
    std::string construction = "scale1", out;
    bool lcg = false;
};
struct MonotoneArgs {
    std::string in, knots = "endpoint";
};

CLI::App* add_lac_command(CLI::App& app, LacArgs& a);
CLI::App* add_monotone_command(CLI::App& app, MonotoneArgs& a);
int run_lac(const LacArgs& a);
int run_monotone(const MonotoneArgs& a);

}  // namespace cagd::cli
