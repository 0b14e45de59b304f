// make bench, OpenCASCADE as its users call it: the peer that occt-interpolate wraps
// (methods/register_opencascade.cpp), so that docs/performance.md can set the wrapper's figures
// beside OpenCASCADE's own. Built only where CMake found OpenCASCADE; nothing here passes or fails.
//  - BM_RawOpenCascade/1000000: Geom2dAPI_Interpolate through BM_Construct's random walk of 10^6
//    points (bench_methods.cpp), given as they are (gp_Pnt2d), open, chord-length parameters (its
//    default), and its B-spline; median of 3.
//  - BM_RawOpenCascadeMemory/1000000: the heap bytes per point of one such interpolation
//    (allocation_tracking.hpp): the peak while it runs and what its curve keeps.
// The wrapper maps the points onto a unit box first and copies the curve out; OpenCASCADE's own
// work is the same.
#include <benchmark/benchmark.h>

#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Precision.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>

#include "allocation_tracking.hpp"
#include "cagd/core/random_walk.hpp"

namespace {

Handle(Geom2d_BSplineCurve) raw_interpolation(const cagd::PointList& p) {
    Handle(TColgp_HArray1OfPnt2d) points = new TColgp_HArray1OfPnt2d(1, static_cast<int>(p.rows()));
    for (Eigen::Index i = 0; i < p.rows(); ++i) points->SetValue(static_cast<int>(i) + 1, gp_Pnt2d(p(i, 0), p(i, 1)));
    Geom2dAPI_Interpolate interpolate(points, false, Precision::Confusion());
    interpolate.Perform();
    return interpolate.IsDone() ? interpolate.Curve() : Handle(Geom2d_BSplineCurve)();
}

void BM_RawOpenCascade(benchmark::State& state) {
    const cagd::PointList p = cagd::random_walk(state.range(0), 7, 0.1, 2.0, 1.0);
    for (auto _ : state) {
        const Handle(Geom2d_BSplineCurve) curve = raw_interpolation(p);
        if (curve.IsNull()) state.SkipWithError("Geom2dAPI_Interpolate found no curve");
        benchmark::DoNotOptimize(curve.get());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_RawOpenCascadeMemory(benchmark::State& state) {
    const cagd::PointList p = cagd::random_walk(state.range(0), 7, 0.1, 2.0, 1.0);
    for (auto _ : state) {
        const std::ptrdiff_t before = cagd_bench::live_heap_bytes();
        cagd_bench::reset_peak_heap_bytes();
        const Handle(Geom2d_BSplineCurve) curve = raw_interpolation(p);
        const std::ptrdiff_t peak = cagd_bench::peak_heap_bytes() - before,
                             kept = cagd_bench::live_heap_bytes() - before;
        if (curve.IsNull()) state.SkipWithError("Geom2dAPI_Interpolate found no curve");
        const double n = static_cast<double>(state.range(0));
        state.counters["peak_bytes_per_point"] = static_cast<double>(peak) / n;
        state.counters["retained_bytes_per_point"] = static_cast<double>(kept) / n;
    }
}

}  // namespace

BENCHMARK(BM_RawOpenCascade)->Arg(1000000)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK(BM_RawOpenCascadeMemory)->Arg(1000000)->Iterations(1)->Unit(benchmark::kMillisecond);
