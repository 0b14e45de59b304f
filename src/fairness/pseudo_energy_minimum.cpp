#include "cagd/fairness/pseudo_energy_minimum.hpp"

#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <glog/logging.h>
#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <numbers>

namespace cagd::fairness {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A descent that ends beyond these has run off towards r = 0 or r = ∞.
constexpr double kRunawayLow = 1e-8, kRunawayHigh = 1e8;

bool is_multiple_of_pi(double theta) { return std::abs(theta) < 1e-12 || std::abs(std::abs(theta) - std::numbers::pi) < 1e-12; }

void require_angles(const char* who, double theta0, double theta1) {
    const std::string w = std::string("cagd::fairness::") + who;
    require_tangent_angle(w.c_str(), theta0, "theta0");
    require_tangent_angle(w.c_str(), theta1, "theta1");
}

PseudoEnergyMinimum undefined_node(double theta0, double theta1) {
    PseudoEnergyMinimum m;
    m.theta0 = theta0;
    m.theta1 = theta1;
    m.type = SegmentType::x;
    m.runner_up = kInf;
    const bool straight = std::abs(theta0) < 1e-12 && std::abs(theta1) < 1e-12;
    m.pseudo_energy = straight ? 0.0 : kInf;
    m.strain_energy = straight ? 0.0 : kInf;
    m.length = straight ? 1.0 : 0.0;
    m.outcome = {Status::no_solution, straight ? "undefined node (0, 0): the straight segment has J = 0 and r0, r1 are not determined (paper §4.1)"
                                               : "undefined node: both tangents are parallel to the chord and point so that every segment has a "
                                                 "cusp; no minimum exists (paper §4.1)"};
    return m;
}

struct ScanPoint {
    double j;
    double rho0, rho1;
};

// Grid-interior local minima of the fast J over the scan box, lowest first.
std::vector<ScanPoint> scan_minima(double theta0, double theta1, const ScanBox& box, long& evaluations) {
    const int n = box.n;
    const double lo = std::log(box.r_lo), hi = std::log(box.r_hi);
    const auto rho = [&](int i) { return lo + (hi - lo) * i / (n - 1); };
    std::vector<double> grid(static_cast<std::size_t>(n * n));
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            const UnitChordHermite seg(theta0, theta1, std::exp(rho(a)), std::exp(rho(b)));
            grid[static_cast<std::size_t>(a * n + b)] = segment_energy_fast(seg, false, 8).pseudo_energy;
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
                    if ((da || db) && x >= 0 && y >= 0 && x < n && y < n && grid[static_cast<std::size_t>(x * n + y)] < v) minimum = false;
                }
            if (minimum) out.push_back({v, rho(a), rho(b)});
        }
    std::sort(out.begin(), out.end(), [](const ScanPoint& p, const ScanPoint& q) { return p.j < q.j; });
    // A narrow diagonal valley need not show as a discrete minimum on a coarse grid: add the
    // lowest grid points lying more than two cells from every seed so far (three of them).
    std::vector<int> order(static_cast<std::size_t>(n * n));
    for (int k = 0; k < n * n; ++k) order[static_cast<std::size_t>(k)] = k;
    std::sort(order.begin(), order.end(), [&](int p, int q) { return grid[static_cast<std::size_t>(p)] < grid[static_cast<std::size_t>(q)]; });
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
        out.erase(std::remove_if(out.begin() + 1, out.end(), [&](const ScanPoint& p) { return p.j > limit; }), out.end());
    }
    return out;
}

