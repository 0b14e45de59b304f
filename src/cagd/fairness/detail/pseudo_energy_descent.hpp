#pragma once
// The minimisation of J = L²E over (r0, r1) of a unit-chord Hermite segment, for any dimension
// (pseudo_energy_minimum.cpp: the plane; space_pseudo_energy.cpp: space): the log-r scan for
// seeds, Newton's method in ρ = log r, the reference descents (Ceres CG on the Romberg energy,
// Newton polish) and the choice among distinct minima. The callers supply the segment's energy
// as a function of (r0, r1). See pseudo_energy_minimum.hpp for the method and its stopping rules.
#if CAGD_WITH_CERES
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <glog/logging.h>
#endif

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "cagd/core/optional_dependencies.hpp"
#include "cagd/fairness/hermite_segment.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"

namespace cagd::fairness::detail {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A descent that ends beyond these has run off towards r = 0 or r = ∞.
constexpr double kRunawayLow = 1e-8, kRunawayHigh = 1e8;

struct ScanPoint {
    double j;
    double rho0, rho1;
};

// Grid-interior local minima of the fast J over the scan box, lowest first; j_at(r0, r1) is the
// cheap energy of the segment (the 8-point rule).
template <class ScanEnergy>
std::vector<ScanPoint> scan_minima(const ScanEnergy& j_at, const ScanBox& box, long& evaluations) {
    const int n = box.n;
    const double lo = std::log(box.r_lo), hi = std::log(box.r_hi);
    const auto rho = [&](int i) { return lo + (hi - lo) * i / (n - 1); };
    std::vector<double> grid(static_cast<std::size_t>(n * n));
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            grid[static_cast<std::size_t>(a * n + b)] = j_at(std::exp(rho(a)), std::exp(rho(b)));
        }
    evaluations += static_cast<long>(n) * n;
    std::vector<ScanPoint> out;
    // Local minima among the existing neighbours, the box's edge included: a minimum beyond
    // the box shows up on its edge and the descent leaves the box towards it.
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            const double v = grid[static_cast<std::size_t>(a * n + b)];
            if (!std::isfinite(v)) continue;
            bool minimum = true;
            for (int da = -1; da <= 1 && minimum; ++da)
                for (int db = -1; db <= 1; ++db) {
                    const int x = a + da, y = b + db;
                    if ((da || db) && x >= 0 && y >= 0 && x < n && y < n &&
                        grid[static_cast<std::size_t>(x * n + y)] < v)
                        minimum = false;
                }
            if (minimum) out.push_back({v, rho(a), rho(b)});
        }
    std::sort(out.begin(), out.end(), [](const ScanPoint& p, const ScanPoint& q) { return p.j < q.j; });
    // A narrow diagonal valley need not show as a discrete minimum on a coarse grid: add the
    // lowest grid points lying more than two cells from every seed so far (three of them).
    std::vector<int> order(static_cast<std::size_t>(n * n));
    for (int k = 0; k < n * n; ++k) order[static_cast<std::size_t>(k)] = k;
    std::sort(order.begin(), order.end(),
              [&](int p, int q) { return grid[static_cast<std::size_t>(p)] < grid[static_cast<std::size_t>(q)]; });
    const double step = (hi - lo) / (n - 1);
    int extra = 0;
    for (int k : order) {
        if (extra == 3 || !std::isfinite(grid[static_cast<std::size_t>(k)])) break;
        const double ra = rho(k / n), rb = rho(k % n);
        bool far = true;
        for (const ScanPoint& p : out)
            if (std::abs(p.rho0 - ra) <= 2.5 * step && std::abs(p.rho1 - rb) <= 2.5 * step) far = false;
        if (!far) continue;
        out.push_back({grid[static_cast<std::size_t>(k)], ra, rb});
        ++extra;
    }
    std::stable_sort(out.begin(), out.end(), [](const ScanPoint& p, const ScanPoint& q) { return p.j < q.j; });
    // Seeds worth a descent: within a factor 2 of the lowest (the basins that matter; the edge
    // points towards r → 0 have far higher J unless the minimum really lies out there).
    if (!out.empty()) {
        const double limit = 2.0 * out.front().j;
        out.erase(std::remove_if(out.begin() + 1, out.end(), [&](const ScanPoint& p) { return p.j > limit; }),
                  out.end());
    }
    return out;
}

