#include "cagd/analysis/curve_measures.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <string>

#include "cagd/analysis/frenet_jet.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/numeric/gauss_legendre.hpp"

namespace cagd::analysis {

namespace {
const numeric::GaussLegendreRule& rule20() {
    static const numeric::GaussLegendreRule rule(20);
    return rule;
}

std::vector<double> subdivided(const std::vector<double>& br, int pieces) {
    if (pieces < 1) fail_input("cagd::analysis", "pieces must be >= 1, got " + std::to_string(pieces));
    std::vector<double> out;
    for (std::size_t k = 0; k + 1 < br.size(); ++k)
        for (int j = 0; j < pieces; ++j) out.push_back(br[k] + (br[k + 1] - br[k]) * j / pieces);
    out.push_back(br.back());
    return out;
}

std::vector<double> clipped_breaks(const Curve& c, double a, double b) {
    std::vector<double> out{a};
    for (double t : c.breakpoints())
        if (t > a && t < b) out.push_back(t);
    out.push_back(b);
    return out;
}

// The integrands below fill a JetMatrix (no allocation per quadrature node).
double speed(const Curve& c, double t) {
    JetMatrix D;
    c.derivatives_into(t, 1, D);
    return D.row(0).norm();
}
}  // namespace

namespace {
// The geometry at t from r' and r'' (rows 0, 1 of Curve::derivatives); throws naming `who` at a
// singular point.
FrenetJet regular_frenet(const Curve& c, double t, const char* who) {
    JetMatrix D;
    c.derivatives_into(t, 2, D);
    const FrenetJet f = frenet_jet(D);
    if (!f.regular)
        fail_input(who, "r'(t) = 0 at t = " + full_precision(t) + "; curvature undefined at a singular point");
    return f;
}

double bending_density(const Curve& c, double t) {  // κ² |r'|, the integrand of ∫ κ² ds in t
    const FrenetJet f = regular_frenet(c, t, "cagd::analysis::curvature");
    return f.curvature * f.curvature * f.speed;
}
}  // namespace

double curvature(const Curve& c, double t) {
    return std::abs(regular_frenet(c, t, "cagd::analysis::curvature").curvature);
}

Eigen::VectorXd curvature_vector(const Eigen::MatrixXd& J) {
    if (J.rows() < 3)
        fail_input("cagd::analysis::curvature_vector",
                   "needs a jet of order >= 2, got " + std::to_string(J.rows() - 1));
    const Eigen::VectorXd d1 = J.row(1).transpose(), d2 = J.row(2).transpose();
    const double s2 = d1.squaredNorm();
    if (!(s2 > 0.0)) fail_input("cagd::analysis::curvature_vector", "r' = 0: curvature undefined at a singular point");
    return (d2 - (d2.dot(d1) / s2) * d1) / s2;
}

double signed_curvature(const Curve& c, double t) {
    if (c.dimension() != 2)
        fail_input("cagd::analysis::signed_curvature",
                   "needs a planar curve, dimension is " + std::to_string(c.dimension()));
    return regular_frenet(c, t, "cagd::analysis::signed_curvature").curvature;
}

double arc_length(const Curve& c, double a, double b, int pieces) {
    if (!(a >= c.t_min() && b <= c.t_max() && a <= b))
        fail_input("cagd::analysis::arc_length",
                   "interval [" + full_precision(a) + ", " + full_precision(b) + "] not inside the domain");
    return rule20().integrate_piecewise([&](double t) { return speed(c, t); },
                                        subdivided(clipped_breaks(c, a, b), pieces));
}

double arc_length(const Curve& c, int pieces) { return arc_length(c, c.t_min(), c.t_max(), pieces); }

// Romberg per piece: 24 levels (1.7·10^7 evaluations) before reporting no convergence; the
// absolute tolerance at the underflow edge only lets a zero-length piece converge.
constexpr int kRombergLevels = 24;
constexpr double kRombergAbsTol = 1e-300;
// Adaptive Gauss–Kronrod (31 points) bisects to depth 15; accurate_arc_length asks rel 1e-12,
// a few hundred ε: what the error estimate of a sum of pieces can still certify.
constexpr int kKronrodDepth = 15;
constexpr double kAccurateRelTol = 1e-12;

double adaptive_arc_length(const Curve& c, double rel_tol) {
    const std::vector<double> br = c.breakpoints();
    double total = 0.0;
    for (std::size_t k = 0; k + 1 < br.size(); ++k)
        total += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
            [&](double t) { return speed(c, t); }, br[k], br[k + 1], kKronrodDepth, rel_tol);
    return total;
}

