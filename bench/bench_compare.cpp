// make bench, compare (goal: `cagd compare` on 10^5 random points within a minute),
// nothing here passes or fails:
//  - BM_CompareEveryMethod/n: compare_methods (all 19 methods, with the locality re-solve) and the
//    figure data at the CLI's budget, on a seeded random walk of n points. The CLI adds reading,
//    writing and gnuplot (about 8 s at 10^5 on the 2-core machine of results/timing).
//  - BM_CompareHermiteA/n: the same for one local method, the baseline: the ratio shows what the
//    other 18 cost, the curvature-profile Newton above all.
#include <benchmark/benchmark.h>

#include "cagd/compare/comparison_figure.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/random_walk.hpp"

using namespace cagd;

namespace {

void run_comparison(benchmark::State& state, const std::vector<std::string>& methods) {
    const PointList p = cagd::random_walk(state.range(0), 1, 0.2, 1.0, 1.2);
    compare::ComparisonOptions o;
    o.methods = methods;
    for (auto _ : state) {
        const std::vector<compare::MethodComparison> c = compare::compare_methods(p, o);
        const compare::FigureData d =
            compare::comparison_figure_data(c, p, compare::figure_sampling(static_cast<int>(p.rows()) - 1, 10000));
        benchmark::DoNotOptimize(d.curves.data());
        for (const compare::MethodComparison& m : c)
            if (m.status != compare::AttemptStatus::ok)
                state.SkipWithError((m.method + ": " + compare::to_string(m.status) + " " + m.note).c_str());
    }
    state.counters["points"] = static_cast<double>(state.range(0));
}

void BM_CompareEveryMethod(benchmark::State& state) { run_comparison(state, {}); }
BENCHMARK(BM_CompareEveryMethod)->Arg(1000)->Arg(10000)->Arg(100000)->Iterations(1)->Unit(benchmark::kSecond);

void BM_CompareHermiteA(benchmark::State& state) { run_comparison(state, {"hermite-a"}); }
BENCHMARK(BM_CompareHermiteA)->Arg(1000)->Arg(10000)->Arg(100000)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
