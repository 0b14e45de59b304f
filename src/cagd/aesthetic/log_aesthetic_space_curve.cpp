#include "cagd/aesthetic/log_aesthetic_space_curve.hpp"

#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::aesthetic {

namespace {

const char* kSpaceCurveWho = "cagd::aesthetic::LogAestheticSpaceCurve";
constexpr int kNodes = 257;
constexpr double kTolerance = 1e-13;

bool vanishes_at_start(const LogAestheticRate& r) { return r.alpha != 0.0 && r.c1 == 0.0; }

// rate(s(w)) · ds/dw for s = L w^m; where c s + d = 0 at s = 0 the two factors are combined
// into one power of w, which is finite (and C¹) for the m chosen below.
double rate_times_jacobian(const LogAestheticRate& r, double length, int m, double w) {
    const double jac = m * length * std::pow(w, m - 1);
    if (!vanishes_at_start(r)) return r.value(length * std::pow(w, m)) * jac;
    return std::pow(r.c0 * length, -1.0 / r.alpha) * m * length * std::pow(w, m * (1.0 - 1.0 / r.alpha) - 1.0);
}

// Frenet–Serret (eq 33) for position and frame in the variable w, s = L w^m.
struct FrenetSerretSystem {
    const LogAestheticSpaceParameters* p;
    int m;
    void operator()(const std::array<double, 12>& x, std::array<double, 12>& dx, double w) const {
        const double js = m * p->length * std::pow(w, m - 1);
        const double k = rate_times_jacobian(p->curvature, p->length, m, w),
                     tau = rate_times_jacobian(p->torsion, p->length, m, w);
        for (std::size_t i = 0; i < 3; ++i) {
            const double t = x[3 + i], n = x[6 + i], b = x[9 + i];
            dx[i] = js * t;
            dx[3 + i] = k * n;
            dx[6 + i] = -k * t + tau * b;
            dx[9 + i] = -tau * n;
        }
    }
};

void integrate_frenet_serret(const FrenetSerretSystem& system, std::array<double, 12>& x, double w0, double w1,
                             double first_step) {
    namespace odeint = boost::numeric::odeint;
    auto stepper =
        odeint::make_controlled(kTolerance, kTolerance, odeint::runge_kutta_dopri5<std::array<double, 12>>());
    odeint::integrate_adaptive(stepper, system, x, w0, w1, first_step);
}

}  // namespace

LogAestheticSpaceParameters normalized_log_aesthetic_space_parameters(double alpha, double beta, double length,
                                                                      double start) {
    const char* who = "cagd::aesthetic::normalized_log_aesthetic_space_parameters";
    if (!(start >= 0.0) || !std::isfinite(start))
        fail_input(who, "start s0 = " + full_precision(start) + " must be finite and >= 0");
    for (const auto& [name, v] : {std::pair{"alpha", alpha}, {"beta", beta}}) {
        if (!std::isfinite(v)) fail_input(who, std::string(name) + " = " + full_precision(v) + " is not finite");
        if (v == 0.0 || v == 1.0)
            fail_input(who, std::string(name) + " = " + full_precision(v) +
                                ": the normalised law |slope - 1| s^(-1/slope) needs a slope other than 0 and 1");
        if (start == 0.0 && v > 0.0 && v < 1.0)
            fail_input(who, std::string(name) + " = " + full_precision(v) +
                                " with start s0 = 0: the turning angle diverges at s = 0 for 0 < slope < 1 (use slope "
                                "< 0 or > 1, or s0 > 0)");
    }
    LogAestheticSpaceParameters p;
    const double c = std::pow(std::abs(alpha - 1.0), -alpha), g = std::pow(std::abs(beta - 1.0), -beta);
    p.curvature = {alpha, c, c * start};
    p.torsion = {beta, g, g * start};
    p.length = length;
    p.curvature.validate(who, "curvature", length);
    return p;
}