// Fills the measures of the segment at (r0, r1).
void fill_measures(PseudoEnergyMinimum& m, double r0, double r1, const SegmentEnergy& e) {
    const UnitChordHermite seg(m.theta0, m.theta1, r0, r1);
    m.r0 = r0;
    m.r1 = r1;
    m.pseudo_energy = e.pseudo_energy;
    m.length = e.length;
    m.strain_energy = e.strain_energy;
    m.area = signed_area(seg);
    m.type = seg.type();
    m.gradient_norm = std::hypot(e.dj_dlog_r0, e.dj_dlog_r1);
    m.error_estimate = e.error_estimate;
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
// Its objective: the Romberg energy to rel 1e-13, as the reference path's (DESIGN.md).
constexpr double kLbfgsRombergRelTol = 1e-13;
// Brent's minimiser on J(θ, θ1) over θ1 keeps 40 bits: more than the 26 a smooth minimum's
// location supports in double precision, as Boost allows up to the full 52.
constexpr int kBrentBits = 40;
// Two descents whose ρ agree to this (r to a relative 1e-6) found the same minimum.
constexpr double kSameMinimum = 1e-6;

struct Descent {
    double j = kInf, rho0 = 0, rho1 = 0;
    SegmentEnergy energy;
    bool converged = false;
    std::string message;
};

// Picks the global answer among descents; counts distinct minima (|Δρ| > kSameMinimum).
PseudoEnergyMinimum choose(double theta0, double theta1, const std::vector<Descent>& runs, long evaluations) {
    PseudoEnergyMinimum m;
    m.theta0 = theta0;
    m.theta1 = theta1;
    m.evaluations = evaluations;
    m.runner_up = kInf;
    std::vector<const Descent*> distinct;
    for (const Descent& d : runs) {
        if (!d.converged || !std::isfinite(d.j)) continue;
        bool seen = false;
        for (const Descent* e : distinct)
            if (std::abs(e->rho0 - d.rho0) < kSameMinimum && std::abs(e->rho1 - d.rho1) < kSameMinimum) seen = true;
        if (!seen) distinct.push_back(&d);
    }
    std::sort(distinct.begin(), distinct.end(), [](const Descent* a, const Descent* b) { return a->j < b->j; });
    m.local_minima = static_cast<int>(distinct.size());
    if (distinct.empty()) {
        m.type = SegmentType::x;
        m.pseudo_energy = kInf;
        std::string why = runs.empty() ? "the scan found no interior local minimum" : runs.front().message;
        m.outcome = {Status::no_convergence, "no descent converged: " + why};
        return m;
    }
    const Descent& best = *distinct.front();
    fill_measures(m, std::exp(best.rho0), std::exp(best.rho1), best.energy);
    if (distinct.size() > 1) {
        m.runner_up = distinct[1]->j;
        m.runner_up_r0 = std::exp(distinct[1]->rho0);
        m.runner_up_r1 = std::exp(distinct[1]->rho1);
    }
    if (std::min(m.r0, m.r1) < kRunawayLow || std::max(m.r0, m.r1) > kRunawayHigh)
        m.outcome = {Status::no_solution, "minimiser runs off to the boundary of r > 0 (r0 = " + full_precision(m.r0) + ", r1 = " + full_precision(m.r1) + ")"};
    return m;
}

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
                const bool flatter = en.pseudo_energy <= e.pseudo_energy + kEnergyNoise * std::abs(e.pseudo_energy) && grad(en).norm() < g.norm();
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
    d.converged = d.converged || (std::isfinite(e.pseudo_energy) && grad(e).norm() <= kGradientConverged * (1.0 + e.pseudo_energy));
    d.rho0 = x[0];
    d.rho1 = x[1];
    d.energy = e;
    d.j = e.pseudo_energy;
    if (!d.converged) d.message = "Newton did not converge (|grad| = " + full_precision(grad(e).norm()) + ")";
    return d;
}

// ---- reference path: Ceres nonlinear conjugate gradients on the Romberg energy --------------

class RombergPseudoEnergy final : public ceres::FirstOrderFunction {
public:
    RombergPseudoEnergy(double theta0, double theta1, double rel_tol, long* evaluations) : theta0_(theta0), theta1_(theta1), rel_tol_(rel_tol), evaluations_(evaluations) {}
    bool Evaluate(const double* rho, double* cost, double* gradient) const override {
        if (!(std::abs(rho[0]) < kLogMagnitudeLimit && std::abs(rho[1]) < kLogMagnitudeLimit)) return false;
        const UnitChordHermite seg(theta0_, theta1_, std::exp(rho[0]), std::exp(rho[1]));
        const SegmentEnergy e = segment_energy_reference(seg, rel_tol_, gradient != nullptr);
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
    double theta0_, theta1_, rel_tol_;
    long* evaluations_;
};

}  // namespace

bool is_undefined_node(double theta0, double theta1) { return is_multiple_of_pi(theta0) && is_multiple_of_pi(theta1); }

