// `cagd typical-surface --n N --alpha-u A --alpha-v B --angle-deg D [--length L] [--grid G] --out
// GRID.csv [--net-out NET.csv]`: the nonstationary typical surface of typical_curves section 5 (net
// with fixed edges, polygons turned about their diagonals) as a Bezier patch with K and H; or the
// patch itself (--out S.json, or S.step up to OpenCASCADE's degree 25).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>

#include "cagd/aesthetic/typical_surface.hpp"
#include "cagd/analysis/surface_curvature.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/export/surface_form.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

struct TypicalSurfaceArgs {
    int n = 25, grid = 51;
    double alpha_u = 0.0, alpha_v = 0.0, angle_deg = 0.0, length = 1.0;
    std::string out, net_out, format;
};

// The patch of bi-degree n − 1 evaluated on a grid² costs about (n · grid)² operations.
constexpr double kMaxNTimesGrid = 1e5;
// The control net holds 3 n² doubles (24 MB at n = 1000) and is built in O(n²) work.
constexpr int kMaxControlPoints = 1000;
// u-rows evaluated together: the matrix products stay efficient, the jets held are 64 · grid.
constexpr std::size_t kRowsPerBlock = 64;

void write_net(const surface::ControlNet& net, OutputFile& file) {
    {
        CsvOutput nout(file, {"i", "j", "x", "y", "z"});
        for (Eigen::Index i = 0; i < net[0].rows(); ++i)
            for (Eigen::Index j = 0; j < net[0].cols(); ++j)
                nout.row({double(i), double(j), net[0](i, j), net[1](i, j), net[2](i, j)}, 15);
    }
    file.commit();
}

int run_typical_surface(const TypicalSurfaceArgs& a) {
    const char* who = "cagd typical-surface";
    if (!std::isfinite(a.angle_deg)) fail_input(who, "--angle-deg = " + full_precision(a.angle_deg) + " is not finite");
    if (static_cast<double>(a.n) * a.grid > kMaxNTimesGrid)
        fail_input(who, "--n " + std::to_string(a.n) + " x --grid " + std::to_string(a.grid) +
                            " exceeds 1e5 ((n grid)^2 operations: minutes); lower one");
    const exports::CurveFormat format = surface_output_format(a.format, a.out, who);
    if (format != exports::CurveFormat::csv && a.n - 1 > exports::max_surface_degree(format))
        fail_input(who, "--n " + std::to_string(a.n) + ": a patch of degree " + std::to_string(a.n - 1) + "; " +
                            exports::curve_format_info(format).name +
                            " takes degree <= " + std::to_string(exports::max_surface_degree(format)) +
                            " (--n <= " + std::to_string(exports::max_surface_degree(format) + 1) + ")");
    OutputFile file(a.out);
    std::unique_ptr<OutputFile> net_file;
    if (!a.net_out.empty()) net_file = std::make_unique<OutputFile>(a.net_out, "--net-out");
    const surface::ControlNet net = aesthetic::log_aesthetic_typical_net(a.alpha_u, a.alpha_v, a.length, a.n - 1,
                                                                         a.angle_deg * std::numbers::pi / 180.0);
    const surface::BezierPatch patch(net);
    if (format != exports::CurveFormat::csv) {
        const exports::SurfaceProvenance provenance{"typical-surface",
                                                    {{"n", std::to_string(a.n)},
                                                     {"alpha-u", full_precision(a.alpha_u)},
                                                     {"alpha-v", full_precision(a.alpha_v)},
                                                     {"angle-deg", full_precision(a.angle_deg)},
                                                     {"length", full_precision(a.length)}}};
        if (const Outcome written =
                exports::write_surface(file.stream(), format, exports::to_bezier(patch), provenance);
            !written.ok())
            throw NoResult(written.message);
        file.commit();
        if (net_file) write_net(net, *net_file);
        return 0;
    }
    std::vector<double> ts;
    for (int k = 0; k < a.grid; ++k) ts.push_back(static_cast<double>(k) / (a.grid - 1));
    CsvOutput out(file, {"u", "v", "x", "y", "z", "gaussian", "mean"});
    // A block of kRowsPerBlock u-rows at a time: memory grows with grid · n, never with grid².
    for (std::size_t first = 0; first < ts.size(); first += kRowsPerBlock) {
        const std::vector<double> us(
            ts.begin() + static_cast<std::ptrdiff_t>(first),
            ts.begin() + static_cast<std::ptrdiff_t>(std::min(ts.size(), first + kRowsPerBlock)));
        const surface::SurfaceGrid g = patch.evaluate_grid(us, ts);
        for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(us.size()); ++i)
            for (Eigen::Index j = 0; j < a.grid; ++j) {
                const analysis::SurfaceJet2 jet = g.jet(i, j);
                const analysis::SurfaceCurvatures c = analysis::surface_curvatures(jet);
                out.row({us[static_cast<std::size_t>(i)], ts[static_cast<std::size_t>(j)], jet.s(0), jet.s(1), jet.s(2),
                         c.gaussian, c.mean},
                        15);
            }
    }
    out.commit();
    if (net_file) write_net(net, *net_file);
    return 0;
}

}  // namespace

Command add_typical_surface_command(CLI::App& app) {
    auto a = std::make_shared<TypicalSurfaceArgs>();
    auto* c = app.add_subcommand("typical-surface",
                                 "Nonstationary typical surface: net with fixed edges, polygons turned about their "
                                 "diagonals; Bezier patch with K and H (typical_curves section 5)");
    c->add_option("--n", a->n, "control points per direction (the patch has bi-degree n - 1; n x grid <= 1e5)")
        ->required()
        ->check(CLI::Range(3, kMaxControlPoints));
    c->add_option("--alpha-u", a->alpha_u, "alpha of the v = 0 boundary P(i,0) (< 0 or > 1)")->required();
    c->add_option("--alpha-v", a->alpha_v, "alpha of the u = 0 boundary P(0,j) (< 0 or > 1)")->required();
    c->add_option("--angle-deg", a->angle_deg, "rotation of every control polygon about its diagonal, degrees")
        ->required();
    c->add_option("--length", a->length, "length of each boundary polygon (> 0)");
    c->add_option("--grid", a->grid, "parameter grid points per direction (grid^2 rows)")->check(CLI::Range(2, 3000));
    c->add_option("--out", a->out,
                  "by extension: .csv grid u, v, x, y, z, gaussian, mean; .json the patch's net (exact); .step/.stp a "
                  "B-spline surface (n <= 26); - for stdout (csv unless --format)")
        ->required();
    c->add_option("--format", a->format, "output format, whatever the extension")
        ->check(CLI::IsMember(surface_format_names()));
    c->add_option("--net-out", a->net_out, "optional CSV of the control net: i, j, x, y, z; - for stdout");
    return {c, [a] { return run_typical_surface(*a); }};
}

}  // namespace cagd::cli