numeric::RombergResult romberg_arc_length(const Curve& c, double rel_tol) {
    numeric::RombergResult total;
    const std::vector<double> br = c.breakpoints();
    for (std::size_t k = 0; k + 1 < br.size(); ++k) {
        const auto r = numeric::romberg([&](double t) { return speed(c, t); }, br[k], br[k + 1], rel_tol,
                                        kRombergAbsTol, kRombergLevels);
        total.value += r.value;
        total.error_estimate += r.error_estimate;
        total.evaluations += r.evaluations;
        total.levels = std::max(total.levels, r.levels);
        if (!r.outcome.ok()) total.outcome = r.outcome;
    }
    return total;
}

ArcLength accurate_arc_length(const Curve& c) {
    ArcLength a;
    const std::vector<double> br = c.breakpoints();
    for (std::size_t k = 0; k + 1 < br.size(); ++k) {
        double error = 0.0;
        a.value += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
            [&](double t) { return speed(c, t); }, br[k], br[k + 1], kKronrodDepth, kAccurateRelTol, &error);
        a.error_estimate += error;
    }
    return a;
}

double area_closed_by_chord(const Curve& c) {
    const Eigen::VectorXd first = c.point(c.t_min()), last = c.point(c.t_max());
    return enclosed_area(c) + 0.5 * (last(0) * first(1) - last(1) * first(0));
}

double enclosed_area(const Curve& c) {
    if (c.dimension() != 2)
        fail_input("cagd::analysis::enclosed_area",
                   "needs a planar curve, dimension is " + std::to_string(c.dimension()));
    return 0.5 * rule20().integrate_piecewise(
                     [&](double t) {
                         JetMatrix J;
                         c.jet_into(t, 1, J);
                         return J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
                     },
                     c.breakpoints());
}

double bending_energy(const Curve& c, double a, double b, int pieces) {
    if (!(a >= c.t_min() && b <= c.t_max() && a <= b))
        fail_input("cagd::analysis::bending_energy",
                   "interval [" + full_precision(a) + ", " + full_precision(b) + "] not inside the domain");
    return rule20().integrate_piecewise([&](double t) { return bending_density(c, t); },
                                        subdivided(clipped_breaks(c, a, b), pieces));
}

double piece_arc_length(const Curve& c, double a, double b, int pieces) {
    return rule20().integrate_piecewise([&](double t) { return speed(c, t); }, subdivided({a, b}, pieces));
}

double piece_bending_energy(const Curve& c, double a, double b, int pieces) {
    return rule20().integrate_piecewise([&](double t) { return bending_density(c, t); }, subdivided({a, b}, pieces));
}

std::pair<double, double> piece_length_and_bending_energy(const Curve& c, double a, double b, int pieces) {
    return rule20().integrate_piecewise(
        [&](double t) {
            const FrenetJet f = regular_frenet(c, t, "cagd::analysis::curvature");
            return std::pair<double, double>{f.speed, f.curvature * f.curvature * f.speed};
        },
        subdivided({a, b}, pieces));
}

double bending_energy(const Curve& c, int pieces) { return bending_energy(c, c.t_min(), c.t_max(), pieces); }

double max_distance_same_parameter(const Curve& a, const Curve& b, double t0, double t1, int samples) {
    if (samples < 2) fail_input("cagd::analysis::max_distance_same_parameter", "samples must be >= 2");
    double worst = 0.0;
    for (int i = 0; i < samples; ++i) {
        const double t = t0 + (t1 - t0) * i / (samples - 1);
        worst = std::max(worst, (a.point(t) - b.point(t)).norm());
    }
    return worst;
}

