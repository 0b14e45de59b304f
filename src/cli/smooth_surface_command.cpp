// `cagd smooth-surface --method net|plate|plate-boundary|approx1|approx2 --lambda L … --in XYZ.csv
// --out GRID.csv`: the elastic net, the plates and the two approximations of hosaka sections 6–7 on
// a grid of heights.
#include <functional>
#include <memory>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/smoothing/surface_smoothing.hpp"
#include "cagd/surface/hosaka_patch.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

enum class SurfaceSmoothing { net, plate, plate_boundary, approx1, approx2 };

struct SmoothSurfaceArgs {
    SurfaceSmoothing method = SurfaceSmoothing::net;
    std::string in, out;
    double lambda = 0.0, poisson = 0.3;
    smoothing::PlateEnergy energy = smoothing::PlateEnergy::no_twist;
    int m = 2, samples = 0;
};

int run_smooth_surface(const SmoothSurfaceArgs& a) {
    const surface::GridHeights g = surface::grid_from_points(read_data_points(a.in));
    const Eigen::MatrixXd lambda = Eigen::MatrixXd::Constant(1, 1, a.lambda);
    OutputFile out(a.out);
    if (a.method == SurfaceSmoothing::net) {  // the net's own unknowns at the nodes
        if (a.samples > 0)
            fail_input("cagd smooth-surface",
                       "--method net gives node values only; use approx2 for a surface to sample");
        const smoothing::ElasticNet net = smoothing::elastic_net(g.x, g.y, g.z, lambda);
        CsvOutput w(out, {"x", "y", "z", "zxx", "zyy"});
        for (std::size_t i = 0; i < g.x.size(); ++i)
            for (std::size_t j = 0; j < g.y.size(); ++j) {
                const Eigen::Index r = static_cast<Eigen::Index>(i), c = static_cast<Eigen::Index>(j);
                w.row({g.x[i], g.y[j], net.values(r, c), net.xx(r, c), net.yy(r, c)}, 15);
            }
        out.commit();
        return 0;
    }
    std::function<double(double, double, int, int)> s;
    if (a.method == SurfaceSmoothing::plate_boundary) {
        const auto b = smoothing::boundary_plate_smoothing(g.x, g.y, g.z, lambda, a.energy, a.m, a.poisson).surface;
        s = [b](double x, double y, int i, int j) { return b.derivative(x, y, i, j); };
    } else {
        const surface::CartesianSurface c =
            a.method == SurfaceSmoothing::plate
                ? smoothing::plate_smoothing(g.x, g.y, g.z, lambda, a.energy, a.poisson).surface
            : a.method == SurfaceSmoothing::approx1
                ? smoothing::local_orthogonal_smoothing(g.x, g.y, g.z, a.lambda, a.energy, a.poisson)
                : smoothing::net_spline_smoothing(g.x, g.y, g.z, lambda);
        s = [c](double x, double y, int i, int j) { return c.derivative(x, y, i, j); };
    }
    CsvOutput w(out, {"x", "y", "z", "zx", "zy", "zxy"});
    const auto emit = [&](double x, double y) {
        w.row({x, y, s(x, y, 0, 0), s(x, y, 1, 0), s(x, y, 0, 1), s(x, y, 1, 1)}, 15);
    };
    if (a.samples == 0) {
        for (double x : g.x)
            for (double y : g.y) emit(x, y);
        out.commit();
        return 0;
    }
    for (int i = 0; i <= a.samples; ++i)
        for (int j = 0; j <= a.samples; ++j)
            emit(std::min(g.x.front() + (g.x.back() - g.x.front()) * i / a.samples, g.x.back()),
                 std::min(g.y.front() + (g.y.back() - g.y.front()) * j / a.samples, g.y.back()));
    out.commit();
    return 0;
}

}  // namespace

Command add_smooth_surface_command(CLI::App& app) {
    auto a = std::make_shared<SmoothSurfaceArgs>();
    CLI::App* c = app.add_subcommand(
        "smooth-surface",
        "Smooth a grid of heights (hosaka sections 6-7): elastic net, plates, approximations 1 and 2");
    add_enum_option(c, "--method", a->method,
                    {{"net", SurfaceSmoothing::net},
                     {"plate", SurfaceSmoothing::plate},
                     {"plate-boundary", SurfaceSmoothing::plate_boundary},
                     {"approx1", SurfaceSmoothing::approx1},
                     {"approx2", SurfaceSmoothing::approx2}},
                    "net | plate (method i) | plate-boundary (method ii) | approx1 (eq 60) | approx2 (net + splines)")
        ->required();
    c->add_option("--lambda", a->lambda, "lambda = EI/k (net) or D/k (plates), >= 0 (> 0 for plates)")->required();
    add_enum_option(c, "--energy", a->energy,
                    {{"55", smoothing::PlateEnergy::poisson},
                     {"56", smoothing::PlateEnergy::no_poisson},
                     {"57", smoothing::PlateEnergy::no_twist},
                     {"58", smoothing::PlateEnergy::mean_curvature}},
                    "plate energy: eq 55 (with --poisson), 56, 57, 58");
    c->add_option("--poisson", a->poisson, "Poisson's ratio for --energy 55, in [0, 0.5)");
    c->add_option("--m", a->m, "plate-boundary: order m of eq (31), 1..4");
    c->add_option("--samples", a->samples,
                  "sample the surface on an (N+1)^2 grid instead of the data nodes (0: the nodes)")
        ->check(CLI::Range(0, 3000));
    c->add_option("--in", a->in, "heights CSV, x,y,z per line covering a rectangular grid; - for stdin")->required();
    c->add_option("--out", a->out, "CSV: x, y, z and derivatives at the nodes (or samples); - for stdout")->required();
    return {c, [a] { return run_smooth_surface(*a); }};
}

}  // namespace cagd::cli
