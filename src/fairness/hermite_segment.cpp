#include "cagd/fairness/hermite_segment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "cagd/numeric/gauss_legendre.hpp"
#include "cagd/numeric/romberg.hpp"

namespace cagd::fairness {

namespace {

constexpr double kCuspSpeed = 1e-13;  // relative to 1 + r0 + r1

double cross(const Eigen::Vector2d& p, const Eigen::Vector2d& q) { return p.x() * q.y() - p.y() * q.x(); }

// cos/sin that are exact at multiples of π/2 given in floating point (±π, ±π/2, 0), so the
// collinear configurations of §4.1 are collinear to the last bit.
Eigen::Vector2d unit_direction(double theta) {
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

// The six integrands at t: |P'|, k²/|P'|⁵, and their derivatives with respect to r0, r1.
using Integrands = std::array<double, 6>;

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

SegmentEnergy assemble(const UnitChordHermite& s, const Integrands& I, double err_l, double err_e) {
    SegmentEnergy r;
    r.length = I[0];
    r.strain_energy = I[1];
    r.pseudo_energy = I[0] * I[0] * I[1];
    const double dj0 = 2.0 * I[0] * I[2] * I[1] + I[0] * I[0] * I[4];
    const double dj1 = 2.0 * I[0] * I[3] * I[1] + I[0] * I[0] * I[5];
    r.dj_dlog_r0 = s.r0() * dj0;
    r.dj_dlog_r1 = s.r1() * dj1;
    r.error_estimate = 2.0 * I[0] * I[1] * err_l + I[0] * I[0] * err_e;
    return r;
}

SegmentEnergy cusp_energy() {
    SegmentEnergy r;
    r.cusp = true;
    r.strain_energy = r.pseudo_energy = std::numeric_limits<double>::infinity();
    r.outcome = {Status::no_solution, "segment has a cusp (P'(t) = 0 in [0, 1]): strain energy diverges"};
    return r;
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
    u0_ = unit_direction(theta0);
    u1_ = unit_direction(theta1);
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

std::vector<SpeedMinimum> speed_minima(const UnitChordHermite& seg) {
    // (|P'|²)'/2 = P'·P'' = q0 + q1 t + q2 t² + q3 t³ (a cubic); its roots where it changes sign
    // from − to + are the minima. The roots of its derivative (a quadratic) split [0, 1] into
    // monotone pieces, each bracketing at most one root, found by bisection to 1 ulp.
    const Eigen::Vector2d &A = seg.a(), &B = seg.b(), &C = seg.c();
    const double q0 = A.dot(B), q1 = B.dot(B) + 2.0 * A.dot(C), q2 = 3.0 * B.dot(C), q3 = 2.0 * C.dot(C);
    const auto slope = [&](double t) { return q0 + t * (q1 + t * (q2 + t * q3)); };
    std::vector<double> cuts{0.0};
    const double a2 = 3.0 * q3, a1 = 2.0 * q2, a0 = q1;  // derivative of the cubic
    if (a2 != 0.0) {
        const double disc = a1 * a1 - 4.0 * a2 * a0;
        if (disc > 0.0) {
            const double sq = std::sqrt(disc);
            const double qq = -0.5 * (a1 + (a1 >= 0 ? sq : -sq));
            for (double r : {qq / a2, qq != 0.0 ? a0 / qq : -1.0})
                if (r > 0.0 && r < 1.0) cuts.push_back(r);
        }
    } else if (a1 != 0.0) {
        const double r = -a0 / a1;
        if (r > 0.0 && r < 1.0) cuts.push_back(r);
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.push_back(1.0);
    std::vector<SpeedMinimum> out;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
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

namespace {
bool cusp_among(const UnitChordHermite& seg, const std::vector<SpeedMinimum>& minima) {
    const double floor = kCuspSpeed * (1.0 + seg.r0() + seg.r1());
    for (const SpeedMinimum& m : minima)
        if (m.speed <= floor) return true;
    return false;
}

std::vector<double> breaks_for(const UnitChordHermite& seg, const std::vector<SpeedMinimum>& minima) {
    std::vector<double> br{0.0, 0.5, 1.0};
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
    std::vector<double> out;
    for (double b : br)
        if (out.empty() || b - out.back() > 1e-15) out.push_back(b);
    if (out.back() != 1.0) out.back() = 1.0;
    return out;
}
}  // namespace

bool has_cusp(const UnitChordHermite& seg) { return cusp_among(seg, speed_minima(seg)); }

std::vector<double> integration_breaks(const UnitChordHermite& seg) { return breaks_for(seg, speed_minima(seg)); }

// Romberg on the reference energy: 20 levels (10^6 evaluations per piece) reach rel 1e-13 on every
// smooth piece; an absolute tolerance at the underflow edge lets a component that vanishes
// identically (a straight segment) converge at 0 without loosening any other.
constexpr int kRombergLevels = 20;
constexpr double kRombergAbsTol = 1e-300;

SegmentEnergy segment_energy_reference(const UnitChordHermite& seg, double rel_tol, bool with_gradient) {
    if (!(rel_tol > 0.0 && rel_tol <= 1e-12)) fail_input("cagd::fairness::segment_energy_reference", "rel_tol must be in (0, 1e-12], got " + full_precision(rel_tol));
    const std::vector<SpeedMinimum> minima = speed_minima(seg);
    if (cusp_among(seg, minima)) return cusp_energy();
    const std::vector<double> br = breaks_for(seg, minima);
    Integrands total{};
    Integrands err{};
    long evaluations = 0;
    Outcome outcome;
    const auto f = [&](double t) { return integrands(seg, t, with_gradient); };
    for (std::size_t p = 0; p + 1 < br.size(); ++p) {
        // abs_tol: a component that vanishes identically (a straight segment) converges at 0.
        const numeric::RombergVectorResult<6> r = numeric::romberg_vector<6>(f, br[p], br[p + 1], rel_tol, kRombergAbsTol, kRombergLevels);
        for (std::size_t c = 0; c < 6; ++c) {
            total[c] += r.value[c];
            err[c] += r.error_estimate[c];
        }
        evaluations += r.evaluations;
        if (!r.outcome.ok() && outcome.ok()) outcome = r.outcome;
    }
    SegmentEnergy out = assemble(seg, total, err[0], err[1]);
    out.evaluations = evaluations;
    out.outcome = outcome;
    return out;
}

SegmentEnergy segment_energy_fast(const UnitChordHermite& seg, bool with_gradient, int rule_nodes) {
    static const numeric::GaussLegendreRule rule20(20), rule8(8);
    if (rule_nodes != 8 && rule_nodes != 20) fail_input("cagd::fairness::segment_energy_fast", "rule_nodes must be 8 or 20, got " + std::to_string(rule_nodes));
    const numeric::GaussLegendreRule& rule = rule_nodes == 8 ? rule8 : rule20;
    const std::vector<SpeedMinimum> minima = speed_minima(seg);
    if (cusp_among(seg, minima)) return cusp_energy();
    const std::vector<double> br = breaks_for(seg, minima);
    Integrands total{};
    long evaluations = 0;
    for (std::size_t p = 0; p + 1 < br.size(); ++p) {
        const double half = 0.5 * (br[p + 1] - br[p]), mid = 0.5 * (br[p + 1] + br[p]);
        for (int i = 0; i < rule.size(); ++i) {
            const Integrands v = integrands(seg, mid + half * rule.nodes()[i], with_gradient);
            const double w = half * rule.weights()[i];
            for (std::size_t c = 0; c < v.size(); ++c) total[c] += w * v[c];
        }
        evaluations += rule.size();
    }
    SegmentEnergy out = assemble(seg, total, 0.0, 0.0);
    out.evaluations = evaluations;
    return out;
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
