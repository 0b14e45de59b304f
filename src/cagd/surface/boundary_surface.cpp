#include "cagd/surface/boundary_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::surface {

using numeric::TaylorJet;

namespace {

TaylorJet jet_of(const DerivativeFunction& f, double x, int order) {
    std::vector<double> d(static_cast<std::size_t>(order) + 1);
    for (int k = 0; k <= order; ++k) d[static_cast<std::size_t>(k)] = f(x, k);
    return TaylorJet::from_derivatives(d);
}

void require_boundary(const BoundaryCurve& c, int m, const char* name, const char* who) {
    if (!c.y) fail_input(who, std::string(name) + " boundary: y(x) is missing");
    if (c.phi.size() != static_cast<std::size_t>(m) + 1)
        fail_input(who, std::string(name) + " boundary: needs m+1 = " + std::to_string(m + 1) +
                            " functions phi (z and the cross derivatives), got " + std::to_string(c.phi.size()));
    for (std::size_t j = 0; j < c.phi.size(); ++j)
        if (!c.phi[j]) fail_input(who, std::string(name) + " boundary: phi[" + std::to_string(j) + "] is missing");
    if (!std::isfinite(c.x_min) || !std::isfinite(c.x_max) || !(c.x_min < c.x_max))
        fail_input(who, std::string(name) + " boundary: needs x_min < x_max, got [" + full_precision(c.x_min) + ", " +
                            full_precision(c.x_max) + "]");
}

}  // namespace

DerivativeFunction constant_function(double c) {
    return [c](double, int k) { return k == 0 ? c : 0.0; };
}

DerivativeFunction polynomial_function(std::vector<double> coefficients) {
    return [c = std::move(coefficients)](double x, int k) {
        double s = 0.0;
        for (std::size_t d = c.size(); d-- > static_cast<std::size_t>(std::max(k, 0));) {
            double falling = 1.0;  // d (d−1) … (d−k+1)
            for (int r = 0; r < k; ++r) falling *= static_cast<double>(d) - r;
            s = s * x + c[d] * falling;
        }
        return s;
    };
}

DerivativeFunction sinusoid(double amplitude, double frequency, double phase, double offset) {
    return [=](double x, int k) {
        return amplitude * std::pow(frequency, k) * std::sin(frequency * x + phase + k * (std::numbers::pi / 2)) +
               (k == 0 ? offset : 0.0);
    };
}

DerivativeFunction explicit_spline_function(std::shared_ptr<const spline::ExplicitSpline> spline, int column) {
    if (!spline || column < 0 || column >= spline->values.cols())
        fail_input("cagd::surface::explicit_spline_function",
                   "needs a spline and a column in [0, columns), got " + std::to_string(column));
    return [spline, column](double x, int k) { return k > 3 ? 0.0 : spline->evaluate(x, k)(column); };
}

BoundaryCurve boundary_through_points(const PointList& xyz, const std::vector<double>& cross_derivatives) {
    const char* who = "cagd::surface::boundary_through_points";
    if (xyz.cols() != 3) fail_input(who, "needs rows x, y, z, got " + std::to_string(xyz.cols()) + " columns");
    std::vector<double> x(static_cast<std::size_t>(xyz.rows()));
    for (Eigen::Index r = 0; r < xyz.rows(); ++r) x[static_cast<std::size_t>(r)] = xyz(r, 0);
    const auto spline =
        std::make_shared<const spline::ExplicitSpline>(spline::hosaka_explicit_spline(x, xyz.rightCols(2)));
    BoundaryCurve c{x.front(), x.back(), explicit_spline_function(spline, 0), {explicit_spline_function(spline, 1)}};
    for (double d : cross_derivatives) {
        if (!std::isfinite(d)) fail_input(who, "cross-boundary derivatives must be finite, got " + full_precision(d));
        c.phi.push_back(constant_function(d));
    }
    return c;
}

BoundaryConformingSurface::BoundaryConformingSurface(int m, BoundaryCurve lower, BoundaryCurve upper)
    : basis_(m), lower_(std::move(lower)), upper_(std::move(upper)) {
    const char* who = "cagd::surface::BoundaryConformingSurface";
    require_boundary(lower_, m, "lower", who);
    require_boundary(upper_, m, "upper", who);
    const double scale = 1.0 + std::max(std::abs(lower_.x_min), std::abs(lower_.x_max));
    if (std::abs(lower_.x_min - upper_.x_min) > 1e-12 * scale || std::abs(lower_.x_max - upper_.x_max) > 1e-12 * scale)
        fail_input(who, "the boundary curves span different x ranges: [" + full_precision(lower_.x_min) + ", " +
                            full_precision(lower_.x_max) + "] and [" + full_precision(upper_.x_min) + ", " +
                            full_precision(upper_.x_max) + "]");
    for (int s = 0; s <= 1024; ++s) {
        const double x = lower_.x_min + (lower_.x_max - lower_.x_min) * s / 1024.0;
        const double y0 = lower_.y(x, 0), y1 = upper_.y(x, 0);
        if (!std::isfinite(y0) || !std::isfinite(y1))
            fail_input(who, "a boundary's y is not finite at x = " + full_precision(x));
        if (!(y1 > y0))
            fail_input(who, "the boundary curves cross or touch at x = " + full_precision(x) +
                                ": y_lower = " + full_precision(y0) + ", y_upper = " + full_precision(y1));
    }
}

