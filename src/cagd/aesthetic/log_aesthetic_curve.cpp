#include "cagd/aesthetic/log_aesthetic_curve.hpp"

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <complex>

#include "cagd/core/errors.hpp"

namespace cagd::aesthetic {

namespace {
const char* kPlanarCurveWho = "cagd::aesthetic::LogAestheticCurve";
bool finite_turning_at_zero_base(double alpha) { return alpha < 0.0 || alpha > 1.0; }
}  // namespace

void LogAestheticRate::validate(const char* who, const char* name, double length) const {
    const std::string n(name);
    for (const auto& [label, v] : {std::pair{"alpha", alpha}, {"c0", c0}, {"c1", c1}})
        if (!std::isfinite(v)) fail_input(who, n + " " + label + " = " + full_precision(v) + " is not finite");
    if (!(length > 0.0) || !std::isfinite(length))
        fail_input(who, "length L = " + full_precision(length) + " must be finite and > 0");
    if (alpha == 0.0) {
        if (!(c0 > 0.0))
            fail_input(who, n + ": alpha = 0 (rho = c0 exp(c1 s), eq 9) needs c0 > 0, got c0 = " + full_precision(c0));
        return;
    }
    const double u0 = base(0.0), u1 = base(length);
    if (u0 < 0.0 || u1 < 0.0 || (u0 == 0.0 && u1 == 0.0))
        fail_input(who, n + ": rho^alpha = c0 s + c1 must be > 0 on (0, L): c0 s + c1 = " + full_precision(u0) +
                            " at s = 0 and " + full_precision(u1) + " at s = L");
    if ((u0 == 0.0 || u1 == 0.0) && !finite_turning_at_zero_base(alpha))
        fail_input(who, n + ": c0 s + c1 = 0 at an end of [0, L] with alpha = " + full_precision(alpha) +
                            ": the turning angle diverges there for 0 < alpha <= 1 (allowed: alpha < 0 or alpha > 1)");
}

double LogAestheticRate::value(double s) const {
    if (alpha == 0.0) return std::exp(-c1 * s) / c0;
    return std::pow(base(s), -1.0 / alpha);
}

double LogAestheticRate::derivative(double s) const {
    if (alpha == 0.0) return -c1 * value(s);
    return (-1.0 / alpha) * c0 * std::pow(base(s), -1.0 / alpha - 1.0);
}

double LogAestheticRate::second_derivative(double s) const {
    if (alpha == 0.0) return c1 * c1 * value(s);
    return (-1.0 / alpha) * (-1.0 / alpha - 1.0) * c0 * c0 * std::pow(base(s), -1.0 / alpha - 2.0);
}

double LogAestheticRate::antiderivative(double s) const {
    if (alpha == 0.0) return c1 == 0.0 ? s / c0 : -std::exp(-c1 * s) / (c0 * c1);
    if (c0 == 0.0) return std::pow(c1, -1.0 / alpha) * s;
    if (alpha == 1.0) return std::log(base(s)) / c0;
    return alpha * std::pow(base(s), (alpha - 1.0) / alpha) / ((alpha - 1.0) * c0);
}

LogAestheticCurve::LogAestheticCurve(const LogAestheticParameters& p) : p_(p), rate_{p.alpha, p.c0, p.c1} {
    for (const auto& [name, v] :
         {std::pair{"start_angle", p.start_angle}, {"start.x", p.start.x()}, {"start.y", p.start.y()}})
        if (!std::isfinite(v))
            fail_input(kPlanarCurveWho, std::string(name) + " = " + full_precision(v) + " is not finite");
    if (p.turn != 1 && p.turn != -1)
        fail_input(kPlanarCurveWho, "turn = " + std::to_string(p.turn) + " must be +1 or -1");
    rate_.validate(kPlanarCurveWho, "curvature", p.length);
    theta_origin_ = rate_.antiderivative(0.0);
}

double LogAestheticCurve::tangent_angle(double s) const {
    if (!(s >= 0.0 && s <= p_.length)) fail_input(kPlanarCurveWho, "s = " + full_precision(s) + " outside [0, L]");
    return p_.start_angle + p_.turn * (rate_.antiderivative(s) - theta_origin_);
}

double LogAestheticCurve::curvature(double s) const {
    if (p_.alpha != 0.0 && rate_.base(s) == 0.0 && p_.alpha > 0.0)
        fail_input(kPlanarCurveWho,
                   "curvature is unbounded at s = " + full_precision(s) + " (c0 s + c1 = 0, alpha > 1)");
    return p_.turn * rate_.value(s);
}

double LogAestheticCurve::curvature_derivative(double s) const {
    if (p_.alpha != 0.0 && rate_.base(s) == 0.0 && p_.alpha > 0.0)
        fail_input(kPlanarCurveWho,
                   "curvature is unbounded at s = " + full_precision(s) + " (c0 s + c1 = 0, alpha > 1)");
    const double d = p_.turn * rate_.derivative(s);
    if (!std::isfinite(d))
        fail_input(kPlanarCurveWho, "dkappa/ds is unbounded at s = " + full_precision(s) +
                                        " (c0 s + c1 = 0 with alpha < -1: alpha = " + full_precision(p_.alpha) + ")");
    return d;
}

Eigen::Vector2d LogAestheticCurve::integrate(double a, double b) const {
    if (b <= a) return Eigen::Vector2d::Zero();
    // tanh-sinh: double-exponential convergence for smooth integrands and for the endpoint
    // singularity of θ' where c0 s + c1 = 0 (α > 1), where Gauss–Kronrod bisects for ever.
    // (Boost 1.74 declares integrate(f, a, b, …) non-const, hence one integrator per thread.)
    thread_local boost::math::quadrature::tanh_sinh<double> rule;
    const auto fx = [this](double v) { return std::cos(tangent_angle(v)); };
    const auto fy = [this](double v) { return std::sin(tangent_angle(v)); };
    return {rule.integrate(fx, a, b, 1e-14), rule.integrate(fy, a, b, 1e-14)};
}

Eigen::MatrixXd LogAestheticCurve::whole_jet(double s, int order) const {
    if (!(s >= 0.0 && s <= p_.length))
        fail_input(kPlanarCurveWho, "s = " + full_precision(s) + " outside [0, L = " + full_precision(p_.length) + "]");
    if (order < 0 || order > 3) fail_input(kPlanarCurveWho, "jet order " + std::to_string(order) + " outside 0..3");
    Eigen::MatrixXd j(order + 1, 2);
    j.row(0) = (p_.start + integrate(0.0, s)).transpose();
    const double th = tangent_angle(s);
    const Eigen::Vector2d t(std::cos(th), std::sin(th)), n(-std::sin(th), std::cos(th));
    if (order >= 1) j.row(1) = t.transpose();
    if (order >= 2) {
        const double k = curvature(s);
        j.row(2) = (k * n).transpose();
        if (order >= 3) j.row(3) = (curvature_derivative(s) * n - k * k * t).transpose();
    }
    return j;
}

Eigen::MatrixXd LogAestheticCurve::sample_points(int count) const {
    if (count < 2) fail_input(kPlanarCurveWho, "sample count " + std::to_string(count) + " < 2");
    Eigen::MatrixXd pts(count, 2);
    Eigen::Vector2d acc = p_.start;
    pts.row(0) = acc.transpose();
    for (int k = 1; k < count; ++k) {
        const double a = p_.length * (k - 1) / (count - 1), b = p_.length * k / (count - 1);
        acc += integrate(a, b);
        pts.row(k) = acc.transpose();
    }
    return pts;
}

std::optional<Eigen::Vector2d> LogAestheticCurve::closed_form_point(double s) const {
    if (!(s >= 0.0 && s <= p_.length)) fail_input(kPlanarCurveWho, "s = " + full_precision(s) + " outside [0, L]");
    using C = std::complex<double>;
    const C i(0.0, 1.0);
    const C start_dir = std::exp(i * p_.start_angle);
    C z;
    if (p_.alpha == 1.0 && p_.c0 != 0.0) {
        // θ = θ_start + σ ln(u/u0)/c0: ∫ (u/u0)^{iσ/c0} ds = (u0/c0) [(u/u0)^{iσ/c0 + 1} − 1]/(iσ/c0 + 1).
        const double u0 = rate_.base(0.0), u = rate_.base(s);
        const C k = i * static_cast<double>(p_.turn) / p_.c0;
        z = start_dir * (u0 / p_.c0) * (std::pow(C(u / u0), k + 1.0) - 1.0) / (k + 1.0);
    } else if (p_.alpha == 2.0 && p_.c0 != 0.0) {
        // u = c0 s + c1 = w², θ = θ_start + σ (2/c0)(w − w0), ds = (2w/c0) dw:
        // ∫ w e^{iω(w − w0)} dw = [e^{iω(w − w0)} (w/(iω) + 1/ω²)],  ω = 2σ/c0.
        const double w0 = std::sqrt(rate_.base(0.0)), w = std::sqrt(rate_.base(s));
        const double om = 2.0 * p_.turn / p_.c0;
        auto prim = [&](double ww) { return std::exp(i * om * (ww - w0)) * (ww / (i * om) + 1.0 / (om * om)); };
        z = start_dir * (2.0 / p_.c0) * (prim(w) - prim(w0));
    } else {
        return std::nullopt;
    }
    return Eigen::Vector2d(p_.start.x() + z.real(), p_.start.y() + z.imag());
}

LogAestheticCurve normalized_log_aesthetic_curve(double alpha, double length) {
    if (!std::isfinite(alpha))
        fail_input("cagd::aesthetic::normalized_log_aesthetic_curve",
                   "alpha = " + full_precision(alpha) + " is not finite");
    if (!finite_turning_at_zero_base(alpha))
        fail_input("cagd::aesthetic::normalized_log_aesthetic_curve",
                   "eq (15) is defined only for alpha < 0 or alpha > 1 (its turning angle alpha s^((alpha-1)/alpha) "
                   "diverges at s = 0 for 0 < alpha < 1, is constant for alpha = "
                   "1, undefined for alpha = 0); got alpha = " +
                       full_precision(alpha));
    LogAestheticParameters p;
    p.alpha = alpha;
    p.turn = alpha > 1.0 ? 1 : -1;
    p.c0 = std::pow(std::abs(alpha - 1.0), -alpha);
    p.c1 = 0.0;
    p.length = length;
    return LogAestheticCurve(p);
}

}  // namespace cagd::aesthetic
