// make bench, curvature_profile (its goals below), nothing here passes or fails:
//  - BM_Fig3Solve: the Fig. 3 design (13 points, lines and arcs), C2 start + Newton with the
//    Moore–Penrose step to ‖f‖∞ ≤ 1e-12·scale: goal under 10 ms.
//  - BM_NewtonIterationSparse/n: one Newton iteration (residual, sparse Jacobian, SparseLU step) of an
//    open G2 clothoid spline with natural ends through n = 10…1000 points on y = sin x: time per
//    point should stay about constant (linear growth). BM_NewtonIterationDense/n, the dense
//    Moore–Penrose step on the same systems, is the baseline that grows like n³.
//  - BM_CurvatureProfileLuStep/100000: the linear algebra of one Newton step of the registry's
//    curvature-profile on BM_Construct's random walk of 10^5 points (bench_methods.cpp): LAPACK's
//    banded LU of the Jacobian at the C2 start (dgbtrf, through numeric::BandedOrSparseLu, its band
//    analysed once as Newton analyses it) and the solve (dgbtrs). Times BM_Construct's newton_steps,
//    it is the part of that construction no evaluation of f and J can shorten
//    (scripts/bench-targets.py sets it beside the 50× cubic-b target).
#include <benchmark/benchmark.h>

#include <Eigen/SparseLU>
#include <cmath>

#include "cagd/core/random_walk.hpp"
#include "cagd/intrinsic/curvature_profile_design.hpp"
#include "cagd/numeric/banded_or_sparse_lu.hpp"

using namespace cagd;
using namespace cagd::intrinsic;

namespace {

CurvatureProfileProblem fig3_problem() {
    PointList p(13, 2);
    p << 9, 1, 4, 1, 1, 3, 1, 6, 2, 7, 7, 7, 10, 3.5, 14, 3.5, 14, 6, 15, 7, 17, 4.2, 20, 3, 22, 3;
    const KnotLayout layout =
        parse_knot_difference_list(
            "{0, S0, 0, S1, 0, S2, 0, S3, 0, S4, 0, S5, 0, S6, 0, S7, 0, S8, 0, {S9, S10}, S11, S12, 0}", 2)
            .layout;
    return {p,
            layout,
            segment_shapes(layout, parse_span_shapes("line,free,line,arc,line,free,arc,line,arc,free,free,line")),
            {},
            false,
            0};
}

CurvatureProfileProblem sine_problem(int points) {
    PointList p(points, 2);
    for (int i = 0; i < points; ++i) p.row(i) << 0.5 * i, std::sin(0.5 * i);
    const std::vector<SegmentShape> spans(static_cast<std::size_t>(points) - 1, SegmentShape::free);
    const KnotLayout layout = span_layout(spans);
    return {
        p,
        layout,
        spans,
        {{DesignCondition::Kind::curvature, 0, 0.0, false}, {DesignCondition::Kind::curvature, points - 1, 0.0, true}},
        false,
        0};
}

void BM_Fig3Solve(benchmark::State& state) {
    const CurvatureProfileProblem P = fig3_problem();
    for (auto _ : state) {
        const CurvatureProfileSolution s = solve_curvature_profile(P, c2_start(P));
        benchmark::DoNotOptimize(s.u.data());
        if (!s.outcome.ok()) state.SkipWithError(s.outcome.message.c_str());
    }
}
BENCHMARK(BM_Fig3Solve)->Unit(benchmark::kMillisecond);

void BM_NewtonIterationSparse(benchmark::State& state) {
    const CurvatureProfileProblem P = sine_problem(static_cast<int>(state.range(0)));
    const Eigen::VectorXd u = c2_start(P);
    for (auto _ : state) {
        const DesignSystem sys = design_system(P, u, true);
        Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(sys.jacobian);
        const Eigen::VectorXd step = lu.solve(sys.f);
        benchmark::DoNotOptimize(step.data());
    }
    state.counters["points"] = static_cast<double>(state.range(0));
    state.counters["per_point"] =
        benchmark::Counter(static_cast<double>(state.range(0)),
                           benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_NewtonIterationSparse)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

void BM_NewtonIterationDense(benchmark::State& state) {
    const CurvatureProfileProblem P = sine_problem(static_cast<int>(state.range(0)));
    const Eigen::VectorXd u = c2_start(P);
    for (auto _ : state) {
        const DesignSystem sys = design_system(P, u, true);
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod{Eigen::MatrixXd(sys.jacobian)};
        const Eigen::VectorXd step = cod.solve(sys.f);
        benchmark::DoNotOptimize(step.data());
    }
    state.counters["points"] = static_cast<double>(state.range(0));
}
// The registry's curvature-profile problem (methods/register_curvature_profile.cpp: free spans on
// span_layout, natural ends) through BM_Construct's random walk.
CurvatureProfileProblem random_walk_problem(long points) {
    const PointList p = random_walk(points, 7, 0.1, 2.0, 1.0);
    const std::vector<SegmentShape> spans(static_cast<std::size_t>(points) - 1, SegmentShape::free);
    CurvatureProfileProblem P{p, span_layout(spans), {}, {}, false, 0};
    P.shapes = segment_shapes(P.layout, spans);
    add_natural_open_ends(P);
    return P;
}

void BM_CurvatureProfileLuStep(benchmark::State& state) {
    const CurvatureProfileProblem P = random_walk_problem(state.range(0));
    const DesignSystem sys = design_system(P, c2_start(P), true);
    numeric::BandedOrSparseLu lu;
    DesignBandOrdering order = design_band_ordering(P);
    lu.analyze(sys.jacobian, std::move(order.rows), std::move(order.columns), kMaxBandStorageRows);
    if (!lu.banded()) state.SkipWithError("the Jacobian's band is not narrow: not the banded LU Newton takes");
    for (auto _ : state) {
        if (!lu.factorize(sys.jacobian)) state.SkipWithError("singular Jacobian");
        const Eigen::VectorXd step = lu.solve(sys.f);
        benchmark::DoNotOptimize(step.data());
    }
}
BENCHMARK(BM_CurvatureProfileLuStep)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

BENCHMARK(BM_NewtonIterationDense)->Arg(10)->Arg(100)->Arg(300)->Unit(benchmark::kMicrosecond);

}  // namespace
