// make bench: timings, never pass/fail. Ratios matter, not absolute times: the baseline
// (conventional cubic B-spline interpolant, a banded solve) runs in the same process.
#include <benchmark/benchmark.h>

#include <cmath>

#include "cagd/locality/locality_spline.hpp"

namespace {
cagd::PointList wave(long n) {
    cagd::PointList p(n, 2);
    for (long i = 0; i < n; ++i) p.row(i) << double(i), std::sin(0.7 * double(i));
    return p;
}

void BM_cubic_bspline_interpolant(benchmark::State& s) {
    const auto p = wave(s.range(0));
    for (auto _ : s) benchmark::DoNotOptimize(cagd::locality::cubic_bspline_interpolant(p, false));
    s.SetComplexityN(s.range(0));
}
void BM_s_spline_m5(benchmark::State& s) {
    const auto p = wave(s.range(0));
    cagd::locality::Options o;
    o.m = {{5, 5}};
    for (auto _ : s) benchmark::DoNotOptimize(cagd::locality::interpolate(p, o));
    s.SetComplexityN(s.range(0));
}
void BM_evaluate_s_spline(benchmark::State& s) {
    const auto c = cagd::locality::interpolate(wave(1000), {}).curve;
    double u = 0.0;
    for (auto _ : s) {
        benchmark::DoNotOptimize(c.jet(u, 2));
        u = std::fmod(u + 0.618, 999.0);
    }
}
}  // namespace

BENCHMARK(BM_cubic_bspline_interpolant)->RangeMultiplier(10)->Range(100, 100000)->Complexity();
BENCHMARK(BM_s_spline_m5)->RangeMultiplier(10)->Range(100, 100000)->Complexity();
BENCHMARK(BM_evaluate_s_spline);
BENCHMARK_MAIN();
