#include "cagd/fairness/space_pseudo_energy.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "cagd/fairness/detail/pseudo_energy_descent.hpp"
#include "cagd/fairness/detail/segment_quadrature.hpp"

namespace cagd::fairness {

namespace {

using detail::Descent;
using detail::Integrands;
using detail::ScanPoint;

void require_space_angles(const char* who, double theta0, double theta1, double phi) {
    const auto check = [&](double v, const char* name, double hi) {
        if (!(v >= -1e-12 && v <= hi + 1e-12))
            fail_input(who, std::string(name) + " must be a finite angle in [0, " + (hi > 4 ? "2pi" : "pi") +
                                "] (radians), got " + full_precision(v));
    };
    check(theta0, "theta0", std::numbers::pi);
    check(theta1, "theta1", std::numbers::pi);
    check(phi, "phi", 2 * std::numbers::pi);
}

// The six integrands of detail/segment_quadrature.hpp for the space segment: |P'| and
// |w|²/|P'|⁵ with w = P' × P'' (κ²|P'|), and their derivatives with respect to r0, r1:
// ∂P'/∂r0 = c'(t) u0, ∂P''/∂r0 = c''(t) u0, ∂P'/∂r1 = d'(t) u1, ∂P''/∂r1 = d''(t) u1, so
// ∂w/∂r_i = D_i × P'' + P' × D_i' and ∂(|w|²/g^{5/2}) = 2 w·∂w / g^{5/2} − 5 |w|² (P'·D_i) / g^{7/2}.
Integrands space_integrands(const SpaceUnitChordHermite& s, double t, bool with_gradient) {
    const Eigen::Vector3d d1 = s.a() + t * (s.b() + t * s.c());
    const Eigen::Vector3d d2 = s.b() + 2.0 * t * s.c();
    const double g = d1.squaredNorm();
    const double speed = std::sqrt(g);
    const Eigen::Vector3d w = d1.cross(d2);
    const double w2 = w.squaredNorm();
    const double inv5 = 1.0 / (g * g * speed);
    Integrands out{speed, w2 * inv5, 0, 0, 0, 0};
    if (!with_gradient) return out;
    const double dc1 = 1.0 - 4.0 * t + 3.0 * t * t, dc2 = 6.0 * t - 4.0;
    const double dd1 = -2.0 * t + 3.0 * t * t, dd2 = 6.0 * t - 2.0;
    const Eigen::Vector3d D0 = dc1 * s.u0(), D0p = dc2 * s.u0();
    const Eigen::Vector3d D1 = dd1 * s.u1(), D1p = dd2 * s.u1();
    const double p0 = d1.dot(D0), p1 = d1.dot(D1);
    const double w0 = w.dot(D0.cross(d2) + d1.cross(D0p)), w1 = w.dot(D1.cross(d2) + d1.cross(D1p));
    out[2] = p0 / speed;
    out[3] = p1 / speed;
    out[4] = 2.0 * w0 * inv5 - 5.0 * w2 * p0 * inv5 / g;
    out[5] = 2.0 * w1 * inv5 - 5.0 * w2 * p1 * inv5 / g;
    return out;
}

SpacePseudoEnergyMinimum undefined_direction(double theta0, double theta1, double phi) {
    SpacePseudoEnergyMinimum m;
    m.theta0 = theta0;
    m.theta1 = theta1;
    m.phi = phi;
    m.runner_up = detail::kInf;
    const bool straight = std::abs(theta0) < 1e-12 && std::abs(theta1) < 1e-12;
    m.pseudo_energy = m.strain_energy = straight ? 0.0 : detail::kInf;
    m.length = straight ? 1.0 : 0.0;
    m.outcome = {
        Status::no_solution,
        straight
            ? "undefined direction (0, 0): the straight segment has J = 0 and r0, r1 are not determined"
            : "undefined direction: both tangents lie along the chord and every segment has a cusp; no minimum exists"};
    return m;
}

SpacePseudoEnergyMinimum choose_space(double theta0, double theta1, double phi, const std::vector<Descent>& runs,
                                      long evaluations) {
    SpacePseudoEnergyMinimum m;
    m.theta0 = theta0;
    m.theta1 = theta1;
    m.phi = phi;
    return detail::choose_minimum(m, runs, evaluations, [&](SpacePseudoEnergyMinimum& out, const Descent& best) {
        const SpaceUnitChordHermite seg(theta0, theta1, phi, std::exp(best.rho0), std::exp(best.rho1));
        out.r0 = seg.r0();
        out.r1 = seg.r1();
        out.pseudo_energy = best.energy.pseudo_energy;
        out.length = best.energy.length;
        out.strain_energy = best.energy.strain_energy;
        out.type = seg.type();
        out.gradient_norm = std::hypot(best.energy.dj_dlog_r0, best.energy.dj_dlog_r1);
        out.error_estimate = best.energy.error_estimate;
    });
}

auto space_scan_energy(double theta0, double theta1, double phi) {
    return [=](double r0, double r1) {
        return space_segment_energy_fast(SpaceUnitChordHermite(theta0, theta1, phi, r0, r1), false, 8).pseudo_energy;
    };
}

}  // namespace

SpaceUnitChordHermite::SpaceUnitChordHermite(double theta0, double theta1, double phi, double r0, double r1)
    : theta0_(theta0), theta1_(theta1), phi_(phi), r0_(r0), r1_(r1) {
    const char* who = "cagd::fairness::SpaceUnitChordHermite";
    require_space_angles(who, theta0, theta1, phi);
    if (!std::isfinite(r0) || !(r0 > 0.0)) fail_input(who, "r0 must be finite and > 0, got " + full_precision(r0));
    if (!std::isfinite(r1) || !(r1 > 0.0)) fail_input(who, "r1 must be finite and > 0, got " + full_precision(r1));
    // Exact at multiples of π/2, so φ = 0, π give planar segments to the last bit.
    const Eigen::Vector2d c0 = detail::exact_unit_direction(theta0), c1 = detail::exact_unit_direction(theta1),
                          cp = detail::exact_unit_direction(phi);
    u0_ = Eigen::Vector3d(c0.x(), c0.y(), 0.0);
    u1_ = Eigen::Vector3d(c1.x(), c1.y() * cp.x(), c1.y() * cp.y());
    const Eigen::Vector3d e1(1.0, 0.0, 0.0);
    // P' = b'(t) e1 + r0 c'(t) u0 + r1 d'(t) u1 with b' = 6t − 6t², c' = 1 − 4t + 3t², d' = −2t + 3t².
    a_ = r0 * u0_;
    b_ = 6.0 * e1 - 4.0 * r0 * u0_ - 2.0 * r1 * u1_;
    c_ = -6.0 * e1 + 3.0 * r0 * u0_ + 3.0 * r1 * u1_;
}

Eigen::Vector3d SpaceUnitChordHermite::position(double t) const { return t * (a_ + t * (b_ / 2.0 + t * c_ / 3.0)); }
Eigen::Vector3d SpaceUnitChordHermite::first(double t) const { return a_ + t * (b_ + t * c_); }
Eigen::Vector3d SpaceUnitChordHermite::second(double t) const { return b_ + 2.0 * t * c_; }
Eigen::Vector3d SpaceUnitChordHermite::binormal_vector(double t) const { return first(t).cross(second(t)); }
SegmentType SpaceUnitChordHermite::type() const {
    return binormal_vector(0.0).dot(binormal_vector(1.0)) >= 0.0 ? SegmentType::c : SegmentType::s;
}

SegmentEnergy space_segment_energy_reference(const SpaceUnitChordHermite& seg, double rel_tol, bool with_gradient) {
    if (!(rel_tol > 0.0 && rel_tol <= 1e-12))
        fail_input("cagd::fairness::space_segment_energy_reference",
                   "rel_tol must be in (0, 1e-12], got " + full_precision(rel_tol));
    return detail::energy_reference(
        seg, detail::pointwise_integrand([&](double t) { return space_integrands(seg, t, with_gradient); }), rel_tol);
}

SegmentEnergy space_segment_energy_fast(const SpaceUnitChordHermite& seg, bool with_gradient, int rule_nodes) {
    static const numeric::GaussLegendreRule rule20(20), rule8(8);
    if (rule_nodes != 8 && rule_nodes != 20)
        fail_input("cagd::fairness::space_segment_energy_fast",
                   "rule_nodes must be 8 or 20, got " + std::to_string(rule_nodes));
    return detail::energy_fast(
        seg, detail::pointwise_integrand([&](double t) { return space_integrands(seg, t, with_gradient); }),
        rule_nodes == 8 ? rule8 : rule20);
}

// The planar undefined nodes' rule on θ0, θ1 ∈ [0, π] (φ plays no part when both tangents lie on the chord).
bool is_undefined_space_direction(double theta0, double theta1) { return is_undefined_node(theta0, theta1); }

SpacePseudoEnergyMinimum minimize_space_pseudo_energy(double theta0, double theta1, double phi,
                                                      const FastMinimizerOptions& opt) {
    require_space_angles("cagd::fairness::minimize_space_pseudo_energy", theta0, theta1, phi);
    if (is_undefined_space_direction(theta0, theta1)) return undefined_direction(theta0, theta1, phi);
    long evaluations = 0;
    const std::vector<ScanPoint> starts =
        detail::scan_minima(space_scan_energy(theta0, theta1, phi), opt.box, evaluations);
    const auto fast_energy = [&](double a, double b) {
        ++evaluations;
        return space_segment_energy_fast(SpaceUnitChordHermite(theta0, theta1, phi, std::exp(a), std::exp(b)));
    };
    std::vector<Descent> runs;
    for (std::size_t s = 0; s < starts.size() && static_cast<int>(s) < opt.starts; ++s)
        runs.push_back(detail::newton_descent(fast_energy, starts[s].rho0, starts[s].rho1));
    return choose_space(theta0, theta1, phi, runs, evaluations);
}

SpacePseudoEnergyMinimum minimize_space_pseudo_energy_reference(double theta0, double theta1, double phi,
                                                                const ReferenceMinimizerOptions& opt) {
    require_space_angles("cagd::fairness::minimize_space_pseudo_energy_reference", theta0, theta1, phi);
    require_built_with(OptionalDependency::ceres, "cagd::fairness::minimize_space_pseudo_energy_reference");
    if (is_undefined_space_direction(theta0, theta1)) return undefined_direction(theta0, theta1, phi);
    long evaluations = 0;
    std::vector<ScanPoint> starts = detail::scan_minima(space_scan_energy(theta0, theta1, phi), opt.box, evaluations);
    if (static_cast<int>(starts.size()) > opt.starts) starts.resize(static_cast<std::size_t>(opt.starts));
    // As the planar reference: also from the fast path's minimum and runner-up.
    const SpacePseudoEnergyMinimum fast = minimize_space_pseudo_energy(theta0, theta1, phi);
    if (fast.outcome.ok()) starts.push_back({fast.pseudo_energy, std::log(fast.r0), std::log(fast.r1)});
    if (std::isfinite(fast.runner_up) && fast.runner_up_r0 > 0 && fast.runner_up_r1 > 0)
        starts.push_back({fast.runner_up, std::log(fast.runner_up_r0), std::log(fast.runner_up_r1)});
    const double rel_tol = opt.romberg_rel_tol;
    const std::vector<Descent> runs = detail::reference_descents(
        [&](double r0, double r1, bool with_gradient) {
            return space_segment_energy_reference(SpaceUnitChordHermite(theta0, theta1, phi, r0, r1), rel_tol,
                                                  with_gradient);
        },
        starts, evaluations);
    return choose_space(theta0, theta1, phi, runs, evaluations);
}

}  // namespace cagd::fairness
