// make bench, typical_curves (its goals below), nothing here passes or fails:
//  - degree-99 Bézier jets to 3rd order at 10^4 parameters: de Casteljau (O(n²), the baseline in
//    the same run), the O(n) Bernstein evaluation and the naive power basis; counter max_error =
//    largest |jet − reference| over the 10^4 parameters, the reference being de Casteljau in
//    50-digit arithmetic (Boost.Multiprecision) at the same parameters, relative to the jet's size;
//  - the Fig. 7 region at 1000 × 1000 points (condition 29, Bernstein signs, exact sign of dκ/dt):
//    goal under 2 s; the baseline is the same grid with condition (29) alone.
#include <benchmark/benchmark.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "cagd/aesthetic/cubic_bspline_monotonicity.hpp"
#include "cagd/aesthetic/typical_bezier.hpp"
#include "cagd/spline/bezier.hpp"

namespace {

using Big = boost::multiprecision::cpp_bin_float_50;
constexpr int kParams = 10000;

// d^k r/dt^k (k ≤ 3) by forward differences and de Casteljau in 50 digits.
std::vector<Eigen::MatrixXd> reference_jets(const Eigen::MatrixXd& cp) {
    const int n = static_cast<int>(cp.rows()) - 1;
    std::vector<std::vector<std::array<Big, 2>>> diffs(4);
    for (int i = 0; i <= n; ++i) diffs[0].push_back({Big(cp(i, 0)), Big(cp(i, 1))});
    for (int k = 1; k <= 3; ++k)
        for (std::size_t i = 0; i + 1 < diffs[k - 1].size(); ++i)
            diffs[k].push_back(
                {diffs[k - 1][i + 1][0] - diffs[k - 1][i][0], diffs[k - 1][i + 1][1] - diffs[k - 1][i][1]});
    std::vector<Eigen::MatrixXd> out;
    for (int q = 0; q < kParams; ++q) {
        const Big t = Big(q) / (kParams - 1);
        Eigen::MatrixXd j(4, 2);
        Big factor = 1;
        for (int k = 0; k <= 3; ++k) {
            if (k > 0) factor *= n - k + 1;
            std::vector<std::array<Big, 2>> w = diffs[k];
            for (std::size_t r = w.size() - 1; r > 0; --r)
                for (std::size_t i = 0; i < r; ++i)
                    for (int c = 0; c < 2; ++c) w[i][c] = (1 - t) * w[i][c] + t * w[i + 1][c];
            j(k, 0) = static_cast<double>(factor * w[0][0]);
            j(k, 1) = static_cast<double>(factor * w[0][1]);
        }
        out.push_back(j);
    }
    return out;
}

void BM_degree99_jets(benchmark::State& s) {
    const auto method = static_cast<cagd::BezierEvaluation>(s.range(0));
    const Eigen::MatrixXd cp = cagd::aesthetic::scale_one_typical_polygon(-0.5, 1.0, 99).points;
    const cagd::BezierCurve c(cp, 0.0, 1.0, method);
    for (auto _ : s)
        for (int q = 0; q < kParams; ++q) benchmark::DoNotOptimize(c.jet(static_cast<double>(q) / (kParams - 1), 3));
    static const std::vector<Eigen::MatrixXd> ref = reference_jets(cp);
    double err = 0;
    for (int q = 0; q < kParams; ++q) {
        const Eigen::MatrixXd j = c.jet(static_cast<double>(q) / (kParams - 1), 3);
        for (int k = 0; k <= 3; ++k)
            err = std::max(err, (j.row(k) - ref[static_cast<std::size_t>(q)].row(k)).norm() /
                                    (1e-300 + ref[static_cast<std::size_t>(q)].row(k).norm()));
    }
    s.counters["max_error"] = err;
    s.SetItemsProcessed(s.iterations() * kParams);
    s.SetLabel(method == cagd::BezierEvaluation::de_casteljau ? "de Casteljau (baseline)"
               : method == cagd::BezierEvaluation::bernstein  ? "Bernstein O(n)"
                                                              : "power basis");
}

void BM_fig7_region(benchmark::State& s) {
    for (auto _ : s) benchmark::DoNotOptimize(cagd::aesthetic::monotonicity_region(1000, 0.0, std::numbers::pi / 2));
    s.SetItemsProcessed(s.iterations() * 1000000);
}

void BM_fig7_condition29_baseline(benchmark::State& s) {
    for (auto _ : s) {
        double count = 0;
        for (int i = 0; i < 1000; ++i)
            for (int j = 0; j < 1000; ++j)
                count +=
                    cagd::aesthetic::condition29(std::numbers::pi / 2 * i / 999, std::numbers::pi / 2 * j / 999) > 0.0;
        benchmark::DoNotOptimize(count);
    }
    s.SetItemsProcessed(s.iterations() * 1000000);
}

}  // namespace

BENCHMARK(BM_degree99_jets)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_fig7_region)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_fig7_condition29_baseline)->Unit(benchmark::kMillisecond);
