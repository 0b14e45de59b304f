#pragma once
// The quadrature of a unit-chord Hermite segment's energies, for any dimension (the plane:
// hermite_segment.cpp; space: space_hermite_segment.cpp). A Segment provides a(), b(), c() (the
// power-form coefficients of P'(t) = A + Bt + Ct²), first(t), second(t), r0(), r1(); an integrand
// function integrand(const double* t, std::size_t m, Integrands* out) gives, at each of m points
// t, the six values |P'|, κ²|P'| (the strain-energy density), and their derivatives with respect
// to r0 and r1 (a batch, so the points of a piece can be evaluated together). Cusp detection and the graded breakpoints
// are those described in hermite_segment.hpp.
#include <algorithm>
#include <array>
#include <boost/container/small_vector.hpp>
#include <boost/container/static_vector.hpp>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <vector>

#include "cagd/fairness/hermite_segment.hpp"
#include "cagd/numeric/gauss_legendre.hpp"
#include "cagd/numeric/romberg.hpp"

namespace cagd::fairness::detail {

constexpr double kCuspSpeed = 1e-13;  // relative to 1 + r0 + r1

// cos/sin that are exact at multiples of π/2 given in floating point (±π, ±π/2, 0), so the
// collinear configurations of §4.1 are collinear to the last bit.
inline Eigen::Vector2d exact_unit_direction(double theta) {
    const double q = theta / (std::numbers::pi / 2);
    const double nearest = std::round(q);
    if (std::abs(q - nearest) < 1e-15 * 4) {
        switch (((static_cast<int>(nearest) % 4) + 4) % 4) {
            case 0: return {1.0, 0.0};
            case 1: return {0.0, 1.0};
            case 2: return {-1.0, 0.0};
            default: return {0.0, -1.0};
        }
    }
    return {std::cos(theta), std::sin(theta)};
}

// The six integrands at t: |P'|, κ²|P'|, and their derivatives with respect to r0, r1.
using Integrands = std::array<double, 6>;

// The quadratures run millions of times in a table build, so their working lists live on the stack:
// at most three monotone pieces of P'·P'' (hence three speed minima), and breakpoints that exceed
// the small buffer only for extreme grading (then on the heap). Same values, same order, as
// std::vector gave.
using SpeedMinimaList = boost::container::static_vector<SpeedMinimum, 3>;
using BreakList = boost::container::small_vector<double, 64>;

template <class Segment>
SpeedMinimaList speed_minima(const Segment& seg) {
    // (|P'|²)'/2 = P'·P'' = q0 + q1 t + q2 t² + q3 t³ (a cubic); its roots where it changes sign
    // from − to + are the minima. The roots of its derivative (a quadratic) split [0, 1] into
    // monotone pieces, each bracketing at most one root, found by bisection to 1 ulp.
    const auto &A = seg.a(), &B = seg.b(), &C = seg.c();
    const double q0 = A.dot(B), q1 = B.dot(B) + 2.0 * A.dot(C), q2 = 3.0 * B.dot(C), q3 = 2.0 * C.dot(C);
    const auto slope = [&](double t) { return q0 + t * (q1 + t * (q2 + t * q3)); };
    std::array<double, 4> cuts{0.0};  // 0, the roots of the quadratic in (0, 1), then 1
    std::size_t n_cuts = 1;
    const double a2 = 3.0 * q3, a1 = 2.0 * q2, a0 = q1;  // derivative of the cubic
    if (a2 != 0.0) {
        const double disc = a1 * a1 - 4.0 * a2 * a0;
        if (disc > 0.0) {
            const double sq = std::sqrt(disc);
            const double qq = -0.5 * (a1 + (a1 >= 0 ? sq : -sq));
            for (double r : {qq / a2, qq != 0.0 ? a0 / qq : -1.0})
                if (r > 0.0 && r < 1.0) cuts[n_cuts++] = r;
        }
    } else if (a1 != 0.0) {
        const double r = -a0 / a1;
        if (r > 0.0 && r < 1.0) cuts[n_cuts++] = r;
    }
    std::sort(cuts.begin(), cuts.begin() + static_cast<std::ptrdiff_t>(n_cuts));
    cuts[n_cuts++] = 1.0;
    SpeedMinimaList out;
    for (std::size_t k = 0; k + 1 < n_cuts; ++k) {
        double lo = cuts[k], hi = cuts[k + 1];
        if (!(slope(lo) < 0.0 && slope(hi) >= 0.0)) continue;
        // Safeguarded Newton: a Newton step that leaves the bracket becomes a bisection.
        const auto dslope = [&](double t) { return a0 + t * (a1 + t * a2); };
        double tm = 0.5 * (lo + hi);
        for (int it = 0; it < 100; ++it) {
            const double f = slope(tm);
            if (f == 0.0) break;
            (f < 0.0 ? lo : hi) = tm;
            const double df = dslope(tm);
            double next = df > 0.0 ? tm - f / df : 0.5 * (lo + hi);
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (std::abs(next - tm) <= 4e-16 * std::max(1.0, std::abs(tm)) || next == lo || next == hi) {
                tm = next;
                break;
            }
            tm = next;
        }
        if (!(tm > 0.0 && tm < 1.0)) continue;
        SpeedMinimum m;
        m.t = tm;
        m.speed = seg.first(tm).norm();
        const double acc = seg.second(tm).norm();
        m.width = acc > 0.0 ? m.speed / acc : 1.0;
        out.push_back(m);
    }
    return out;
}

template <class Segment>
bool cusp_among(const Segment& seg, const SpeedMinimaList& minima) {
    const double floor = kCuspSpeed * (1.0 + seg.r0() + seg.r1());
    for (const SpeedMinimum& m : minima)
        if (m.speed <= floor) return true;
    return false;
}

template <class Segment>
BreakList breaks_for(const Segment& seg, const SpeedMinimaList& minima) {
    BreakList br{0.0, 0.5, 1.0};
    for (const SpeedMinimum& m : minima) {
        if (m.width >= 0.25) continue;
        br.push_back(m.t);
        for (double h = m.width; h < 1.0; h *= 2.0) {
            if (m.t - h > 0.0) br.push_back(m.t - h);
            if (m.t + h < 1.0) br.push_back(m.t + h);
        }
    }
    // A short end tangent (r0 or r1 ≪ |P''|) is a near-cusp at the end itself: grade towards it.
    const double w0 = seg.r0() / std::max(seg.second(0.0).norm(), 1e-300);
    const double w1 = seg.r1() / std::max(seg.second(1.0).norm(), 1e-300);
    for (double h = w0; h < 0.25; h *= 2.0) br.push_back(h);
    for (double h = w1; h < 0.25; h *= 2.0) br.push_back(1.0 - h);
    std::sort(br.begin(), br.end());
    // Drop breakpoints within 1e-15 of the one kept before them, in place.
    std::size_t kept = 0;
    for (std::size_t i = 0; i < br.size(); ++i)
        if (kept == 0 || br[i] - br[kept - 1] > 1e-15) br[kept++] = br[i];
    br.resize(kept);
    if (br.back() != 1.0) br.back() = 1.0;
    return br;
}
// A batch integrand (as above) from one of a point at a time, f(t) → Integrands.
template <class F>
auto pointwise_integrand(F f) {
    return [f](const double* t, std::size_t m, Integrands* out) {
        for (std::size_t i = 0; i < m; ++i) out[i] = f(t[i]);
    };
}

inline SegmentEnergy assemble_energy(double r0, double r1, const Integrands& I, double err_l, double err_e) {
    SegmentEnergy r;
    r.length = I[0];
    r.strain_energy = I[1];
    r.pseudo_energy = I[0] * I[0] * I[1];
    const double dj0 = 2.0 * I[0] * I[2] * I[1] + I[0] * I[0] * I[4];
    const double dj1 = 2.0 * I[0] * I[3] * I[1] + I[0] * I[0] * I[5];
    r.dj_dlog_r0 = r0 * dj0;
    r.dj_dlog_r1 = r1 * dj1;
    r.error_estimate = 2.0 * I[0] * I[1] * err_l + I[0] * I[0] * err_e;
    return r;
}

inline SegmentEnergy cusp_energy() {
    SegmentEnergy r;
    r.cusp = true;
    r.strain_energy = r.pseudo_energy = std::numeric_limits<double>::infinity();
    r.outcome = {Status::no_solution, "segment has a cusp (P'(t) = 0 in [0, 1]): strain energy diverges"};
    return r;
}

// Romberg on the reference energy: 20 levels (10^6 evaluations per piece) reach rel 1e-13 on every
// smooth piece; an absolute tolerance at the underflow edge lets a component that vanishes
// identically (a straight segment) converge at 0 without loosening any other.
constexpr int kRombergLevels = 20;
constexpr double kRombergAbsTol = 1e-300;

// Reference path: Romberg on every piece of breaks_for, rel_tol per integral.
template <class Segment, class Integrand>
SegmentEnergy energy_reference(const Segment& seg, const Integrand& integrand, double rel_tol) {
    const SpeedMinimaList minima = detail::speed_minima(seg);
    if (cusp_among(seg, minima)) return cusp_energy();
    const BreakList br = breaks_for(seg, minima);
    Integrands total{};
    Integrands err{};
    long evaluations = 0;
    Outcome outcome;
    for (std::size_t p = 0; p + 1 < br.size(); ++p) {
        const numeric::RombergVectorResult<6> r =
            numeric::romberg_vector_batched<6>(integrand, br[p], br[p + 1], rel_tol, kRombergAbsTol, kRombergLevels);
        for (std::size_t c = 0; c < 6; ++c) {
            total[c] += r.value[c];
            err[c] += r.error_estimate[c];
        }
        evaluations += r.evaluations;
        if (!r.outcome.ok() && outcome.ok()) outcome = r.outcome;
    }
    SegmentEnergy out = assemble_energy(seg.r0(), seg.r1(), total, err[0], err[1]);
    out.evaluations = evaluations;
    out.outcome = outcome;
    return out;
}

// Fast path: a Gauss–Legendre rule (20 points; 8 for cheap scans) on the same pieces.
inline constexpr int kMaxFastRuleNodes = 20;
template <class Segment, class Integrand>
SegmentEnergy energy_fast(const Segment& seg, const Integrand& integrand, const numeric::GaussLegendreRule& rule) {
    if (rule.size() > kMaxFastRuleNodes)
        fail_input("cagd::fairness::detail::energy_fast", "at most 20 rule nodes, got " + std::to_string(rule.size()));
    const SpeedMinimaList minima = detail::speed_minima(seg);
    if (cusp_among(seg, minima)) return cusp_energy();
    const BreakList br = breaks_for(seg, minima);
    Integrands total{};
    long evaluations = 0;
    for (std::size_t p = 0; p + 1 < br.size(); ++p) {
        const double half = 0.5 * (br[p + 1] - br[p]), mid = 0.5 * (br[p + 1] + br[p]);
        // All nodes of the piece first (independent evaluations), then the sums in node order.
        std::array<double, kMaxFastRuleNodes> t;
        std::array<Integrands, kMaxFastRuleNodes> v;
        for (int i = 0; i < rule.size(); ++i)
            t[static_cast<std::size_t>(i)] = mid + half * rule.nodes()[static_cast<std::size_t>(i)];
        integrand(t.data(), static_cast<std::size_t>(rule.size()), v.data());
        for (int i = 0; i < rule.size(); ++i) {
            const double w = half * rule.weights()[static_cast<std::size_t>(i)];
            for (std::size_t c = 0; c < total.size(); ++c) total[c] += w * v[static_cast<std::size_t>(i)][c];
        }
        evaluations += rule.size();
    }
    SegmentEnergy out = assemble_energy(seg.r0(), seg.r1(), total, 0.0, 0.0);
    out.evaluations = evaluations;
    return out;
}

}  // namespace cagd::fairness::detail