double BoundaryConformingSurface::y_lower(double x) const { return lower_.y(x, 0); }
double BoundaryConformingSurface::y_upper(double x) const { return upper_.y(x, 0); }

double BoundaryConformingSurface::section_v(double x, double y, const char* who) const {
    if (!(x >= x_min() && x <= x_max()))
        fail_input(who, "x = " + full_precision(x) + " outside [" + full_precision(x_min()) + ", " +
                            full_precision(x_max()) + "]");
    const double y0 = y_lower(x), ly = y_upper(x) - y0;
    if (!(ly > 0.0)) fail_input(who, "the boundary curves cross or touch at x = " + full_precision(x));
    if (!(y >= y0 - 1e-9 * ly && y <= y0 + ly * (1 + 1e-9)))
        fail_input(who, "y = " + full_precision(y) + " outside the section [" + full_precision(y0) + ", " +
                            full_precision(y0 + ly) + "] at x = " + full_precision(x));
    return (y - y0) / ly;
}

BoundaryConformingSurface::Inputs BoundaryConformingSurface::inputs(double x, int order) const {
    Inputs in{{jet_of(lower_.y, x, order), jet_of(upper_.y, x, order)}, {}};
    for (int k = 0; k < 2; ++k)
        for (const DerivativeFunction& f : (k == 0 ? lower_ : upper_).phi) in.phi[k].push_back(jet_of(f, x, order));
    return in;
}

std::vector<double> BoundaryConformingSurface::characteristics(double x, int k, int i, int jmax) const {
    const Inputs in = inputs(x, i);
    const TaylorJet l = in.y[1] - in.y[0];
    const TaylorJet l_inverse = numeric::reciprocal(l);
    const double side = k;  // v at the boundary
    // Level 0: _kφ_{0,j}, j = 0..jmax+i; j ≤ m given, j > m from eq (37) at v = k.
    std::vector<TaylorJet> level;
    for (int j = 0; j <= jmax + i; ++j) {
        if (j <= m()) {
            level.push_back(in.phi[k][static_cast<std::size_t>(j)]);
            continue;
        }
        TaylorJet sum(i);
        for (int jj = 0; jj <= m(); ++jj)
            sum +=
                numeric::power(l_inverse, j - jj) * (in.phi[0][static_cast<std::size_t>(jj)] * basis_.p(jj, side, j) +
                                                     in.phi[1][static_cast<std::size_t>(jj)] * basis_.q(jj, side, j));
        level.push_back(sum);
    }
    // Recurrence (36), one x-derivative per step.
    const TaylorJet slope_k = in.y[k].differentiated();
    for (int r = 1; r <= i; ++r) {
        std::vector<TaylorJet> next;
        for (std::size_t j = 0; j + 1 < level.size(); ++j)
            next.push_back(level[j].differentiated() - level[j + 1] * slope_k);
        level = std::move(next);
    }
    std::vector<double> values;
    for (int j = 0; j <= jmax; ++j) values.push_back(level[static_cast<std::size_t>(j)].value());
    return values;
}

double BoundaryConformingSurface::characteristic(double x, int k, int i, int j) const {
    const char* who = "cagd::surface::BoundaryConformingSurface::characteristic";
    if (k < 0 || k > 1 || i < 0 || j < 0)
        fail_input(who, "needs k in {0, 1}, i >= 0, j >= 0, got k=" + std::to_string(k) + " i=" + std::to_string(i) +
                            " j=" + std::to_string(j));
    section_v(x, y_lower(x), who);
    return characteristics(x, k, i, j).back();
}

double BoundaryConformingSurface::derivative(double x, double y, int i, int n) const {
    const char* who = "cagd::surface::BoundaryConformingSurface::derivative";
    if (i < 0 || n < 0)
        fail_input(who, "derivative orders must be >= 0, got (" + std::to_string(i) + ", " + std::to_string(n) + ")");
    const double v = section_v(x, y, who), l = y_upper(x) - y_lower(x);
    const std::vector<double> c0 = characteristics(x, 0, i, m()), c1 = characteristics(x, 1, i, m());
    double s = 0.0;
    for (int j = 0; j <= m(); ++j)
        s += std::pow(l, j - n) * (c0[static_cast<std::size_t>(j)] * basis_.p(j, v, n) +
                                   c1[static_cast<std::size_t>(j)] * basis_.q(j, v, n));
    return s;
}

