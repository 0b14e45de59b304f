#pragma once
// `cagd lac`, `cagd monotone`, `cagd lac3d` and `cagd typical-surface` (typical_curves): registered on
// the app by main.cpp.
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

struct Lac3dArgs {
    double alpha = 0.0, beta = 0.0, length = 1.0, start = 0.1;
    int degree = 0, samples = 200;
    std::string composition = "alexa", out;
    bool slopes = false;
};
struct TypicalSurfaceArgs {
    int n = 25, grid = 51;
    double alpha_u = 0.0, alpha_v = 0.0, angle_deg = 0.0, length = 1.0;
    std::string out, net_out;
};

CLI::App* add_lac_command(CLI::App& app, LacArgs& a);
CLI::App* add_lac3d_command(CLI::App& app, Lac3dArgs& a);
CLI::App* add_typical_surface_command(CLI::App& app, TypicalSurfaceArgs& a);
int run_lac3d(const Lac3dArgs& a);
int run_typical_surface(const TypicalSurfaceArgs& a);
CLI::App* add_monotone_command(CLI::App& app, MonotoneArgs& a);
int run_lac(const LacArgs& a);
int run_monotone(const MonotoneArgs& a);

}  // namespace cagd::cli
