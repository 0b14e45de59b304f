// make bench, hosaka sections 6-7 (its goals below), nothing here passes or fails:
//  - the elastic line (five-term system (51), banded LDLT) through 10^3 … 10^6 points should take
//    linear time: items_per_second flat across the sizes; the interpolating spline of eq (23) on the
//    same data is the baseline in the same run;
//  - the elastic net on a 200 × 200 grid: goal under 2 s; counters give the unknowns and the memory
//    of the LDLT factor (nonzeros × 12 bytes: a double and an index);
//  - the surface methods on one 41 × 41 grid, for the comparison's time column.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "cagd/smoothing/elastic_line.hpp"
#include "cagd/smoothing/surface_smoothing.hpp"

namespace {

struct LineData {
    std::vector<double> x;
    Eigen::MatrixXd a;
};
LineData noisy_line(long n) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> step(0.5, 1.5);
    std::normal_distribution<double> noise(0.0, 0.1);
    LineData d{{}, Eigen::MatrixXd(n, 1)};
    double x = 0;
    for (long i = 0; i < n; ++i) {
        d.x.push_back(x);
        d.a(i, 0) = std::sin(0.01 * x) + noise(rng);
        x += step(rng);
    }
    return d;
}

void BM_elastic_line(benchmark::State& s) {
    const LineData d = noisy_line(s.range(0));
    for (auto _ : s) benchmark::DoNotOptimize(cagd::smoothing::elastic_line(d.x, d.a, 0.5));
    s.SetItemsProcessed(s.iterations() * s.range(0));
}

void BM_interpolating_spline_baseline(benchmark::State& s) {
    const LineData d = noisy_line(s.range(0));
    for (auto _ : s) benchmark::DoNotOptimize(cagd::spline::hosaka_explicit_spline(d.x, d.a));
    s.SetItemsProcessed(s.iterations() * s.range(0));
}

struct GridData {
    std::vector<double> x, y;
    Eigen::MatrixXd a;
};
GridData noisy_grid(long n) {
    std::mt19937 rng(19);
    std::normal_distribution<double> noise(0.0, 0.02);
    GridData g{{}, {}, Eigen::MatrixXd(n, n)};
    for (long i = 0; i < n; ++i) {
        g.x.push_back(static_cast<double>(i) / static_cast<double>(n - 1));
        g.y.push_back(static_cast<double>(i) / static_cast<double>(n - 1));
    }
    for (long i = 0; i < n; ++i)
        for (long j = 0; j < n; ++j)
            g.a(i, j) =
                std::sin(3 * g.x[static_cast<std::size_t>(i)]) * std::cos(2 * g.y[static_cast<std::size_t>(j)]) +
                noise(rng);
    return g;
}

void BM_elastic_net(benchmark::State& s) {
    const GridData g = noisy_grid(s.range(0));
    const Eigen::MatrixXd lambda = Eigen::MatrixXd::Constant(1, 1, 1e-6);
    cagd::smoothing::ElasticNet net;
    for (auto _ : s) {
        net = cagd::smoothing::elastic_net(g.x, g.y, g.a, lambda);
        benchmark::DoNotOptimize(net.values.data());
    }
    s.counters["unknowns"] = static_cast<double>(net.system_size);
    s.counters["factor_MB"] = static_cast<double>(net.factor_nonzeros) * 12.0 / 1e6;
    s.SetItemsProcessed(s.iterations() * s.range(0) * s.range(0));
}

void BM_surface_method(benchmark::State& s) {
    const GridData g = noisy_grid(41);
    const Eigen::MatrixXd lambda = Eigen::MatrixXd::Constant(1, 1, 1e-5);
    using cagd::smoothing::PlateEnergy;
    for (auto _ : s) switch (s.range(0)) {
            case 0: benchmark::DoNotOptimize(cagd::smoothing::net_spline_smoothing(g.x, g.y, g.a, lambda)); break;
            case 1:
                benchmark::DoNotOptimize(
                    cagd::smoothing::plate_smoothing(g.x, g.y, g.a, lambda, PlateEnergy::no_twist));
                break;
            case 2:
                benchmark::DoNotOptimize(
                    cagd::smoothing::boundary_plate_smoothing(g.x, g.y, g.a, lambda, PlateEnergy::no_twist, 2));
                break;
            default:
                benchmark::DoNotOptimize(
                    cagd::smoothing::local_orthogonal_smoothing(g.x, g.y, g.a, 1e-5, PlateEnergy::no_twist));
                break;
        }
    static const char* names[] = {"approx2 (net + splines)", "plate (i) eq 57", "plate (ii) eq 57 m=2",
                                  "approx1 eq 57"};
    s.SetLabel(names[s.range(0)]);
}

}  // namespace

BENCHMARK(BM_elastic_line)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_interpolating_spline_baseline)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_elastic_net)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_surface_method)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
