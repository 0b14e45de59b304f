#include "cagd/fairness/hermite_segment.hpp"

#include "cagd/fairness/detail/segment_quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "cagd/numeric/gauss_legendre.hpp"
#include "cagd/numeric/romberg.hpp"

namespace cagd::fairness {

namespace {

double cross(const Eigen::Vector2d& p, const Eigen::Vector2d& q) { return p.x() * q.y() - p.y() * q.x(); }

using detail::Integrands;

// The six integrands (detail/segment_quadrature.hpp) for the plane at m points t: k²/|P'|⁵ with
// k of eq (15), and |P'|, with their derivatives with respect to r0, r1. Scalar loops over the
// points, so the compiler evaluates two at a time (sqrt and division are exact in every lane);
// each value is computed by the same operations in the same order as the vector form
// d1 = A + t(B + tC), d2 = B + 2tC, k = d2 × d1.
// Points per pass: the values are computed into arrays of this length (structure of arrays, which
// the compiler vectorises), then copied out.
constexpr std::size_t kIntegrandPass = 32;

// P'(t), P''(t), g = |P'|², |P'|, k and 1/|P'|⁵ at t from the power-form coefficients.
struct Derivatives {
    double d1x, d1y, d2x, d2y, g, speed, k, inv5;
};
[[gnu::always_inline]] inline Derivatives derivatives_at(const std::array<double, 6>& abc, double ti) {
    const auto [ax, ay, bx, by, cx, cy] = abc;
    Derivatives d{};
    d.d1x = ax + ti * (bx + ti * cx);
    d.d1y = ay + ti * (by + ti * cy);
    d.d2x = bx + 2.0 * ti * cx;
    d.d2y = by + 2.0 * ti * cy;
    d.g = d.d1x * d.d1x + d.d1y * d.d1y;
    d.speed = std::sqrt(d.g);
    d.k = d.d2x * d.d1y - d.d2y * d.d1x;
    d.inv5 = 1.0 / (d.g * d.g * d.speed);
    return d;
}

void integrands_pass(const UnitChordHermite& s, const double* t, std::size_t m, bool with_gradient, Integrands* out) {
    const std::array<double, 6> abc{s.a().x(), s.a().y(), s.b().x(), s.b().y(), s.c().x(), s.c().y()};
    std::array<std::array<double, kIntegrandPass>, 6> v;
    if (!with_gradient) {
        for (std::size_t i = 0; i < m; ++i) {
            const Derivatives d = derivatives_at(abc, t[i]);
            v[0][i] = d.speed;
            v[1][i] = d.k * d.k * d.inv5;
        }
        for (std::size_t i = 0; i < m; ++i) out[i] = {v[0][i], v[1][i], 0, 0, 0, 0};
        return;
    }
    const double u0x = s.u0().x(), u0y = s.u0().y(), u1x = s.u1().x(), u1y = s.u1().y();
    for (std::size_t i = 0; i < m; ++i) {
        const double ti = t[i];
        const Derivatives d = derivatives_at(abc, ti);
        // ∂P'/∂r0 = c'(t) u0, ∂P''/∂r0 = c''(t) u0;  ∂P'/∂r1 = d'(t) u1, ∂P''/∂r1 = d''(t) u1.
        const double dc1 = 1.0 - 4.0 * ti + 3.0 * ti * ti, dc2 = 6.0 * ti - 4.0;
        const double dd1 = -2.0 * ti + 3.0 * ti * ti, dd2 = 6.0 * ti - 2.0;
        const double D0x = dc1 * u0x, D0y = dc1 * u0y, D0px = dc2 * u0x, D0py = dc2 * u0y;
        const double D1x = dd1 * u1x, D1y = dd1 * u1y, D1px = dd2 * u1x, D1py = dd2 * u1y;
        const double p0 = d.d1x * D0x + d.d1y * D0y, p1 = d.d1x * D1x + d.d1y * D1y;
        const double k0 = (D0px * d.d1y - D0py * d.d1x) + (d.d2x * D0y - d.d2y * D0x);
        const double k1 = (D1px * d.d1y - D1py * d.d1x) + (d.d2x * D1y - d.d2y * D1x);
        v[0][i] = d.speed;
        v[1][i] = d.k * d.k * d.inv5;
        v[2][i] = p0 / d.speed;
        v[3][i] = p1 / d.speed;
        v[4][i] = 2.0 * d.k * k0 * d.inv5 - 5.0 * d.k * d.k * p0 * d.inv5 / d.g;
        v[5][i] = 2.0 * d.k * k1 * d.inv5 - 5.0 * d.k * d.k * p1 * d.inv5 / d.g;
    }
    for (std::size_t i = 0; i < m; ++i) out[i] = {v[0][i], v[1][i], v[2][i], v[3][i], v[4][i], v[5][i]};
}

void integrands(const UnitChordHermite& s, const double* t, std::size_t m, bool with_gradient, Integrands* out) {
    for (std::size_t i0 = 0; i0 < m; i0 += kIntegrandPass)
        integrands_pass(s, t + i0, std::min(kIntegrandPass, m - i0), with_gradient, out + i0);
}

}  // namespace

const char* to_string(SegmentType t) {
    switch (t) {
        case SegmentType::c: return "c";
        case SegmentType::s: return "s";
        default: return "x";
    }
}

double wrap_angle_out_of_range(double theta) {
    // Fast path (differences of two wrapped angles, the common case): one shift by 2π.
    if (theta > std::numbers::pi && theta <= 3.0 * std::numbers::pi) {
        const double w = theta - 2.0 * std::numbers::pi;
        if (w > -std::numbers::pi) return w;
    }
    if (theta <= -std::numbers::pi && theta > -3.0 * std::numbers::pi) {
        const double w = theta + 2.0 * std::numbers::pi;
        if (w <= std::numbers::pi && w > -std::numbers::pi) return w;
    }
    if (!std::isfinite(theta))
        fail_input("cagd::fairness::wrap_angle", "angle must be finite, got " + full_precision(theta));
    double w = std::remainder(theta, 2.0 * std::numbers::pi);  // in [−π, π]
    if (w <= -std::numbers::pi) w += 2.0 * std::numbers::pi;
    return w;
}

void fail_tangent_angle(const char* who, double theta, const char* name) {
    fail_input(who, std::string(name) + " must be a finite angle in [-pi, pi] (radians), got " + full_precision(theta));
}

UnitChordHermite::UnitChordHermite(double theta0, double theta1, double r0, double r1)
    : theta0_(theta0), theta1_(theta1), r0_(r0), r1_(r1) {
    const char* who = "cagd::fairness::UnitChordHermite";
    require_tangent_angle(who, theta0, "theta0");
    require_tangent_angle(who, theta1, "theta1");
    if (!std::isfinite(r0) || !(r0 > 0.0)) fail_input(who, "r0 must be finite and > 0, got " + full_precision(r0));
    if (!std::isfinite(r1) || !(r1 > 0.0)) fail_input(who, "r1 must be finite and > 0, got " + full_precision(r1));
    u0_ = detail::exact_unit_direction(theta0);
    u1_ = detail::exact_unit_direction(theta1);
    const Eigen::Vector2d e1(1.0, 0.0);
    // P' = b'(t) e1 + r0 c'(t) u0 + r1 d'(t) u1 with b' = 6t − 6t², c' = 1 − 4t + 3t², d' = −2t + 3t².
    a_ = r0 * u0_;
    b_ = 6.0 * e1 - 4.0 * r0 * u0_ - 2.0 * r1 * u1_;
    c_ = -6.0 * e1 + 3.0 * r0 * u0_ + 3.0 * r1 * u1_;
}

Eigen::Vector2d UnitChordHermite::position(double t) const { return t * (a_ + t * (b_ / 2.0 + t * c_ / 3.0)); }
Eigen::Vector2d UnitChordHermite::first(double t) const { return a_ + t * (b_ + t * c_); }
Eigen::Vector2d UnitChordHermite::second(double t) const { return b_ + 2.0 * t * c_; }
double UnitChordHermite::curvature_numerator(double t) const { return cross(second(t), first(t)); }

SegmentType UnitChordHermite::type() const {
    return curvature_numerator(0.0) * curvature_numerator(1.0) >= 0.0 ? SegmentType::c : SegmentType::s;
}

BezierCurve UnitChordHermite::bezier() const {
    Eigen::MatrixXd cp(4, 2);
    cp.row(0) << 0.0, 0.0;
    cp.row(1) = (r0_ * u0_ / 3.0).transpose();
    cp.row(2) = (Eigen::Vector2d(1.0, 0.0) - r1_ * u1_ / 3.0).transpose();
    cp.row(3) << 1.0, 0.0;
    return BezierCurve(cp, 0.0, 1.0);
}

std::vector<SpeedMinimum> speed_minima(const UnitChordHermite& seg) {
    const detail::SpeedMinimaList m = detail::speed_minima(seg);
    return {m.begin(), m.end()};
}

bool has_cusp(const UnitChordHermite& seg) { return detail::cusp_among(seg, detail::speed_minima(seg)); }

std::vector<double> integration_breaks(const UnitChordHermite& seg) {
    const detail::BreakList br = detail::breaks_for(seg, detail::speed_minima(seg));
    return {br.begin(), br.end()};
}

SegmentEnergy segment_energy_reference(const UnitChordHermite& seg, double rel_tol, bool with_gradient) {
    if (!(rel_tol > 0.0 && rel_tol <= 1e-12))
        fail_input("cagd::fairness::segment_energy_reference",
                   "rel_tol must be in (0, 1e-12], got " + full_precision(rel_tol));
    return detail::energy_reference(
        seg, [&](const double* t, std::size_t m, Integrands* out) { integrands(seg, t, m, with_gradient, out); },
        rel_tol);
}

SegmentEnergy segment_energy_fast(const UnitChordHermite& seg, bool with_gradient, int rule_nodes) {
    static const numeric::GaussLegendreRule rule20(20), rule8(8);
    if (rule_nodes != 8 && rule_nodes != 20)
        fail_input("cagd::fairness::segment_energy_fast",
                   "rule_nodes must be 8 or 20, got " + std::to_string(rule_nodes));
    return detail::energy_fast(
        seg, [&](const double* t, std::size_t m, Integrands* out) { integrands(seg, t, m, with_gradient, out); },
        rule_nodes == 8 ? rule8 : rule20);
}

double signed_area(const UnitChordHermite& seg) {
    // y(t) x'(t) has degree 5: a 3-point Gauss–Legendre rule is exact.
    static const numeric::GaussLegendreRule rule(3);
    double s = 0.0;
    for (int i = 0; i < rule.size(); ++i) {
        const double t = 0.5 + 0.5 * rule.nodes()[i];
        s += 0.5 * rule.weights()[i] * seg.position(t).y() * seg.first(t).x();
    }
    return s;
}

}  // namespace cagd::fairness