PseudoEnergyMinimum minimize_pseudo_energy_reference(double theta0, double theta1, const ReferenceMinimizerOptions& opt) {
    require_angles("minimize_pseudo_energy_reference", theta0, theta1);
    if (is_undefined_node(theta0, theta1)) return undefined_node(theta0, theta1);
    // Ceres logs a warning each time CG restarts, which nearly converged CG does constantly.
    FLAGS_minloglevel = std::max(FLAGS_minloglevel, 2);
    long evaluations = 0;
    std::vector<ScanPoint> starts = scan_minima(theta0, theta1, opt.box, evaluations);
    if (static_cast<int>(starts.size()) > opt.starts) starts.resize(static_cast<std::size_t>(opt.starts));
    // Also descend from the fast path's minimum and runner-up: its finer seeding (extra grid
    // points) reaches narrow valleys the reference scan can miss, so the reference answer is the
    // lowest of both — never a local minimum the fast path has beaten.
    const PseudoEnergyMinimum fast = minimize_pseudo_energy(theta0, theta1);
    if (fast.outcome.ok()) starts.push_back({fast.pseudo_energy, std::log(fast.r0), std::log(fast.r1)});
    if (std::isfinite(fast.runner_up) && fast.runner_up_r0 > 0 && fast.runner_up_r1 > 0)
        starts.push_back({fast.runner_up, std::log(fast.runner_up_r0), std::log(fast.runner_up_r1)});
    std::vector<Descent> runs;
    for (std::size_t s = 0; s < starts.size(); ++s) {
        double rho[2] = {starts[s].rho0, starts[s].rho1};
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
        ceres::GradientProblem problem(new RombergPseudoEnergy(theta0, theta1, opt.romberg_rel_tol, &evaluations));
        ceres::GradientProblemSolver::Summary summary;
        ceres::Solve(o, problem, rho, &summary);
        // CG's value-based line search stalls at |∇J| ~ sqrt(quadrature noise); Newton on ∇J = 0
        // with the same Romberg gradients takes the last digits.
        const auto romberg_energy = [&](double a, double b) {
            ++evaluations;
            return segment_energy_reference(UnitChordHermite(theta0, theta1, std::exp(a), std::exp(b)), opt.romberg_rel_tol);
        };
        Descent d = newton_descent(romberg_energy, rho[0], rho[1]);
        d.message = "Ceres CG: " + summary.message + "; " + d.message;
        runs.push_back(d);
    }
    return choose(theta0, theta1, runs, evaluations);
}

PseudoEnergyMinimum minimize_pseudo_energy_nlopt(double theta0, double theta1, const ScanBox& box) {
    require_angles("minimize_pseudo_energy_nlopt", theta0, theta1);
    if (is_undefined_node(theta0, theta1)) return undefined_node(theta0, theta1);
    long evaluations = 0;
    const std::vector<ScanPoint> starts = scan_minima(theta0, theta1, box, evaluations);
    std::vector<Descent> runs;
    for (std::size_t si = 0; si < starts.size() && si < 6; ++si) {
        // NLopt's L-BFGS (Lukšan) opens with a unit steepest-descent step, Δρ = −∇J, which at a
        // steep seed lands on the bounds, where a Romberg energy costs ~0.6 s. Dividing J by
        // max(1, |∇J(seed)| / kLbfgsFirstStep) bounds that first step to kLbfgsFirstStep in ρ; the
        // quasi-Newton steps after it, ftol_rel and the minimiser do not change with the scale.
        const SegmentEnergy at_seed = segment_energy_reference(UnitChordHermite(theta0, theta1, std::exp(starts[si].rho0), std::exp(starts[si].rho1)), kLbfgsRombergRelTol, true);
        ++evaluations;
        const double scale = std::max(1.0, std::hypot(at_seed.dj_dlog_r0, at_seed.dj_dlog_r1) / kLbfgsFirstStep);
        struct Data {
            double theta0, theta1, scale;
            long* evaluations;
        } data{theta0, theta1, scale, &evaluations};
        nlopt::opt opt(nlopt::LD_LBFGS, 2);
        opt.set_min_objective(
            [](const std::vector<double>& rho, std::vector<double>& grad, void* p) -> double {
                const Data& dd = *static_cast<const Data*>(p);
                ++*dd.evaluations;
                const UnitChordHermite seg(dd.theta0, dd.theta1, std::exp(rho[0]), std::exp(rho[1]));
                const SegmentEnergy e = segment_energy_reference(seg, kLbfgsRombergRelTol, !grad.empty());
                if (!grad.empty()) {
                    grad[0] = e.dj_dlog_r0 / dd.scale;
                    grad[1] = e.dj_dlog_r1 / dd.scale;
                }
                return e.pseudo_energy / dd.scale;
            },
            &data);
        // Bounds r ∈ [1e-4, 1e4]: the minimisers of the 1° grid lie in [0.002, 10]; wider bounds let
        // the line search probe r ~ 1e±8, where each Romberg evaluation costs seconds.
        opt.set_lower_bounds({std::log(1.0 / kLbfgsBound), std::log(1.0 / kLbfgsBound)});
        opt.set_upper_bounds({std::log(kLbfgsBound), std::log(kLbfgsBound)});
        opt.set_ftol_rel(kLbfgsFtolRel);
        opt.set_xtol_rel(kLbfgsXtolRel);
        opt.set_maxeval(kLbfgsEvaluations);
        std::vector<double> x{starts[si].rho0, starts[si].rho1};
        double f = 0.0;
        Descent d;
        try {
            const nlopt::result r = opt.optimize(x, f);
            d.message = "NLopt LD_LBFGS result " + std::to_string(static_cast<int>(r));
        } catch (const nlopt::roundoff_limited&) {
            d.message = "NLopt LD_LBFGS stopped by roundoff (x is its best point)";
        }
        d.rho0 = x[0];
        d.rho1 = x[1];
        d.energy = segment_energy_reference(UnitChordHermite(theta0, theta1, std::exp(x[0]), std::exp(x[1])));
        d.j = d.energy.pseudo_energy;
        d.converged = std::hypot(d.energy.dj_dlog_r0, d.energy.dj_dlog_r1) <= kLbfgsGradient * (1.0 + d.j);
        runs.push_back(d);
    }
    return choose(theta0, theta1, runs, evaluations);
}

