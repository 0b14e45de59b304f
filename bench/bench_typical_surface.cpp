// make bench, typical_curves section 5 (its goal below), nothing here passes or fails:
//  - the Fig. 6 bi-degree-24 patch with Gaussian and mean curvature on a 200 × 200 parameter grid:
//    goal under 1 s. The baseline in the same run is the point-by-point evaluation (basis values
//    and the O(mn) contraction per point, BezierPatch::jet); the grid path shares the basis
//    values along each parameter line and contracts by matrix products (evaluate_grid).
//    Counter max_diff = largest |K_grid − K_pointwise| + |H_grid − H_pointwise|.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "cagd/aesthetic/typical_surface.hpp"
#include "cagd/analysis/surface_curvature.hpp"
#include "cagd/surface/bezier_patch.hpp"

namespace {

constexpr int kGrid = 200;

const cagd::surface::BezierPatch& fig6_patch() {
    static const cagd::surface::BezierPatch patch(
        cagd::aesthetic::log_aesthetic_typical_net(-0.5, -0.6, 1.0, 24, 0.01 * std::numbers::pi / 180.0));
    return patch;
}

std::vector<double> grid_parameters() {
    std::vector<double> t;
    for (int k = 0; k < kGrid; ++k) t.push_back(static_cast<double>(k) / (kGrid - 1));
    return t;
}

void BM_bi24_curvature_grid(benchmark::State& state) {
    const auto& patch = fig6_patch();
    const std::vector<double> t = grid_parameters();
    double max_diff = 0.0;
    for (auto _ : state) {
        const cagd::surface::SurfaceGrid g = patch.evaluate_grid(t, t);
        double sum = 0.0;
        for (Eigen::Index a = 0; a < kGrid; ++a)
            for (Eigen::Index b = 0; b < kGrid; ++b) {
                const cagd::analysis::SurfaceCurvatures c = cagd::analysis::surface_curvatures(g.jet(a, b));
                sum += c.gaussian + c.mean;
            }
        benchmark::DoNotOptimize(sum);
    }
    const cagd::surface::SurfaceGrid g = patch.evaluate_grid(t, t);
    for (Eigen::Index a = 0; a < kGrid; a += 7)
        for (Eigen::Index b = 0; b < kGrid; b += 7) {
            const cagd::analysis::SurfaceCurvatures x = cagd::analysis::surface_curvatures(g.jet(a, b));
            const cagd::analysis::SurfaceCurvatures y = cagd::analysis::surface_curvatures(
                patch.jet(t[static_cast<std::size_t>(a)], t[static_cast<std::size_t>(b)]));
            max_diff = std::max(max_diff, std::abs(x.gaussian - y.gaussian) + std::abs(x.mean - y.mean));
        }
    state.counters["max_diff"] = max_diff;
}

void BM_bi24_curvature_pointwise_baseline(benchmark::State& state) {
    const auto& patch = fig6_patch();
    const std::vector<double> t = grid_parameters();
    for (auto _ : state) {
        double sum = 0.0;
        for (double u : t)
            for (double v : t) {
                const cagd::analysis::SurfaceCurvatures c = cagd::analysis::surface_curvatures(patch.jet(u, v));
                sum += c.gaussian + c.mean;
            }
        benchmark::DoNotOptimize(sum);
    }
}

}  // namespace

BENCHMARK(BM_bi24_curvature_grid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_bi24_curvature_pointwise_baseline)->Unit(benchmark::kMillisecond);