// newton_descent's stopping rules and safeguards, each with its reason.
// Central-difference step for the Hessian of the analytic ∇J in ρ = log r: truncation O(h²) and
// rounding O(ε/h) balance near ε^(1/3) ≈ 6e-6.
constexpr double kHessianStep = 1e-5;
// Newton converges quadratically in about ten steps; a hundred only guards against cycling.
constexpr int kNewtonIterations = 100;
// Converged when |∇J| ≤ kGradientAtRounding · (1 + J): the gradient is at rounding level.
constexpr double kGradientAtRounding = 1e-14;
// At the rounding floor (no acceptable step) a descent still counts as converged when
// |∇J| ≤ kGradientConverged · (1 + J): about 1e4 ε, what the energy's quadrature noise leaves.
constexpr double kGradientConverged = 1e-10;
// Levenberg damping relative to the Hessian's scale 1 + |λ_max|: the first shift above an
// indefinite Hessian's least eigenvalue, the floor of μ, and its growth per rejected step.
constexpr double kDampingShift = 1e-6;
constexpr double kDampingFloor = 1e-9;
constexpr double kDampingGrowth = 8.0;
// Rejected steps before giving up: 8^40 ≈ 1e36 has turned any step into a tiny steepest descent.
constexpr int kDampingTries = 40;
// |ρ| < 50 (r between 2e-22 and 5e21, far past the runaway limits): beyond it J loses every digit.
constexpr double kLogMagnitudeLimit = 50.0;
// A step changes r by at most a factor e = exp(kMaxStep): J's valleys curve at small angles.
constexpr double kMaxStep = 1.0;
// A step shorter than this in ρ changes r by less than rounding.
constexpr double kStepAtRounding = 1e-15;
// A "flatter" step (smaller |∇J|) may raise J by the quadrature noise of the energy (relative).
constexpr double kEnergyNoise = 1e-13;
// The reference path's Ceres CG (Polak–Ribière, Wolfe line search with curvature factor 0.1, the
// usual choice for CG): its stopping tolerances sit just above the Romberg energy's noise (1e-13
// relative), and the Newton polish below takes the last digits.
constexpr int kCgIterations = 500;
constexpr double kCgFunctionTolerance = 1e-14, kCgGradientTolerance = 1e-11, kCgParameterTolerance = 1e-13;
// The NLopt cross-check (L-BFGS on r ∈ [1e-4, 1e4]): ~20–60 evaluations converge; beyond
// kLbfgsEvaluations it is stalled at the noise floor. A value-based method stops at
// |∇J| ~ sqrt(quadrature noise · J · λ), so it counts as converged at kLbfgsGradient · (1 + J).
constexpr double kLbfgsBound = 1e4, kLbfgsFtolRel = 1e-15, kLbfgsXtolRel = 1e-12, kLbfgsGradient = 1e-6;
constexpr int kLbfgsEvaluations = 300;
// Its first step in ρ = log r is at most this (a factor e in r); see the objective's scale.
constexpr double kLbfgsFirstStep = 1.0;
// Its objective: the Romberg energy to rel 1e-13, as the reference path's.
constexpr double kLbfgsRombergRelTol = 1e-13;
// Brent's minimiser on J(θ, θ1) over θ1 keeps 40 bits: more than the 26 a smooth minimum's
// location supports in double precision, as Boost allows up to the full 52.
constexpr int kBrentBits = 40;
// Two descents whose ρ agree to this (r to a relative 1e-6) found the same minimum.
constexpr double kSameMinimum = 1e-6;
// The census merges two minima closer than kCensusSameMinimum in ρ, or closer than
// kCensusSameValley with J equal to kCensusSameJ relative: along a flat valley floor two stops of a
// value-based descent can lie 1e-3 apart in ρ at the same J to ten digits, while distinct minima
// (symmetric pairs with equal J included) lie 0.1 or more apart.
constexpr double kCensusSameMinimum = 1e-4;
constexpr double kCensusSameValley = 1e-2;
constexpr double kCensusSameJ = 1e-9;
// Brent along a grid line in the census: 20 bits put the point on a valley floor to 1e-6 of a step.
constexpr int kCensusBrentBits = 20;
// A census descent that stopped short of the gradient test still counts below this |∇J| / (1 + J).
constexpr double kCensusGradient = 1e-6;
inline bool same_census_minimum(double j_a, double rho0_a, double rho1_a, double j_b, double rho0_b, double rho1_b) {
    const double d = std::max(std::abs(rho0_a - rho0_b), std::abs(rho1_a - rho1_b));
    return d < kCensusSameMinimum ||
           (d < kCensusSameValley && std::abs(j_a - j_b) <= kCensusSameJ * (1.0 + std::abs(j_a)));
}
// The independent multistart (local_minima_multistart): BOBYQA to 1e-8 in ρ within the census's
// box, at most 2000 evaluations a start (it needs about 100); the minimum test probes 1e-3 away in
// ρ (J rises there by about 1e-6 · J'' — far above the fast quadrature's 1e-13 noise).
constexpr double kMultistartXtol = 1e-8;
constexpr int kMultistartEvaluations = 2000;
constexpr double kMultistartProbe = 1e-3;
constexpr int kMaxMultistartStarts = 100000;
// The multistart's barrier test samples the segment joining two results at 16 points.
constexpr int kBarrierSamples = 16;
// The census grid's largest side (n² fast energies): 2001² = 4e6, a few seconds a node.
constexpr int kMaxCensusGrid = 2001;

