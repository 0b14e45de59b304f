#include "cagd/aesthetic/cubic_bspline_monotonicity.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cagd/core/errors.hpp"

namespace cagd::aesthetic {

namespace {

void require_angles(double theta0, double theta1, const char* who) {
    for (double a : {theta0, theta1})
        if (!std::isfinite(a) || a < 0.0 || a >= std::numbers::pi)
            fail_input(who, "angle " + full_precision(a) + " outside [0, pi)");
}

double signed_turn(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

// C0, C1, C2 of the header; the others by C_{5−k}(θ0, θ1) = −C_k(θ1, θ0).
std::array<double, 3> leading_coefficients(double a, double b) {
    using std::cos;
    using std::sin;
    const double c3 = std::pow(cos(a / 2), 3);
    const double c0 = c3 * (sin(a / 2 + b) - 3 * sin(a / 2));
    const double c1 = -0.4 * (2 - 4 * cos(a) + cos(b) + cos(a + b)) * sin(a) - c3 * (3 * sin(a / 2) - sin(a / 2 + b));
    const double c2 = (-22 * sin(a) + 7 * sin(2 * a) -
                       2 * cos(a / 2) *
                           (32 * sin(a / 2 - b) + 14 * sin(a / 2 + b) - 6 * sin(1.5 * a + b) + sin(a / 2 + 2 * b) +
                            sin(1.5 * a + 2 * b))) /
                      40;
    return {c0, c1, c2};
}

}  // namespace

CubicPoints unit_edge_polygon(double theta0, double theta1) {
    require_angles(theta0, theta1, "cagd::aesthetic::unit_edge_polygon");
    CubicPoints p;
    p << -std::cos(theta0), std::sin(theta0), 0.0, 0.0, 1.0, 0.0, 1.0 + std::cos(theta1), std::sin(theta1);
    return p;
}

CubicPoints uniform_segment_bezier(const CubicPoints& p) {
    CubicPoints q;
    q.row(0) = (p.row(0) + 4.0 * p.row(1) + p.row(2)) / 6.0;
    q.row(1) = (2.0 * p.row(1) + p.row(2)) / 3.0;
    q.row(2) = (p.row(1) + 2.0 * p.row(2)) / 3.0;
    q.row(3) = (p.row(1) + 4.0 * p.row(2) + p.row(3)) / 6.0;
    return q;
}

CubicPoints equivalent_uniform_polygon(const CubicPoints& q) {
    CubicPoints p;
    p.row(1) = 2.0 * q.row(1) - q.row(2);
    p.row(2) = 2.0 * q.row(2) - q.row(1);
    p.row(0) = 6.0 * q.row(0) - 4.0 * p.row(1) - p.row(2);
    p.row(3) = 6.0 * q.row(3) - p.row(1) - 4.0 * p.row(2);
    return p;
}

std::array<double, 6> monotonicity_coefficients(double theta0, double theta1) {
    require_angles(theta0, theta1, "cagd::aesthetic::monotonicity_coefficients");
    const auto f = leading_coefficients(theta0, theta1), r = leading_coefficients(theta1, theta0);
    return {f[0], f[1], f[2], -r[2], -r[1], -r[0]};
}

double condition29(double theta0, double theta1) {
    require_angles(theta0, theta1, "cagd::aesthetic::condition29");
    return std::sin(theta0 + theta1 / 2) - 3.0 * std::sin(theta1 / 2);
}

double theta1_bound(double theta0) {
    require_angles(theta0, 0.0, "cagd::aesthetic::theta1_bound");
    return 2.0 * std::acos((3.0 - std::cos(theta0)) / std::sqrt(10.0 - 6.0 * std::cos(theta0)));
}

Eigen::MatrixXd endpoint_interpolating_polygon(const Eigen::MatrixXd& unit_polygon) {
    const char* who = "cagd::aesthetic::endpoint_interpolating_polygon";
    if (unit_polygon.cols() != 2 || unit_polygon.rows() < 5) fail_input(who, "needs at least 5 planar points");
    if (!unit_polygon.allFinite()) fail_input(who, "a coordinate is not finite");
    Eigen::MatrixXd p = unit_polygon;
    const Eigen::Index n = p.rows() - 1;
    // Start: P1 at 2/3 from P2 towards Q1, P0 at cos θ/3 from P1 towards Q0 (θ the turn at Q1).
    auto adjust = [&](Eigen::Index q0, Eigen::Index q1, Eigen::Index q2) {
        const Eigen::Vector2d a = (unit_polygon.row(q1) - unit_polygon.row(q0)).transpose();
        const Eigen::Vector2d b = (unit_polygon.row(q2) - unit_polygon.row(q1)).transpose();
        if (!(a.norm() > 0.0) || !(b.norm() > 0.0))
            fail_input(who, "zero-length edge next to point " + std::to_string(q1));
        const double turn = signed_turn(a, b);
        if (!(std::abs(turn) < std::numbers::pi / 2))
            fail_input(who, "turning angle " + full_precision(turn) + " at point " + std::to_string(q1) +
                                " must be below pi/2 in magnitude (|P0P1| = cos(theta0)/3 > 0)");
        p.row(q1) = unit_polygon.row(q2) + (2.0 / 3.0) * b.normalized().transpose() * -1.0;
        p.row(q0) = p.row(q1) - (std::cos(turn) / 3.0) * a.normalized().transpose();
    };
    adjust(0, 1, 2);
    adjust(n, n - 1, n - 2);
    return p;
}

RegionPoint classify_unit_polygon(double theta0, double theta1) {
    const std::array<double, 6> c = monotonicity_coefficients(theta0, theta1);
    RegionPoint r;
    r.condition29 = condition29(theta0, theta1) > 0.0;
    r.all_negative = std::all_of(c.begin(), c.end(), [](double v) { return v < 0.0; });
    r.c0_negative = c[0] < 0.0;
    r.c4_negative = c[4] < 0.0;
    r.c5_negative = c[5] < 0.0;
    r.exact =
        r.all_negative
            ? analysis::Trend::decreasing
            : analysis::trend_of(sign_on_unit_interval(BernsteinPolynomial(std::vector<double>(c.begin(), c.end()))));
    return r;
}

std::vector<RegionPoint> monotonicity_region(int n, double lo, double hi) {
    if (n < 2) fail_input("cagd::aesthetic::monotonicity_region", "n = " + std::to_string(n) + " < 2");
    require_angles(lo, hi, "cagd::aesthetic::monotonicity_region");
    std::vector<RegionPoint> out;
    out.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            out.push_back(classify_unit_polygon(lo + (hi - lo) * i / (n - 1), lo + (hi - lo) * j / (n - 1)));
    return out;
}

BSplineCurve uniform_cubic_bspline(const Eigen::MatrixXd& control) {
    if (control.rows() < 4)
        fail_input("cagd::aesthetic::uniform_cubic_bspline",
                   "needs at least 4 control points, got " + std::to_string(control.rows()));
    std::vector<double> knots;
    for (Eigen::Index i = 0; i < control.rows() + 4; ++i) knots.push_back(static_cast<double>(i));
    return BSplineCurve(3, knots, control);
}

BSplineCurve endpoint_interpolating_cubic_bspline(const Eigen::MatrixXd& control) {
    if (control.rows() < 4)
        fail_input("cagd::aesthetic::endpoint_interpolating_cubic_bspline",
                   "needs at least 4 control points, got " + std::to_string(control.rows()));
    const int spans = static_cast<int>(control.rows()) - 3;
    std::vector<double> knots{0.0, 0.0, 0.0};
    for (int i = 0; i <= spans; ++i) knots.push_back(i);
    for (int i = 0; i < 3; ++i) knots.push_back(spans);
    return BSplineCurve(3, knots, control);
}

const char* to_string(Guarantee g) {
    switch (g) {
        case Guarantee::monotone: return "monotone";
        case Guarantee::not_guaranteed: return "not_guaranteed";
        case Guarantee::not_applicable: return "not_applicable";
    }
    return "?";
}

MonotonicityReport cubic_bspline_curvature_monotonicity(const BSplineCurve& curve) {
    const char* who = "cagd::aesthetic::cubic_bspline_curvature_monotonicity";
    if (curve.degree() != 3 || curve.dimension() != 2) fail_input(who, "needs a planar cubic B-spline");
    const Eigen::MatrixXd& d = curve.control_points();
    if (!d.allFinite()) fail_input(who, "a control point coordinate is not finite");
    for (Eigen::Index k = 0; k + 1 < d.rows(); ++k)
        if (!((d.row(k + 1) - d.row(k)).norm() > 0.0))
            fail_input(who, "control points " + std::to_string(k) + " and " + std::to_string(k + 1) +
                                " coincide (zero-length edge)");
    MonotonicityReport report;
    int index = 0;
    bool any_inc = false, any_dec = false, any_bad = false, any_undetermined = false;
    for (const BezierCurve& piece : bezier_segments(curve)) {
        SegmentVerdict v;
        v.segment = index++;
        v.bezier = piece.control_points();
        v.polygon = equivalent_uniform_polygon(v.bezier);
        for (Eigen::Index k = 0; k < 3; ++k)
            v.edges[static_cast<std::size_t>(k)] = (v.polygon.row(k + 1) - v.polygon.row(k)).norm();
        const bool edges_ok = v.edges[0] > 0.0 && v.edges[1] > 0.0 && v.edges[2] > 0.0;
        if (edges_ok) {
            v.turn0 = signed_turn((v.polygon.row(1) - v.polygon.row(0)).transpose(),
                                  (v.polygon.row(2) - v.polygon.row(1)).transpose());
            v.turn1 = signed_turn((v.polygon.row(2) - v.polygon.row(1)).transpose(),
                                  (v.polygon.row(3) - v.polygon.row(2)).transpose());
            v.equal_edges = std::abs(v.edges[1] - v.edges[0]) <= 1e-9 * v.edges[0] &&
                            std::abs(v.edges[2] - v.edges[0]) <= 1e-9 * v.edges[0];
        }
        if (v.equal_edges && v.turn0 * v.turn1 > 0.0) {
            const double a = std::max(std::abs(v.turn0), std::abs(v.turn1)),
                         b = std::min(std::abs(v.turn0), std::abs(v.turn1));
            v.condition29_value = condition29(a, b);
            v.condition29_verdict = v.condition29_value > 0.0 ? Guarantee::monotone : Guarantee::not_guaranteed;
        }
        const BezierCurve unit(piece.control_points());
        const BernsteinPolynomial h = analysis::curvature_derivative_numerator(unit);
        for (std::size_t k = 0; k < 6; ++k)
            v.h_coefficients[k] = k < h.coefficients().size() ? h.coefficients()[k] : 0.0;
        bool all_neg = true, all_pos = true;
        for (double c : h.coefficients()) {
            all_neg = all_neg && c < 0.0;
            all_pos = all_pos && c > 0.0;
        }
        v.bernstein_verdict = (all_neg || all_pos) ? Guarantee::monotone : Guarantee::not_guaranteed;
        v.exact = analysis::trend_of(sign_on_unit_interval(h));
        any_inc = any_inc || v.exact == analysis::Trend::increasing;
        any_dec = any_dec || v.exact == analysis::Trend::decreasing;
        any_bad = any_bad || v.exact == analysis::Trend::not_monotone;
        any_undetermined = any_undetermined || v.exact == analysis::Trend::undetermined;
        report.segments.push_back(v);
    }
    if (any_bad || (any_inc && any_dec))
        report.whole_curve = analysis::Trend::not_monotone;
    else if (any_undetermined)
        report.whole_curve = analysis::Trend::undetermined;
    else if (any_inc)
        report.whole_curve = analysis::Trend::increasing;
    else if (any_dec)
        report.whole_curve = analysis::Trend::decreasing;
    else
        report.whole_curve = analysis::Trend::constant;
    return report;
}

}  // namespace cagd::aesthetic
