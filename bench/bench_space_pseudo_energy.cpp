// The space pseudo-energy targets: the 36 × 36 × 72 fast space table on 2 threads (≤ 60 s) and its lookup (≤ 100 ns).
#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <vector>

#include "cagd/fairness/space_pseudo_energy_table.hpp"

using namespace cagd;
using namespace cagd::fairness;

namespace {

void BM_SpaceTable36x36x72(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(SpacePseudoEnergyTable::build({36, 72}, TableMethod::fast, 2));
    state.SetItemsProcessed(state.iterations() * 36L * 36 * 72);
}
BENCHMARK(BM_SpaceTable36x36x72)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_SpaceTableLookup(benchmark::State& state) {
    const SpacePseudoEnergyTable t = SpacePseudoEnergyTable::build({12, 24}, TableMethod::fast, 2);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> theta(0.0, 3.14159), phi(0.0, 6.28318);
    std::vector<std::array<double, 3>> q(4096);
    for (auto& x : q) x = {theta(rng), theta(rng), phi(rng)};
    std::size_t k = 0;
    for (auto _ : state) {
        const auto& x = q[k++ & 4095];
        benchmark::DoNotOptimize(t.lookup(x[0], x[1], x[2]));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SpaceTableLookup);

}  // namespace