// The census's seeds. J's valleys can be far narrower across than a grid step (at (60°, −60°) a
// minimum at r ≈ (3.0, 0.029) whose J rises by 8 at 0.06 in ρ0 but by 1e-3 along ρ1), so a valley
// floor need not show as a grid minimum. It does show as one-dimensional minima of the grid lines
// it crosses: each is refined by Brent along its line onto the floor, and a refined point lower
// than every refined point of the two neighbouring lines within two steps of it is a seed (the
// floor's own minimum, to a step). Both families of lines, ρ0 = const and ρ1 = const, are used.
template <class ScanEnergy>
std::vector<ScanPoint> census_seeds(const ScanEnergy& j_at, const ScanBox& box, long& evaluations) {
    const int n = box.n;
    const double lo = std::log(box.r_lo), hi = std::log(box.r_hi), step = (hi - lo) / (n - 1);
    const auto rho = [&](int i) { return lo + step * i; };
    std::vector<double> grid(static_cast<std::size_t>(n * n));
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b)
            grid[static_cast<std::size_t>(a * n + b)] = j_at(std::exp(rho(a)), std::exp(rho(b)));
    evaluations += static_cast<long>(n) * n;
    std::vector<ScanPoint> out;
    for (int across = 0; across < 2; ++across) {
        // Line L holds the other coordinate at rho(L); position i along it is rho(i).
        const auto value = [&](int line, int i) {
            return across == 0 ? grid[static_cast<std::size_t>(i * n + line)]
                               : grid[static_cast<std::size_t>(line * n + i)];
        };
        const auto energy = [&](int line, double x) {
            ++evaluations;
            return across == 0 ? j_at(std::exp(x), std::exp(rho(line))) : j_at(std::exp(rho(line)), std::exp(x));
        };
        std::vector<std::vector<std::pair<double, double>>> floor(
            static_cast<std::size_t>(n));  // per line: (x, J) on the floor
        for (int line = 0; line < n; ++line)
            for (int i = 1; i + 1 < n; ++i) {
                const double v = value(line, i);
                if (!std::isfinite(v) || v > value(line, i - 1) || v > value(line, i + 1)) continue;
                const auto [x, j] = boost::math::tools::brent_find_minima([&](double t) { return energy(line, t); },
                                                                          rho(i - 1), rho(i + 1), kCensusBrentBits);
                floor[static_cast<std::size_t>(line)].emplace_back(x, std::min(j, v));
            }
        for (int line = 0; line < n; ++line)
            for (const auto& [x, j] : floor[static_cast<std::size_t>(line)]) {
                bool lowest = true;
                for (int other : {line - 1, line + 1})
                    if (other >= 0 && other < n)
                        for (const auto& [y, k] : floor[static_cast<std::size_t>(other)])
                            lowest = lowest && !(std::abs(y - x) <= 2 * step && k < j);
                if (lowest) out.push_back(across == 0 ? ScanPoint{j, x, rho(line)} : ScanPoint{j, rho(line), x});
            }
    }
    return out;
}