double BoundaryConformingSurface::derivative_direct(double x, double y, int i, int n) const {
    const char* who = "cagd::surface::BoundaryConformingSurface::derivative_direct";
    if (i < 0 || n < 0)
        fail_input(who, "derivative orders must be >= 0, got (" + std::to_string(i) + ", " + std::to_string(n) + ")");
    const double v0 = section_v(x, y, who);
    const Inputs in = inputs(x, i);
    const TaylorJet l = in.y[1] - in.y[0];
    const TaylorJet v = (TaylorJet(i, y) - in.y[0]) * numeric::reciprocal(l);  // v(x) at fixed y
    TaylorJet sum(i);
    for (int j = 0; j <= m(); ++j) {
        std::vector<double> dp, dq;  // derivatives of p_j^{(n)}, q_j^{(n)} at v0
        for (int r = 0; r <= i; ++r) {
            dp.push_back(basis_.p(j, v0, n + r));
            dq.push_back(basis_.q(j, v0, n + r));
        }
        sum += numeric::power(l, j - n) * (in.phi[0][static_cast<std::size_t>(j)] * numeric::compose(dp, v) +
                                           in.phi[1][static_cast<std::size_t>(j)] * numeric::compose(dq, v));
    }
    return sum.derivative(i);
}

RationalPolynomial identity40_bracket(int m, int j, int k, int s) {
    const char* who = "cagd::surface::identity40_bracket";
    if (m < 0 || j < 0 || j > m || k < 0 || k > 1 || s < 0 || s > 1)
        fail_input(who, "needs m >= 0, 0 <= j <= m, k and s in {0, 1}, got m=" + std::to_string(m) +
                            " j=" + std::to_string(j) + " k=" + std::to_string(k) + " s=" + std::to_string(s));
    const RationalPolynomial b = k == 0 ? spline::hosaka_p(m, j) : spline::hosaka_q(m, j);
    const RationalPolynomial previous =
        j == 0 ? RationalPolynomial() : (k == 0 ? spline::hosaka_p(m, j - 1) : spline::hosaka_q(m, j - 1));
    const Rational high_0 = b.derivative(m + 1)(0), high_1 = b.derivative(m + 1)(1);
    const RationalPolynomial v = RationalPolynomial::monomial(1), v_minus_1 = RationalPolynomial::linear(-1, 1);
    if (s == 0)
        return Rational(-j) * b + (k == 0 ? previous : RationalPolynomial()) + b.derivative() * v_minus_1 +
               high_0 * spline::hosaka_p(m, m);
    return Rational(j) * b + (k == 1 ? previous : RationalPolynomial()) - b.derivative() * v +
           high_1 * spline::hosaka_q(m, m);
}

SectionJoinedSurface::SectionJoinedSurface(const BoundaryConformingSurface& a, double x0, BoundaryCurve far)
    : a_(std::make_shared<const BoundaryConformingSurface>(a)), x0_(x0) {
    const char* who = "cagd::surface::SectionJoinedSurface";
    if (!(x0 >= a.x_min() && x0 <= a.x_max()))
        fail_input(who, "the section x0 = " + full_precision(x0) + " lies outside the surface's range [" +
                            full_precision(a.x_min()) + ", " + full_precision(a.x_max()) + "]");
    const double y0 = a.y_lower(x0), y1 = a.y_upper(x0), scale = 1.0 + std::max(std::abs(y0), std::abs(y1));
    if (std::abs(far.x_min - y0) > 1e-12 * scale || std::abs(far.x_max - y1) > 1e-12 * scale)
        fail_input(who, "the far boundary L3 must span the section's y range [" + full_precision(y0) + ", " +
                            full_precision(y1) + "], got [" + full_precision(far.x_min) + ", " +
                            full_precision(far.x_max) + "]");
    BoundaryCurve near;
    near.x_min = y0;
    near.x_max = y1;
    near.y = [x0](double, int k) { return k == 0 ? x0 : 0.0; };
    const std::shared_ptr<const BoundaryConformingSurface> source = a_;
    // y clamped to the section: the far curve's range equals it only to 1e-12.
    for (int i = 0; i <= a.m(); ++i)
        near.phi.push_back(
            [source, x0, i, y0, y1](double y, int r) { return source->derivative(x0, std::clamp(y, y0, y1), i, r); });
    try {
        joined_ = std::make_shared<const BoundaryConformingSurface>(a.m(), std::move(near), std::move(far));
    } catch (const InvalidInput& e) {
        fail_input(who, std::string("the surface between the section and L3 is not defined (x3(y) must exceed x0 = ") +
                            full_precision(x0) + "): " + e.what());
    }
}

}  // namespace cagd::surface
