#include "cagd/fairness/pseudo_energy_minimum.hpp"

#include "cagd/fairness/detail/pseudo_energy_descent.hpp"

#include <algorithm>
#include <array>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <limits>
#if CAGD_WITH_NLOPT
#include <nlopt.hpp>
#endif
#include <numbers>
#include <random>

namespace cagd::fairness {

namespace {

using namespace detail;

bool is_multiple_of_pi(double theta) {
    return std::abs(theta) < 1e-12 || std::abs(std::abs(theta) - std::numbers::pi) < 1e-12;
}

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
    m.outcome = {
        Status::no_solution,
        straight ? "undefined node (0, 0): the straight segment has J = 0 and r0, r1 are not determined (paper §4.1)"
                 : "undefined node: both tangents are parallel to the chord and point so that every segment has a "
                   "cusp; no minimum exists (paper §4.1)"};
    return m;
}

// The scan's cheap energy of the planar segment (θ0, θ1) at (r0, r1).
auto planar_scan_energy(double theta0, double theta1) {
    return [=](double r0, double r1) {
        return segment_energy_fast(UnitChordHermite(theta0, theta1, r0, r1), false, 8).pseudo_energy;
    };
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

// Picks the global answer among descents; counts distinct minima (|Δρ| > kSameMinimum).
PseudoEnergyMinimum choose(double theta0, double theta1, const std::vector<Descent>& runs, long evaluations) {
    PseudoEnergyMinimum m;
    m.theta0 = theta0;
    m.theta1 = theta1;
    return choose_minimum(m, runs, evaluations, [&](PseudoEnergyMinimum& out, const Descent& best) {
        fill_measures(out, std::exp(best.rho0), std::exp(best.rho1), best.energy);
    });
}

}  // namespace

bool is_undefined_node(double theta0, double theta1) { return is_multiple_of_pi(theta0) && is_multiple_of_pi(theta1); }

PseudoEnergyMinimum minimize_pseudo_energy_reference(double theta0, double theta1,
                                                     const ReferenceMinimizerOptions& opt) {
    require_angles("minimize_pseudo_energy_reference", theta0, theta1);
    require_built_with(OptionalDependency::ceres, "cagd::fairness::minimize_pseudo_energy_reference");
    if (is_undefined_node(theta0, theta1)) return undefined_node(theta0, theta1);
    long evaluations = 0;
    std::vector<ScanPoint> starts = scan_minima(planar_scan_energy(theta0, theta1), opt.box, evaluations);
    if (static_cast<int>(starts.size()) > opt.starts) starts.resize(static_cast<std::size_t>(opt.starts));
    // Also descend from the fast path's minimum and runner-up: its finer seeding (extra grid
    // points) reaches narrow valleys the reference scan can miss, so the reference answer is the
    // lowest of both — never a local minimum the fast path has beaten.
    const PseudoEnergyMinimum fast = minimize_pseudo_energy(theta0, theta1);
    if (fast.outcome.ok()) starts.push_back({fast.pseudo_energy, std::log(fast.r0), std::log(fast.r1)});
    if (std::isfinite(fast.runner_up) && fast.runner_up_r0 > 0 && fast.runner_up_r1 > 0)
        starts.push_back({fast.runner_up, std::log(fast.runner_up_r0), std::log(fast.runner_up_r1)});
    // The census: a distinct minimum it reaches that is lower than the fast path's global one
    // becomes a start (its reference descent polishes it); the others enter the count and the
    // runner-up below with their fast-energy values, which is all those need (a Romberg descent
    // from each would multiply the table's cost).
    std::vector<Descent> census;
    std::vector<const Descent*> census_found;
    if (opt.census.n > 1) {
        const auto fast_energy = [&](double a, double b) {
            ++evaluations;
            return segment_energy_fast(UnitChordHermite(theta0, theta1, std::exp(a), std::exp(b)));
        };
        for (const ScanPoint& seed : census_seeds(planar_scan_energy(theta0, theta1), opt.census, evaluations))
            census.push_back(newton_descent(fast_energy, seed.rho0, seed.rho1));
        census_found = census_minima(census, [&](double a, double b) { return fast_energy(a, b).pseudo_energy; });
        for (const Descent* d : census_found) {
            if (fast.outcome.ok() && !(d->j < fast.pseudo_energy - kCensusSameJ * (1.0 + fast.pseudo_energy))) continue;
            bool near = false;
            for (const ScanPoint& s : starts)
                near = near || same_census_minimum(s.j, s.rho0, s.rho1, d->j, d->rho0, d->rho1);
            if (!near) starts.push_back({d->j, d->rho0, d->rho1});
        }
    }
    const double rel_tol = opt.romberg_rel_tol;
    const std::vector<Descent> runs = reference_descents(
        [&](double r0, double r1, bool with_gradient) {
            return segment_energy_reference(UnitChordHermite(theta0, theta1, r0, r1), rel_tol, with_gradient);
        },
        starts, evaluations);
    PseudoEnergyMinimum m = choose(theta0, theta1, runs, evaluations);
    if (census.empty() || !m.outcome.ok()) return m;
    // The count and the runner-up over every distinct minimum reached: the reference descents
    // first, then census minima whose reference descent did not meet its gradient test (in the
    // valleys of condition 1e7 at r ~ 1e-3 |∇J| stays near 1e-7): minima of the fast energy all the same.
    std::vector<const Descent*> all = distinct_minima(runs);
    for (const Descent* d : census_found) {
        bool seen = false;
        for (const Descent* e : all) seen = seen || same_census_minimum(e->j, e->rho0, e->rho1, d->j, d->rho0, d->rho1);
        if (!seen) all.push_back(d);
    }
    std::vector<const Descent*> others;
    for (const Descent* d : all)
        if (!same_census_minimum(d->j, d->rho0, d->rho1, m.pseudo_energy, std::log(m.r0), std::log(m.r1)))
            others.push_back(d);
    std::sort(others.begin(), others.end(), [](const Descent* a, const Descent* b) { return a->j < b->j; });
    m.local_minima = static_cast<int>(others.size()) + 1;
    m.runner_up = others.empty() ? kInf : others.front()->j;
    m.runner_up_r0 = others.empty() ? 0.0 : std::exp(others.front()->rho0);
    m.runner_up_r1 = others.empty() ? 0.0 : std::exp(others.front()->rho1);
    return m;
}

PseudoEnergyMinimum minimize_pseudo_energy_nlopt(double theta0, double theta1, const ScanBox& box) {
    require_angles("minimize_pseudo_energy_nlopt", theta0, theta1);
    require_built_with(OptionalDependency::nlopt, "cagd::fairness::minimize_pseudo_energy_nlopt");
#if CAGD_WITH_NLOPT
    if (is_undefined_node(theta0, theta1)) return undefined_node(theta0, theta1);
    long evaluations = 0;
    const std::vector<ScanPoint> starts = scan_minima(planar_scan_energy(theta0, theta1), box, evaluations);
    std::vector<Descent> runs;
    for (std::size_t si = 0; si < starts.size() && si < 6; ++si) {
        // NLopt's L-BFGS (Lukšan) opens with a unit steepest-descent step, Δρ = −∇J, which at a
        // steep seed lands on the bounds, where a Romberg energy costs ~0.6 s. Dividing J by
        // max(1, |∇J(seed)| / kLbfgsFirstStep) bounds that first step to kLbfgsFirstStep in ρ; the
        // quasi-Newton steps after it, ftol_rel and the minimiser do not change with the scale.
        const SegmentEnergy at_seed = segment_energy_reference(
            UnitChordHermite(theta0, theta1, std::exp(starts[si].rho0), std::exp(starts[si].rho1)), kLbfgsRombergRelTol,
            true);
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
#else
    (void)box;
    return {};
#endif
}

std::vector<LocalMinimum> local_minima_census(double theta0, double theta1, const ScanBox& box) {
    const char* who = "cagd::fairness::local_minima_census";
    require_angles("local_minima_census", theta0, theta1);
    if (!(box.r_lo > 0 && box.r_hi > box.r_lo && std::isfinite(box.r_hi)) || box.n < 3 || box.n > kMaxCensusGrid)
        fail_input(who, "the box [" + full_precision(box.r_lo) + ", " + full_precision(box.r_hi) +
                            "] with n = " + std::to_string(box.n) +
                            " must satisfy 0 < r_lo < r_hi < inf and 3 <= n <= " + std::to_string(kMaxCensusGrid));
    std::vector<LocalMinimum> out;
    if (is_undefined_node(theta0, theta1)) return out;
    long evaluations = 0;
    const auto fast_energy = [&](double a, double b) {
        return segment_energy_fast(UnitChordHermite(theta0, theta1, std::exp(a), std::exp(b)));
    };
    std::vector<Descent> runs;
    for (const ScanPoint& seed : census_seeds(planar_scan_energy(theta0, theta1), box, evaluations))
        runs.push_back(newton_descent(fast_energy, seed.rho0, seed.rho1));
    for (const Descent* d : census_minima(runs, [&](double a, double b) { return fast_energy(a, b).pseudo_energy; }))
        out.push_back({d->j, std::exp(d->rho0), std::exp(d->rho1)});
    return out;
}

std::vector<LocalMinimum> local_minima_multistart(double theta0, double theta1, int starts, const ScanBox& box,
                                                  unsigned seed) {
    const char* who = "cagd::fairness::local_minima_multistart";
    require_angles("local_minima_multistart", theta0, theta1);
    require_built_with(OptionalDependency::nlopt, who);
#if CAGD_WITH_NLOPT
    if (starts < 1 || starts > kMaxMultistartStarts)
        fail_input(who, "starts = " + std::to_string(starts) + "; allowed 1.." + std::to_string(kMaxMultistartStarts));
    if (!(box.r_lo > 0 && box.r_hi > box.r_lo && std::isfinite(box.r_hi)))
        fail_input(who, "the box [" + full_precision(box.r_lo) + ", " + full_precision(box.r_hi) +
                            "] must satisfy 0 < r_lo < r_hi < inf");
    std::vector<LocalMinimum> out;
    if (is_undefined_node(theta0, theta1)) return out;
    const auto j_at = [&](double rho0, double rho1) {
        const UnitChordHermite seg(theta0, theta1, std::exp(rho0), std::exp(rho1));
        const double j = segment_energy_fast(seg).pseudo_energy;
        return std::isfinite(j) ? j : kInf;
    };
    struct Data {
        const decltype(j_at)* f;
    } data{&j_at};
    const double lo = std::log(box.r_lo), hi = std::log(box.r_hi);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(lo, hi);
    std::vector<std::array<double, 3>> found;  // (J, ρ0, ρ1)
    for (int k = 0; k < starts; ++k) {
        nlopt::opt o(nlopt::LN_BOBYQA, 2);
        o.set_min_objective([](const std::vector<double>& x, std::vector<double>&,
                               void* p) { return (*static_cast<Data*>(p)->f)(x[0], x[1]); },
                            &data);
        o.set_lower_bounds({lo, lo});
        o.set_upper_bounds({hi, hi});
        o.set_xtol_abs(kMultistartXtol);
        o.set_maxeval(kMultistartEvaluations);
        std::vector<double> x{U(rng), U(rng)};
        double f = 0.0;
        try {
            o.optimize(x, f);
        } catch (const std::exception&) {
            continue;  // NLopt's roundoff stop: the start is dropped, others cover its basin
        }
        if (!std::isfinite(f) || x[0] <= lo + kMultistartXtol || x[0] >= hi - kMultistartXtol ||
            x[1] <= lo + kMultistartXtol || x[1] >= hi - kMultistartXtol)
            continue;         // on the bound: not an interior minimum
        bool minimum = true;  // J does not decrease at the eight neighbours
        for (int da = -1; da <= 1 && minimum; ++da)
            for (int db = -1; db <= 1; ++db)
                if ((da || db) && j_at(x[0] + da * kMultistartProbe, x[1] + db * kMultistartProbe) < f) minimum = false;
        if (!minimum) continue;
        // The same minimum: close in ρ with no barrier between (J on the joining segment never above
        // the higher end by more than kCensusSameJ relative).
        const auto same_basin = [&](const std::array<double, 3>& m) {
            if (std::max(std::abs(m[1] - x[0]), std::abs(m[2] - x[1])) >= kCensusSameValley) return false;
            const double top = std::max(m[0], f) + kCensusSameJ * (1.0 + std::max(m[0], f));
            for (int s = 1; s < kBarrierSamples; ++s) {
                const double t = static_cast<double>(s) / kBarrierSamples;
                if (j_at(m[1] + t * (x[0] - m[1]), m[2] + t * (x[1] - m[2])) > top) return false;
            }
            return true;
        };
        bool seen = false;
        for (auto& m : found)
            if (same_basin(m)) {
                seen = true;
                if (f < m[0]) m = {f, x[0], x[1]};
            }
        if (!seen) found.push_back({f, x[0], x[1]});
    }
    std::sort(found.begin(), found.end());
    for (const auto& m : found) out.push_back({m[0], std::exp(m[1]), std::exp(m[2])});
    return out;
#else
    (void)starts, (void)box, (void)seed;
    return {};
#endif
}

PseudoEnergyMinimum minimize_pseudo_energy(double theta0, double theta1, const FastMinimizerOptions& opt,
                                           const std::vector<Eigen::Vector2d>& warm) {
    require_angles("minimize_pseudo_energy", theta0, theta1);
    if (is_undefined_node(theta0, theta1)) return undefined_node(theta0, theta1);
    long evaluations = 0;
    const std::vector<ScanPoint> starts = scan_minima(planar_scan_energy(theta0, theta1), opt.box, evaluations);
    const auto fast_energy = [&](double a, double b) {
        ++evaluations;
        return segment_energy_fast(UnitChordHermite(theta0, theta1, std::exp(a), std::exp(b)));
    };
    std::vector<Descent> runs;
    for (std::size_t s = 0; s < starts.size() && static_cast<int>(s) < opt.starts; ++s)
        runs.push_back(newton_descent(fast_energy, starts[s].rho0, starts[s].rho1));
    for (const Eigen::Vector2d& w : warm)
        if (w[0] > 0 && w[1] > 0) runs.push_back(newton_descent(fast_energy, std::log(w[0]), std::log(w[1])));
    return choose(theta0, theta1, runs, evaluations);
}

PseudoEnergyMinimum measure_segment(double theta0, double theta1, double r0, double r1) {
    const char* who = "cagd::fairness::measure_segment";
    if (r0 > kMaxSegmentMagnitude) fail_input(who, "r0 = " + full_precision(r0) + "; allowed (0, 1e60]");
    if (r1 > kMaxSegmentMagnitude) fail_input(who, "r1 = " + full_precision(r1) + "; allowed (0, 1e60]");
    const UnitChordHermite seg(theta0, theta1, r0, r1);
    PseudoEnergyMinimum m;
    m.theta0 = theta0;
    m.theta1 = theta1;
    m.runner_up = kInf;
    fill_measures(m, r0, r1, segment_energy_fast(seg));
    for (const double v : {m.pseudo_energy, m.length, m.strain_energy, m.area, m.gradient_norm, m.error_estimate})
        if (!std::isfinite(v)) {
            m.outcome = Outcome{Status::not_representable, "the measures of (r0, r1) = (" + full_precision(r0) + ", " +
                                                               full_precision(r1) + ") overflow double precision"};
            break;
        }
    return m;
}

double end_angle_energy(const PseudoEnergyMinimum& m) {
    if (is_undefined_node(m.theta0, m.theta1)) return m.pseudo_energy;  // 0 at (0, 0), +∞ elsewhere
    return m.outcome.ok() ? m.pseudo_energy : kInf;
}

double end_angle_energy(double theta, double theta1) { return end_angle_energy(minimize_pseudo_energy(theta, theta1)); }

AngleMinimum minimize_over_end_angle(double theta, double scan_step) {
    require_angles("minimize_over_end_angle", theta, 0.0);
    const auto j_of = [&](double theta1) { return end_angle_energy(theta, theta1); };
    return minimize_over_end_angle(theta, j_of, scan_step);
}

AngleMinimum minimize_over_end_angle(double theta, const std::function<double(double)>& j_of, double scan_step) {
    require_angles("minimize_over_end_angle", theta, 0.0);
    if (!(scan_step > 0.0 && scan_step <= 0.5))
        fail_input("cagd::fairness::minimize_over_end_angle",
                   "scan_step must be in (0, 0.5], got " + full_precision(scan_step));
    const int n = static_cast<int>(std::ceil(2 * std::numbers::pi / scan_step));
    std::vector<double> t(static_cast<std::size_t>(n + 1)), v(static_cast<std::size_t>(n + 1));
    for (int i = 0; i <= n; ++i) {
        t[static_cast<std::size_t>(i)] = -std::numbers::pi + 2 * std::numbers::pi * i / n;
        v[static_cast<std::size_t>(i)] = j_of(t[static_cast<std::size_t>(i)]);
    }
    return refine_end_angle_scan(theta, t, v, j_of);
}

AngleMinimum refine_end_angle_scan(double theta, const std::vector<double>& t, const std::vector<double>& v,
                                   const std::function<double(double)>& j_of) {
    if (t.size() < 2 || t.size() != v.size())
        fail_input("cagd::fairness::refine_end_angle_scan", "needs >= 2 scan angles with one J each");
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
