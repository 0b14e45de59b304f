// make bench, pseudo_energy: table builds (reference vs fast path, in one process) and a single
// lookup. Issue 3 goals: fast 36 × 36 build < 0.5 s, 1° table (361 × 361) < 20 s on two cores,
// lookup < 100 ns. Compare the reported times; nothing here passes or fails.
#include <benchmark/benchmark.h>

#include <cmath>

#include "cagd/fairness/pseudo_energy_table.hpp"

namespace {
using namespace cagd::fairness;

void BM_table36_reference(benchmark::State& s) {
    for (auto _ : s)
        benchmark::DoNotOptimize(
            PseudoEnergyTable::build({36, NodePlacement::periodic}, TableMethod::reference, 2, false));
}
void BM_table36_fast(benchmark::State& s) {
    for (auto _ : s)
        benchmark::DoNotOptimize(PseudoEnergyTable::build({36, NodePlacement::periodic}, TableMethod::fast, 2, true));
}
void BM_table361_fast(benchmark::State& s) {
    for (auto _ : s)
        benchmark::DoNotOptimize(PseudoEnergyTable::build({361, NodePlacement::endpoints}, TableMethod::fast, 2, true));
}
void BM_single_minimum_fast(benchmark::State& s) {
    double a = 0.3;
    for (auto _ : s) {
        benchmark::DoNotOptimize(minimize_pseudo_energy(a, -1.1));
        a = a > 3.0 ? 0.3 : a + 0.01;
    }
}
void BM_lookup36(benchmark::State& s) {
    const PseudoEnergyTable t = PseudoEnergyTable::build({36, NodePlacement::periodic}, TableMethod::fast, 2, true);
    double a = -3.0, b = 1.0;
    for (auto _ : s) {
        benchmark::DoNotOptimize(t.lookup(a, b));
        a = a > 3.0 ? -3.0 : a + 0.0137;
        b = b < -3.0 ? 3.0 : b - 0.0071;
    }
}
}  // namespace

BENCHMARK(BM_table36_reference)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_table36_fast)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK(BM_table361_fast)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_single_minimum_fast)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_lookup36);