struct Descent {
    double j = kInf, rho0 = 0, rho1 = 0;
    SegmentEnergy energy;
    bool converged = false;
    std::string message;
};

// Newton's method in ρ for ∇J = 0 on the given energy (fast or Romberg): Hessian by central
// differences of the analytic gradient, Levenberg-damped when not positive definite. A step is
// accepted when J decreases, or when J stays within its quadrature noise (1e-13 J) and |∇J|
// decreases — near the minimum a value-based test alone stalls at |∇J| ~ sqrt(noise).
template <class Energy>
Descent newton_descent(const Energy& energy, double rho0, double rho1) {
    Descent d;
    Eigen::Vector2d x(rho0, rho1);
    SegmentEnergy e = energy(x[0], x[1]);
    const double h = kHessianStep;
    const auto grad = [](const SegmentEnergy& s) { return Eigen::Vector2d(s.dj_dlog_r0, s.dj_dlog_r1); };
    for (int it = 0; it < kNewtonIterations; ++it) {
        if (!std::isfinite(e.pseudo_energy)) break;
        const Eigen::Vector2d g = grad(e);
        if (g.norm() <= kGradientAtRounding * (1.0 + e.pseudo_energy)) {
            d.converged = true;
            break;
        }
        Eigen::Matrix2d H;
        for (int k = 0; k < 2; ++k) {
            Eigen::Vector2d xp = x, xm = x;
            xp[k] += h;
            xm[k] -= h;
            H.col(k) = (grad(energy(xp[0], xp[1])) - grad(energy(xm[0], xm[1]))) / (2 * h);
        }
        H = 0.5 * (H + H.transpose()).eval();
        // Levenberg damping: μ = 0 when H is positive definite, grown ×8 on each rejected step
        // (the steps then turn towards steepest descent and shrink) — robust in the long curved
        // valleys J has at small angles, where H is nearly singular.
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(H);
        const double lmin = eig.eigenvalues()[0], lmax = std::abs(eig.eigenvalues()[1]);
        double mu = lmin > 0.0 ? 0.0 : -lmin + kDampingShift * (1.0 + lmax);
        bool accepted = false;
        double step_norm = 0.0;
        for (int tries = 0; tries < kDampingTries && !accepted; ++tries) {
            Eigen::Vector2d step = -(H + mu * Eigen::Matrix2d::Identity()).ldlt().solve(g);
            if (step.norm() > kMaxStep) step *= kMaxStep / step.norm();
            const Eigen::Vector2d xn = x + step;
            if (step.allFinite() && std::abs(xn[0]) < kLogMagnitudeLimit && std::abs(xn[1]) < kLogMagnitudeLimit) {
                const SegmentEnergy en = energy(xn[0], xn[1]);
                const bool lower = en.pseudo_energy < e.pseudo_energy;
                const bool flatter = en.pseudo_energy <= e.pseudo_energy + kEnergyNoise * std::abs(e.pseudo_energy) &&
                                     grad(en).norm() < g.norm();
                if (lower || flatter) {
                    x = xn;
                    e = en;
                    accepted = true;
                    step_norm = step.norm();
                }
            }
            mu = std::max(kDampingGrowth * mu, kDampingFloor * (1.0 + lmax));
        }
        if (!accepted || step_norm < kStepAtRounding) {  // at the rounding floor
            d.converged = grad(e).norm() <= kGradientConverged * (1.0 + e.pseudo_energy);
            break;
        }
    }
    d.converged = d.converged ||
                  (std::isfinite(e.pseudo_energy) && grad(e).norm() <= kGradientConverged * (1.0 + e.pseudo_energy));
    d.rho0 = x[0];
    d.rho1 = x[1];
    d.energy = e;
    d.j = e.pseudo_energy;
    if (!d.converged) d.message = "Newton did not converge (|grad| = " + full_precision(grad(e).norm()) + ")";
    return d;
}

