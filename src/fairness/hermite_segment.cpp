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

// The six integrands at t (detail/segment_quadrature.hpp) for the plane: k²/|P'|⁵ with k of eq (15).
Integrands integrands(const UnitChordHermite& s, double t, bool with_gradient) {
    const Eigen::Vector2d d1 = s.a() + t * (s.b() + t * s.c());
    const Eigen::Vector2d d2 = s.b() + 2.0 * t * s.c();
    const double g = d1.squaredNorm();
    const double speed = std::sqrt(g);
    const double k = cross(d2, d1);
    const double inv5 = 1.0 / (g * g * speed);
    Integrands out{speed, k * k * inv5, 0, 0, 0, 0};
    if (!with_gradient) return out;
    // ∂P'/∂r0 = c'(t) u0, ∂P''/∂r0 = c''(t) u0;  ∂P'/∂r1 = d'(t) u1, ∂P''/∂r1 = d''(t) u1.
    const double dc1 = 1.0 - 4.0 * t + 3.0 * t * t, dc2 = 6.0 * t - 4.0;
    const double dd1 = -2.0 * t + 3.0 * t * t, dd2 = 6.0 * t - 2.0;
    const Eigen::Vector2d D0 = dc1 * s.u0(), D0p = dc2 * s.u0();
    const Eigen::Vector2d D1 = dd1 * s.u1(), D1p = dd2 * s.u1();
    const double p0 = d1.dot(D0), p1 = d1.dot(D1);
    const double k0 = cross(D0p, d1) + cross(d2, D0), k1 = cross(D1p, d1) + cross(d2, D1);
    out[2] = p0 / speed;
    out[3] = p1 / speed;
    out[4] = 2.0 * k * k0 * inv5 - 5.0 * k * k * p0 * inv5 / g;
    out[5] = 2.0 * k * k1 * inv5 - 5.0 * k * k * p1 * inv5 / g;
    return out;
}

}  // namespace

const char* to_string(SegmentType t) {
    switch (t) {
        case SegmentType::c: return "c";
        case SegmentType::s: return "s";
        default: return "x";
    }
}

double wrap_angle(double theta) {
    // Fast path (differences of two wrapped angles, the common case): one shift by 2π.
    if (theta > -std::numbers::pi && theta <= std::numbers::pi) return theta;
    if (theta > std::numbers::pi && theta <= 3.0 * std::numbers::pi) {
        const double w = theta - 2.0 * std::numbers::pi;
        if (w > -std::numbers::pi) return w;
    }
    if (theta <= -std::numbers::pi && theta > -3.0 * std::numbers::pi) {
        const double w = theta + 2.0 * std::numbers::pi;
        if (w <= std::numbers::pi && w > -std::numbers::pi) return w;
    }
    if (!std::isfinite(theta)) fail_input("cagd::fairness::wrap_angle", "angle must be finite, got " + full_precision(theta));
    double w = std::remainder(theta, 2.0 * std::numbers::pi);  // in [−π, π]
    if (w <= -std::numbers::pi) w += 2.0 * std::numbers::pi;
    return w;
}

void fail_tangent_angle(const char* who, double theta, const char* name) {
    fail_input(who, std::string(name) + " must be a finite angle in [-pi, pi] (radians), got " + full_precision(theta));
}

UnitChordHermite::UnitChordHermite(double theta0, double theta1, double r0, double r1) : theta0_(theta0), theta1_(theta1), r0_(r0), r1_(r1) {
    const std::string who = "cagd::fairness::UnitChordHermite";
    require_tangent_angle(who.c_str(), theta0, "theta0");
    require_tangent_angle(who.c_str(), theta1, "theta1");
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

SegmentType UnitChordHermite::type() const { return curvature_numerator(0.0) * curvature_numerator(1.0) >= 0.0 ? SegmentType::c : SegmentType::s; }

BezierCurve UnitChordHermite::bezier() const {
    Eigen::MatrixXd cp(4, 2);
    cp.row(0) << 0.0, 0.0;
    cp.row(1) = (r0_ * u0_ / 3.0).transpose();
    cp.row(2) = (Eigen::Vector2d(1.0, 0.0) - r1_ * u1_ / 3.0).transpose();
    cp.row(3) << 1.0, 0.0;
    return BezierCurve(cp, 0.0, 1.0);
}

std::vector<SpeedMinimum> speed_minima(const UnitChordHermite& seg) { return detail::speed_minima(seg); }

bool has_cusp(const UnitChordHermite& seg) { return detail::cusp_among(seg, speed_minima(seg)); }

std::vector<double> integration_breaks(const UnitChordHermite& seg) { return detail::breaks_for(seg, speed_minima(seg)); }

SegmentEnergy segment_energy_reference(const UnitChordHermite& seg, double rel_tol, bool with_gradient) {
    if (!(rel_tol > 0.0 && rel_tol <= 1e-12)) fail_input("cagd::fairness::segment_energy_reference", "rel_tol must be in (0, 1e-12], got " + full_precision(rel_tol));
    return detail::energy_reference(
        seg, [&](double t) { return integrands(seg, t, with_gradient); }, rel_tol);
}

SegmentEnergy segment_energy_fast(const UnitChordHermite& seg, bool with_gradient, int rule_nodes) {
    static const numeric::GaussLegendreRule rule20(20), rule8(8);
    if (rule_nodes != 8 && rule_nodes != 20) fail_input("cagd::fairness::segment_energy_fast", "rule_nodes must be 8 or 20, got " + std::to_string(rule_nodes));
    return detail::energy_fast(
        seg, [&](double t) { return integrands(seg, t, with_gradient); }, rule_nodes == 8 ? rule8 : rule20);
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