double max_distance_same_parameter(const Curve& a, const Curve& b, int samples_per_piece) {
    const double t0 = std::max(a.t_min(), b.t_min()), t1 = std::min(a.t_max(), b.t_max());
    std::set<double> br{t0, t1};
    for (double t : a.breakpoints())
        if (t > t0 && t < t1) br.insert(t);
    for (double t : b.breakpoints())
        if (t > t0 && t < t1) br.insert(t);
    const std::vector<double> v(br.begin(), br.end());
    double worst = 0.0;
    for (std::size_t k = 0; k + 1 < v.size(); ++k)
        worst = std::max(worst, max_distance_same_parameter(a, b, v[k], v[k + 1], samples_per_piece + 1));
    return worst;
}

double normal_offset(const Curve& a, const Curve& b, double t) {
    if (a.dimension() != 2 || b.dimension() != 2) fail_input("cagd::analysis::normal_offset", "needs planar curves");
    const Eigen::MatrixXd J = b.jet(t, 1);
    const double speed_b = J.row(1).norm();
    if (!(speed_b > 0.0)) fail_input("cagd::analysis::normal_offset", "b'(t) = 0 at t = " + full_precision(t));
    const Eigen::Vector2d normal(-J(1, 1) / speed_b, J(1, 0) / speed_b);
    return (a.point(t) - b.point(t)).dot(normal);
}

double tangent_turns(const Curve& c, int samples_per_piece) {
    const char* who = "cagd::analysis::tangent_turns";
    if (c.dimension() != 2) fail_input(who, "needs a planar curve, dimension is " + std::to_string(c.dimension()));
    if (samples_per_piece < 1) fail_input(who, "samples_per_piece = " + std::to_string(samples_per_piece) + " < 1");
    const std::vector<double> br = c.breakpoints();
    JetMatrix D;
    double turn = 0.0, px = 0.0, py = 0.0;
    bool first = true;
    for (std::size_t k = 0; k + 1 < br.size(); ++k)
        for (int j = k == 0 ? 0 : 1; j <= samples_per_piece; ++j) {
            const double t = br[k] + (br[k + 1] - br[k]) * j / samples_per_piece;
            c.derivatives_into(t, 1, D);
            const double x = D(0, 0), y = D(0, 1);
            if (!(x * x + y * y > 0.0))
                fail_input(who, "r'(t) = 0 at t = " + full_precision(t) + ": the tangent is undefined there");
            if (!first) turn += std::atan2(px * y - py * x, px * x + py * y);
            px = x, py = y, first = false;
        }
    return turn / (2.0 * std::numbers::pi);
}

int polygon_turning_number(const PointList& p) {
    if (p.cols() != 2 || p.rows() < 3)
        fail_input("cagd::analysis::polygon_turning_number", "needs at least 3 planar points");
    const Eigen::Index n = p.rows();
    double turn = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Vector2d a = p.row((i + 1) % n) - p.row(i), b = p.row((i + 2) % n) - p.row((i + 1) % n);
        turn += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
    return static_cast<int>(std::lround(turn / (2.0 * std::numbers::pi)));
}

std::string closed_curve_anomaly(const Curve& c, const PointList& points, double length) {
    double perimeter = 0.0;
    for (Eigen::Index i = 0; i < points.rows(); ++i)
        perimeter += (points.row((i + 1) % points.rows()) - points.row(i)).norm();
    const long curve_turns = std::lround(tangent_turns(c)), polygon_turns = polygon_turning_number(points);
    std::string reason;
    if (curve_turns != polygon_turns)
        reason =
            "turning number " + std::to_string(curve_turns) + " against the polygon's " + std::to_string(polygon_turns);
    if (length > kLoopingLengthFactor * perimeter) {
        char ratio[32];
        std::snprintf(ratio, sizeof ratio, "%.3g", length / perimeter);
        reason += (reason.empty() ? "" : "; ") + std::string("length ") + ratio +
                  " × the polygon's perimeter (more than " + std::to_string(kLoopingLengthFactor).substr(0, 3) + ")";
    }
    return reason;
}

}  // namespace cagd::analysis
