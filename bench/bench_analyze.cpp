// make bench, `cagd analyze --in` (goal: the Table 1 data in at most 0.2 s):
//  - BM_AnalyzeIn/<method>: what the command computes after reading the points — the curve
//    (methods::interpolate), its length by adaptive Gauss–Kronrod to 1e-12, the area closed by
//    the chord, the sampled curvature extremes — on the 13 points of pseudo_energy Table 1.
//    The pseudo-spline's 36-node table is built once per process (about 0.15 s on two cores,
//    which the command pays on every run) before the timed loop.
//  - BM_AnalyzeInRombergLength: the length by Romberg to 1e-13 instead, as the command did before
//    (seconds per span: the reason for the change), on the cubic-b curve, as the baseline.
#include <benchmark/benchmark.h>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/methods/method_registry.hpp"

using namespace cagd;

namespace {

PointList table1() {
    return read_points_csv(std::string(CAGD_SOURCE_DIR) + "/reference/pseudo_energy/data/table1.csv");
}

void BM_AnalyzeIn(benchmark::State& state, const char* method) {
    const PointList p = table1();
    methods::interpolate(method, p, false);  // the per-process table, outside the timing
    for (auto _ : state) {
        const methods::InterpolationResult r = methods::interpolate(method, p, false);
        const Curve& c = *r.interpolant->curve;
        benchmark::DoNotOptimize(analysis::accurate_arc_length(c).value + analysis::area_closed_by_chord(c) +
                                 analysis::curvature_torsion_extremes(c).max_abs_curvature);
    }
}
BENCHMARK_CAPTURE(BM_AnalyzeIn, pseudo_spline, "pseudo-spline")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AnalyzeIn, cubic_b, "cubic-b")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AnalyzeIn, curvature_profile, "curvature-profile")->Unit(benchmark::kMillisecond);

void BM_AnalyzeInRombergLength(benchmark::State& state) {
    const PointList p = table1();
    const methods::InterpolationResult r = methods::interpolate("cubic-b", p, false);
    for (auto _ : state) benchmark::DoNotOptimize(analysis::romberg_arc_length(*r.interpolant->curve).value);
}
BENCHMARK(BM_AnalyzeInRombergLength)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