PseudoEnergyMinimum minimize_pseudo_energy(double theta0, double theta1, const FastMinimizerOptions& opt, const std::vector<Eigen::Vector2d>& warm) {
    require_angles("minimize_pseudo_energy", theta0, theta1);
    if (is_undefined_node(theta0, theta1)) return undefined_node(theta0, theta1);
    long evaluations = 0;
    const std::vector<ScanPoint> starts = scan_minima(theta0, theta1, opt.box, evaluations);
    const auto fast_energy = [&](double a, double b) {
        ++evaluations;
        return segment_energy_fast(UnitChordHermite(theta0, theta1, std::exp(a), std::exp(b)));
    };
    std::vector<Descent> runs;
    for (std::size_t s = 0; s < starts.size() && static_cast<int>(s) < opt.starts; ++s) runs.push_back(newton_descent(fast_energy, starts[s].rho0, starts[s].rho1));
    for (const Eigen::Vector2d& w : warm)
        if (w[0] > 0 && w[1] > 0) runs.push_back(newton_descent(fast_energy, std::log(w[0]), std::log(w[1])));
    return choose(theta0, theta1, runs, evaluations);
}

PseudoEnergyMinimum measure_segment(double theta0, double theta1, double r0, double r1) {
    const UnitChordHermite seg(theta0, theta1, r0, r1);
    PseudoEnergyMinimum m;
    m.theta0 = theta0;
    m.theta1 = theta1;
    m.runner_up = kInf;
    fill_measures(m, r0, r1, segment_energy_fast(seg));
    return m;
}

AngleMinimum minimize_over_end_angle(double theta, double scan_step) {
    require_angles("minimize_over_end_angle", theta, 0.0);
    const auto j_of = [&](double theta1) {
        const PseudoEnergyMinimum m = minimize_pseudo_energy(theta, theta1);
        if (is_undefined_node(theta, theta1)) return m.pseudo_energy;  // 0 at (0, 0), +∞ elsewhere
        return m.outcome.ok() ? m.pseudo_energy : kInf;
    };
    return minimize_over_end_angle(theta, j_of, scan_step);
}

AngleMinimum minimize_over_end_angle(double theta, const std::function<double(double)>& j_of, double scan_step) {
    require_angles("minimize_over_end_angle", theta, 0.0);
    if (!(scan_step > 0.0 && scan_step <= 0.5)) fail_input("cagd::fairness::minimize_over_end_angle", "scan_step must be in (0, 0.5], got " + full_precision(scan_step));
    const int n = static_cast<int>(std::ceil(2 * std::numbers::pi / scan_step));
    std::vector<double> t(static_cast<std::size_t>(n + 1)), v(static_cast<std::size_t>(n + 1));
    for (int i = 0; i <= n; ++i) {
        t[static_cast<std::size_t>(i)] = -std::numbers::pi + 2 * std::numbers::pi * i / n;
        v[static_cast<std::size_t>(i)] = j_of(t[static_cast<std::size_t>(i)]);
    }
    const auto best = static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin());
    AngleMinimum out;
    out.theta = theta;
    if (!std::isfinite(v[best])) {
        out.outcome = {Status::no_solution, "J(theta, theta1) is undefined for every scanned theta1"};
        return out;
    }
    if (v[best] == 0.0) {  // θ = 0: the straight segment
        out.theta1 = t[best];
        return out;
    }
    const double lo = t[best == 0 ? 0 : best - 1], hi = t[std::min(best + 1, t.size() - 1)];
    const auto r = boost::math::tools::brent_find_minima(j_of, lo, hi, kBrentBits);
    out.theta1 = r.second <= v[best] ? r.first : t[best];
    out.pseudo_energy = std::min(r.second, v[best]);
    return out;
}

}  // namespace cagd::fairness