// ---- reference path: Ceres nonlinear conjugate gradients on the Romberg energy --------------

// J of the segment at r = exp(ρ) with its gradient in ρ: energy(r0, r1, with_gradient).
using SegmentEnergyAt = std::function<SegmentEnergy(double r0, double r1, bool with_gradient)>;

#if CAGD_WITH_CERES
class RombergPseudoEnergy final : public ceres::FirstOrderFunction {
public:
    RombergPseudoEnergy(SegmentEnergyAt energy, long* evaluations)
        : energy_(std::move(energy)), evaluations_(evaluations) {}
    bool Evaluate(const double* rho, double* cost, double* gradient) const override {
        if (!(std::abs(rho[0]) < kLogMagnitudeLimit && std::abs(rho[1]) < kLogMagnitudeLimit)) return false;
        const SegmentEnergy e = energy_(std::exp(rho[0]), std::exp(rho[1]), gradient != nullptr);
        ++*evaluations_;
        if (e.cusp || !std::isfinite(e.pseudo_energy)) return false;
        *cost = e.pseudo_energy;
        if (gradient) {
            gradient[0] = e.dj_dlog_r0;
            gradient[1] = e.dj_dlog_r1;
        }
        return true;
    }
    int NumParameters() const override { return 2; }

private:
    SegmentEnergyAt energy_;
    long* evaluations_;
};

// The reference descents from each start: Ceres CG (Polak–Ribière) on the Romberg energy, then
// Newton on ∇J = 0 with the same Romberg gradients — CG's value-based line search stalls at
// |∇J| ~ sqrt(quadrature noise), Newton takes the last digits.
inline std::vector<Descent> reference_descents(const SegmentEnergyAt& romberg, const std::vector<ScanPoint>& starts,
                                               long& evaluations) {
    // Ceres logs a warning each time CG restarts, which nearly converged CG does constantly.
    FLAGS_minloglevel = std::max(FLAGS_minloglevel, 2);
    std::vector<Descent> runs;
    for (const ScanPoint& start : starts) {
        double rho[2] = {start.rho0, start.rho1};
        ceres::GradientProblemSolver::Options o;
        o.line_search_direction_type = ceres::NONLINEAR_CONJUGATE_GRADIENT;
        o.nonlinear_conjugate_gradient_type = ceres::POLAK_RIBIERE;
        o.line_search_type = ceres::WOLFE;
        o.line_search_sufficient_curvature_decrease = 0.1;  // the usual choice for CG
        o.max_num_iterations = kCgIterations;
        o.function_tolerance = kCgFunctionTolerance;
        o.gradient_tolerance = kCgGradientTolerance;
        o.parameter_tolerance = kCgParameterTolerance;
        o.logging_type = ceres::SILENT;
        ceres::GradientProblem problem(new RombergPseudoEnergy(romberg, &evaluations));
        ceres::GradientProblemSolver::Summary summary;
        ceres::Solve(o, problem, rho, &summary);
        const auto romberg_energy = [&](double a, double b) {
            ++evaluations;
            return romberg(std::exp(a), std::exp(b), true);
        };
        Descent d = newton_descent(romberg_energy, rho[0], rho[1]);
        d.message = "Ceres CG: " + summary.message + "; " + d.message;
        runs.push_back(d);
    }
    return runs;
}
#else
// Without Ceres the reference minimisers refuse before they get here (require_built_with).
inline std::vector<Descent> reference_descents(const SegmentEnergyAt&, const std::vector<ScanPoint>&, long&) {
    require_built_with(OptionalDependency::ceres, "cagd::fairness reference minimiser");
    return {};
}
#endif

