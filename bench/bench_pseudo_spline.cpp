// make bench, pseudo_energy sections 3–5 (its goals below):
//  * pseudo-spline through 10^5 random points with the tables in memory, per tangent mode, against
//    Hermite curve A and Boost.Math's catmull_rom on the same points (construction of an evaluable
//    curve). Goal: the approximate mode within 3× of Hermite A — compare BM_pseudo_spline/approx
//    with BM_hermite_a in the same run.
//  * length and area from the L and S tables (eq 16–21) against adaptive integration of the same
//    curve: the time ratio, and the relative error of the table values as counters.
// Nothing here passes or fails.
#include <benchmark/benchmark.h>

#include <array>
#include <boost/math/interpolators/catmull_rom.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/random_walk.hpp"
#include "cagd/fairness/pseudo_spline.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace {
using namespace cagd;
using namespace cagd::fairness;

// A random walk: chords of length 0.5..2, turning by at most 2.5 rad (no hairpins), seeded.
PointList random_walk(int n, unsigned seed) { return cagd::random_walk(n, seed, 0.5, 2.0, 2.5); }

struct Fixture {
    PseudoEnergyTable table = PseudoEnergyTable::build({36, NodePlacement::periodic}, TableMethod::fast, 2, true);
    AngleMinimumTable angles = AngleMinimumTable::from_energy_table(table);
    TableOracle oracle{table, angles};
    PointList points = random_walk(100000, 4);
};
Fixture& fixture() {
    static Fixture f;
    return f;
}

void BM_pseudo_spline(benchmark::State& s) {
    Fixture& f = fixture();
    const auto mode = static_cast<TangentOptimization>(s.range(0));
    for (auto _ : s) benchmark::DoNotOptimize(pseudo_spline(f.points, f.oracle, mode, false));
    s.SetLabel(to_string(mode));
    s.SetItemsProcessed(s.iterations() * f.points.rows());
}

void BM_hermite_a(benchmark::State& s) {
    Fixture& f = fixture();
    for (auto _ : s)
        benchmark::DoNotOptimize(spline::hermite_interpolant(
            f.points, spline::hermite_tangent_directions(f.points, spline::TangentRule::chord_of_neighbours, false),
            false));
    s.SetItemsProcessed(s.iterations() * f.points.rows());
}

void BM_catmull_rom_boost(benchmark::State& s) {
    Fixture& f = fixture();
    std::vector<std::array<double, 2>> pts(static_cast<std::size_t>(f.points.rows()));
    for (Eigen::Index i = 0; i < f.points.rows(); ++i)
        pts[static_cast<std::size_t>(i)] = {f.points(i, 0), f.points(i, 1)};
    for (auto _ : s) {
        auto copy = pts;  // catmull_rom takes the points by value
        benchmark::DoNotOptimize(boost::math::catmull_rom<std::array<double, 2>>(std::move(copy)));
    }
    s.SetItemsProcessed(s.iterations() * f.points.rows());
}

// Length and area of one pseudo-spline through 1000 of the points: tables vs adaptive integration.
void BM_length_area(benchmark::State& s) {
    Fixture& f = fixture();
    const PointList p = f.points.topRows(1000);
    const PseudoSpline ps = pseudo_spline(p, f.oracle, TangentOptimization::approximate, false);
    const bool tables = s.range(0) == 0;
    double length = 0, area = 0;
    for (auto _ : s) {
        if (tables) {
            length = ps.length_from_tables();
            area = ps.area_from_tables();
        } else {
            length = analysis::adaptive_arc_length(ps.curve, 1e-10);
            const Eigen::MatrixXd& n = ps.curve.nodes();
            area =
                analysis::enclosed_area(ps.curve) + 0.5 * (n(n.rows() - 1, 0) * n(0, 1) - n(n.rows() - 1, 1) * n(0, 0));
        }
        benchmark::DoNotOptimize(length);
        benchmark::DoNotOptimize(area);
    }
    s.SetLabel(tables ? "tables (eq 16-21)" : "adaptive Gauss-Kronrod 1e-10 + exact area");
    if (tables) {
        const double L = analysis::adaptive_arc_length(ps.curve, 1e-12);
        s.counters["length_rel_error"] = std::abs(length - L) / L;
    }
}
}  // namespace

BENCHMARK(BM_pseudo_spline)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_hermite_a)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_catmull_rom_boost)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_length_area)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
