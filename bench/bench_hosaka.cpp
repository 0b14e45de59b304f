// make bench, hosaka section 3 (its goal below): the C2 spline with scale factors (eq 20) through
// 10^3 … 10^6 points should take linear time — items_per_second flat across the sizes — compared,
// in the same run, with Boost.Math's cardinal cubic B-spline (uniform parameter, per coordinate).
// Nothing here passes or fails.
#include <benchmark/benchmark.h>

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "cagd/core/random_walk.hpp"
#include "cagd/spline/hosaka_spline.hpp"

namespace {
cagd::PointList walk(long n) { return cagd::random_walk(n, 11, 0.1, 2.0, 1.0); }

void BM_hosaka_c2_chord(benchmark::State& s) {
    const cagd::PointList p = walk(s.range(0));
    for (auto _ : s) benchmark::DoNotOptimize(cagd::spline::hosaka_c2_spline(p));
    s.SetItemsProcessed(s.iterations() * s.range(0));
}

void BM_boost_cardinal_cubic_b_spline_xy(benchmark::State& s) {
    const cagd::PointList p = walk(s.range(0));
    std::vector<double> x(p.col(0).data(), p.col(0).data() + p.rows()), y(p.col(1).data(), p.col(1).data() + p.rows());
    for (auto _ : s) {
        boost::math::interpolators::cardinal_cubic_b_spline<double> sx(x.data(), x.size(), 0.0, 1.0);
        boost::math::interpolators::cardinal_cubic_b_spline<double> sy(y.data(), y.size(), 0.0, 1.0);
        benchmark::DoNotOptimize(sx(0.5));
        benchmark::DoNotOptimize(sy(0.5));
    }
    s.SetItemsProcessed(s.iterations() * s.range(0));
}
}  // namespace

BENCHMARK(BM_hosaka_c2_chord)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_boost_cardinal_cubic_b_spline_xy)
    ->RangeMultiplier(10)
    ->Range(1000, 10000000)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);  // median of 3, like the constructions it is the peer of