// The converged descents that reached distinct minima (|Δρ| > kSameMinimum), lowest J first.
inline std::vector<const Descent*> distinct_minima(const std::vector<Descent>& runs) {
    std::vector<const Descent*> distinct;
    for (const Descent& d : runs) {
        if (!d.converged || !std::isfinite(d.j)) continue;
        bool seen = false;
        for (const Descent* e : distinct)
            if (std::abs(e->rho0 - d.rho0) < kSameMinimum && std::abs(e->rho1 - d.rho1) < kSameMinimum) seen = true;
        if (!seen) distinct.push_back(&d);
    }
    std::sort(distinct.begin(), distinct.end(), [](const Descent* a, const Descent* b) { return a->j < b->j; });
    return distinct;
}

// The census's minima among its descents, distinct by same_census_minimum, lowest J first: a
// converged descent, or one that stopped at the rounding floor of a valley too ill-conditioned for
// the gradient test (condition 1e7 at r ~ 1e-3: |∇J| ≈ 1e-7) where |∇J| ≤ kCensusGradient (1 + J)
// and J(ρ) rises at the eight neighbours kMultistartProbe away.
template <class Energy>
std::vector<const Descent*> census_minima(const std::vector<Descent>& runs, const Energy& j_at) {
    std::vector<const Descent*> out;
    for (const Descent& d : runs) {
        if (!std::isfinite(d.j)) continue;
        bool minimum = d.converged;
        if (!minimum && std::hypot(d.energy.dj_dlog_r0, d.energy.dj_dlog_r1) <= kCensusGradient * (1.0 + d.j)) {
            minimum = true;
            for (int a = -1; a <= 1 && minimum; ++a)
                for (int b = -1; b <= 1; ++b)
                    if ((a || b) && j_at(d.rho0 + a * kMultistartProbe, d.rho1 + b * kMultistartProbe) < d.j)
                        minimum = false;
        }
        if (!minimum) continue;
        bool seen = false;
        for (const Descent* e : out) seen = seen || same_census_minimum(e->j, e->rho0, e->rho1, d.j, d.rho0, d.rho1);
        if (!seen) out.push_back(&d);
    }
    std::sort(out.begin(), out.end(), [](const Descent* a, const Descent* b) { return a->j < b->j; });
    return out;
}

// The answer among the descents (planar PseudoEnergyMinimum or its space form): the lowest distinct
// minimum, measured by fill(m, best); the runner-up; no_convergence when no descent converged,
// no_solution when the minimiser runs off towards r = 0 or ∞.
template <class Minimum, class Fill>
Minimum choose_minimum(Minimum m, const std::vector<Descent>& runs, long evaluations, const Fill& fill) {
    m.evaluations = evaluations;
    m.runner_up = kInf;
    const std::vector<const Descent*> distinct = distinct_minima(runs);
    m.local_minima = static_cast<int>(distinct.size());
    if (distinct.empty()) {
        m.type = SegmentType::x;
        m.pseudo_energy = kInf;
        std::string why = runs.empty() ? "the scan found no interior local minimum" : runs.front().message;
        m.outcome = {Status::no_convergence, "no descent converged: " + why};
        return m;
    }
    fill(m, *distinct.front());
    if (distinct.size() > 1) {
        m.runner_up = distinct[1]->j;
        m.runner_up_r0 = std::exp(distinct[1]->rho0);
        m.runner_up_r1 = std::exp(distinct[1]->rho1);
    }
    if (std::min(m.r0, m.r1) < kRunawayLow || std::max(m.r0, m.r1) > kRunawayHigh)
        m.outcome = {Status::no_solution, "minimiser runs off to the boundary of r > 0 (r0 = " + full_precision(m.r0) +
                                              ", r1 = " + full_precision(m.r1) + ")"};
    return m;
}

}  // namespace cagd::fairness::detail
