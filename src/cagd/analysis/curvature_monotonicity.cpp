#include "cagd/analysis/curvature_monotonicity.hpp"

#include "cagd/core/errors.hpp"

namespace cagd::analysis {

namespace {

// Component k of the m-th hodograph (without the factor n!/(n−m)!, which is positive and
// irrelevant to the sign but kept so values are true derivatives).
BernsteinPolynomial hodograph(const BezierCurve& c, int m, Eigen::Index k) {
    Eigen::VectorXd d = c.control_points().col(k);
    double factor = 1.0;
    for (int r = 1; r <= m; ++r) {
        d = (d.tail(d.size() - 1) - d.head(d.size() - 1)).eval();
        factor *= c.degree() - r + 1;
    }
    std::vector<double> coeffs(d.data(), d.data() + d.size());
    return factor * BernsteinPolynomial(std::move(coeffs));
}

void require(const BezierCurve& c, int min_degree, int dim_lo, int dim_hi, const char* who) {
    if (c.degree() < min_degree)
        fail_input(who, "degree " + std::to_string(c.degree()) + " < " + std::to_string(min_degree));
    if (c.dimension() < dim_lo || c.dimension() > dim_hi)
        fail_input(who, "dimension " + std::to_string(c.dimension()) + " not supported");
    if (c.t_min() != 0.0 || c.t_max() != 1.0) fail_input(who, "the curve must be parametrised on [0, 1]");
}

struct Derivatives {
    std::vector<BernsteinPolynomial> d1, d2, d3;
};

Derivatives derivatives(const BezierCurve& c, int order) {
    Derivatives d;
    for (Eigen::Index k = 0; k < c.dimension(); ++k) {
        d.d1.push_back(hodograph(c, 1, k));
        d.d2.push_back(hodograph(c, 2, k));
        if (order >= 3) d.d3.push_back(hodograph(c, 3, k));
    }
    return d;
}

BernsteinPolynomial dot(const std::vector<BernsteinPolynomial>& a, const std::vector<BernsteinPolynomial>& b) {
    BernsteinPolynomial s = a[0] * b[0];
    for (std::size_t k = 1; k < a.size(); ++k) s = s + a[k] * b[k];
    return s;
}

// Components of r' × r'' (planar: one component, the z one); a = r', b = r''.
std::vector<BernsteinPolynomial> cross(const std::vector<BernsteinPolynomial>& a,
                                       const std::vector<BernsteinPolynomial>& b) {
    // r' × r'' has degree 2n − 4, one below the product's 2n − 3: reduce exactly.
    if (a.size() == 2) return {(a[0] * b[1] - a[1] * b[0]).reduced()};
    return {(a[1] * b[2] - a[2] * b[1]).reduced(), (a[2] * b[0] - a[0] * b[2]).reduced(),
            (a[0] * b[1] - a[1] * b[0]).reduced()};
}

}  // namespace

PlanarCurvatureParts planar_curvature_parts(const BezierCurve& c) {
    require(c, 2, 2, 2, "cagd::analysis::planar_curvature_parts");
    const Derivatives d = derivatives(c, 2);
    return {cross(d.d1, d.d2)[0], dot(d.d1, d.d1)};
}

BernsteinPolynomial curvature_derivative_numerator(const BezierCurve& c) {
    const PlanarCurvatureParts p = planar_curvature_parts(c);
    return p.f.derivative() * p.g - 1.5 * (p.f * p.g.derivative());
}

BernsteinPolynomial squared_curvature_derivative_numerator(const BezierCurve& c) {
    require(c, 2, 2, 3, "cagd::analysis::squared_curvature_derivative_numerator");
    const Derivatives d = derivatives(c, 2);
    const std::vector<BernsteinPolynomial> cr = cross(d.d1, d.d2);
    const BernsteinPolynomial q = dot(cr, cr), g = dot(d.d1, d.d1);
    return q.derivative() * g - 3.0 * (q * g.derivative());
}

BernsteinPolynomial torsion_derivative_numerator(const BezierCurve& c) {
    require(c, 3, 3, 3, "cagd::analysis::torsion_derivative_numerator");
    const Derivatives d = derivatives(c, 3);
    const std::vector<BernsteinPolynomial> cr = cross(d.d1, d.d2);
    const BernsteinPolynomial q = dot(cr, cr), det = dot(cr, d.d3);
    return det.derivative() * q - det * q.derivative();
}

const char* to_string(Trend t) {
    switch (t) {
        case Trend::increasing: return "increasing";
        case Trend::decreasing: return "decreasing";
        case Trend::constant: return "constant";
        case Trend::not_monotone: return "not_monotone";
        case Trend::undetermined: return "undetermined";
    }
    return "?";
}

Trend trend_of(const SignAnalysis& s) {
    switch (s.sign) {
        case SignOnInterval::negative:
        case SignOnInterval::nonpositive: return Trend::decreasing;
        case SignOnInterval::positive:
        case SignOnInterval::nonnegative: return Trend::increasing;
        case SignOnInterval::zero: return Trend::constant;
        case SignOnInterval::changes_sign: return Trend::not_monotone;
        case SignOnInterval::undetermined: return Trend::undetermined;
    }
    return Trend::undetermined;
}

}  // namespace cagd::analysis