LogAestheticSpaceCurve::LogAestheticSpaceCurve(const LogAestheticSpaceParameters& p) : p_(p) {
    p.curvature.validate(kSpaceCurveWho, "curvature", p.length);
    p.torsion.validate(kSpaceCurveWho, "torsion", p.length);
    for (const auto& [name, r] : {std::pair{"curvature", p.curvature}, {"torsion", p.torsion}})
        if (r.alpha != 0.0 && r.base(p.length) == 0.0)
            fail_input(kSpaceCurveWho,
                       std::string(name) + ": c s + d = 0 at s = L = " + full_precision(p.length) +
                           " (a singular end is not supported; reverse the curve so that it is at s = 0)");
    for (const LogAestheticRate& r : {p.curvature, p.torsion})
        if (vanishes_at_start(r))
            exponent_ = std::max(
                {exponent_, 2, r.alpha > 1.0 ? static_cast<int>(std::ceil(2.0 * r.alpha / (r.alpha - 1.0))) : 2});

    State x{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    nodes_.reserve(kNodes);
    nodes_.push_back(x);
    const FrenetSerretSystem system{&p_, exponent_};
    for (int k = 1; k < kNodes; ++k) {
        const double w0 = static_cast<double>(k - 1) / (kNodes - 1), w1 = static_cast<double>(k) / (kNodes - 1);
        integrate_frenet_serret(system, x, w0, w1, (w1 - w0) / 8);
        nodes_.push_back(x);
    }
}

void LogAestheticSpaceCurve::check_s(double s) const {
    if (!(s >= 0.0 && s <= p_.length))
        fail_input(kSpaceCurveWho, "s = " + full_precision(s) + " outside [0, L = " + full_precision(p_.length) + "]");
}

LogAestheticSpaceCurve::State LogAestheticSpaceCurve::state_at(double s) const {
    check_s(s);
    const double w = std::pow(s / p_.length, 1.0 / exponent_);
    const int k = std::min(kNodes - 1, static_cast<int>(std::floor(w * (kNodes - 1))));
    State x = nodes_[static_cast<std::size_t>(k)];
    const double w0 = static_cast<double>(k) / (kNodes - 1);
    if (w > w0) {
        integrate_frenet_serret(FrenetSerretSystem{&p_, exponent_}, x, w0, w, (w - w0) / 4);
    }
    return x;
}

double LogAestheticSpaceCurve::curvature_angle(double s) const {
    check_s(s);
    return p_.curvature.antiderivative(s) - p_.curvature.antiderivative(0.0);
}

double LogAestheticSpaceCurve::torsion_angle(double s) const {
    check_s(s);
    return p_.torsion.antiderivative(s) - p_.torsion.antiderivative(0.0);
}

Eigen::Matrix3d LogAestheticSpaceCurve::frame(double s) const {
    const State x = state_at(s);
    Eigen::Matrix3d f;
    for (int i = 0; i < 3; ++i) {
        f(i, 0) = x[3 + static_cast<std::size_t>(i)];
        f(i, 1) = x[6 + static_cast<std::size_t>(i)];
        f(i, 2) = x[9 + static_cast<std::size_t>(i)];
    }
    return f;
}

Eigen::MatrixXd LogAestheticSpaceCurve::whole_jet(double s, int order) const {
    if (order < 0 || order > 4) fail_input(kSpaceCurveWho, "jet order " + std::to_string(order) + " outside 0..4");
    const State x = state_at(s);
    Eigen::MatrixXd j(order + 1, 3);
    const Eigen::Vector3d r(x[0], x[1], x[2]), t(x[3], x[4], x[5]), n(x[6], x[7], x[8]), b(x[9], x[10], x[11]);
    j.row(0) = r.transpose();
    if (order >= 1) j.row(1) = t.transpose();
    if (order >= 2) {
        const double k = curvature(s);
        if (!std::isfinite(k)) fail_input(kSpaceCurveWho, "curvature is unbounded at s = " + full_precision(s));
        j.row(2) = (k * n).transpose();
        if (order >= 3) {
            const double dk = p_.curvature.derivative(s), tau = torsion(s);
            if (!std::isfinite(dk) || !std::isfinite(tau))
                fail_input(kSpaceCurveWho, "dkappa/ds or torsion is unbounded at s = " + full_precision(s));
            j.row(3) = (-k * k * t + dk * n + k * tau * b).transpose();
            if (order >= 4) {
                const double ddk = p_.curvature.second_derivative(s), dtau = p_.torsion.derivative(s);
                if (!std::isfinite(ddk) || !std::isfinite(dtau))
                    fail_input(kSpaceCurveWho,
                               "a derivative of curvature or torsion is unbounded at s = " + full_precision(s));
                j.row(4) = (-3.0 * k * dk * t + (ddk - k * k * k - k * tau * tau) * n + (2.0 * dk * tau + k * dtau) * b)
                               .transpose();
            }
        }
    }
    return j;
}

}  // namespace cagd::aesthetic
