#include "compare/interpolation_methods.hpp"

#include <array>
#include <cmath>
// Boost 1.74's pchip.hpp and makima.hpp call isnan unqualified on a double, which only compiles if
// std::isnan is visible where the templates are defined.
using std::isnan;
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/pchip.hpp>
#include <stdexcept>

#include "fairness/pseudo_spline.hpp"
#include "intrinsic/curvature_profile_design.hpp"
#include "locality/locality_spline.hpp"
#include "spline/hermite_spline.hpp"
#include "spline/hosaka_spline.hpp"

namespace cagd::compare {

const char* to_string(Invariance i) {
    switch (i) {
        case Invariance::none: return "none claimed";
        case Invariance::translation_scale: return "translation, uniform scaling";
        case Invariance::similarity: return "similarity (translation, rotation, uniform scaling)";
        case Invariance::affine: return "affine";
    }
    return "?";
}

const std::vector<MethodInfo>& interpolation_methods() {
    using I = Invariance;
    static const std::vector<MethodInfo> methods = {
        {"pseudo-spline-none", "pseudo_energy eq (4)-(11), 36-node table, tangents not optimised", 0, 1, "u (unit spans)", I::similarity, true, 2, 3, 2},
        {"pseudo-spline-exact", "pseudo_energy eq (4)-(12), 36-node table, exact tangent optimisation", 0, 1, "u (unit spans)", I::none, true, 2, 3, 2},
        {"pseudo-spline-approx", "pseudo_energy eq (4)-(12), 36-node table, 3-point approximation", 0, 1, "u (unit spans)", I::similarity, true, 2, 3, 2},
        {"cubic-a", "pseudo_energy sec 4.2 cubic spline A (natural, uniform parameter)", 2, 2, "uniform", I::affine, true, 2, 3, 3},
        {"cubic-b", "pseudo_energy sec 4.2 cubic spline B (natural, chord length)", 2, 2, "chord length", I::similarity, true, 2, 3, 3},
        {"hermite-a", "pseudo_energy sec 4.2 Hermite curve A (neighbour chord tangents)", 0, 1, "u (unit spans)", I::similarity, true, 2, 3, 3},
        {"hermite-b", "pseudo_energy sec 4.2 Hermite curve B (circle tangents)", 0, 1, "u (unit spans)", I::similarity, true, 3, 3, 3},
        {"s-spline-m1", "sb2_locality eq (12), S-spline, m = 1, natural ends", 2, 2, "uniform", I::affine, true, 2, 3, 3},
        {"s-spline-m2", "sb2_locality eq (12), S-spline, m = 2, natural ends", 2, 2, "uniform", I::affine, true, 2, 3, 3},
        {"s-spline-m4", "sb2_locality eq (12)-(13), S-spline, m = 4, natural ends", 2, 2, "uniform", I::affine, true, 2, 3, 3},
        {"b2-spline-m1", "sb2_locality eq (12), B2-spline, m = 1, natural ends", 2, 2, "uniform", I::affine, true, 2, 3, 3},
        {"b2-spline-m2", "sb2_locality eq (12), B2-spline, m = 2, natural ends", 2, 2, "uniform", I::affine, true, 2, 3, 3},
        {"b2-spline-m4", "sb2_locality eq (12)-(13), B2-spline, m = 4, natural ends", 2, 2, "uniform", I::affine, true, 2, 3, 3},
        {"hosaka-c2-chord", "hosaka eq (18)-(20), scale factors k_i of eq (19)", 2, 2, "chord length", I::similarity, true, 2, 3, 3},
        {"hosaka-c2-unit", "hosaka eq (20) with k_i = 1", 2, 2, "uniform", I::affine, true, 2, 3, 3},
        {"curvature-profile", "curvature_profile sec 2-4, free spans (clothoid spline), natural ends", 2, 2, "arc length", I::similarity, true, 2, 3, 2},
        {"boost-pchip", "Boost.Math pchip on x(t), y(t)", 1, 0, "chord length", I::translation_scale, false, 4, 0, 3},
        {"boost-makima", "Boost.Math makima on x(t), y(t)", 1, 0, "chord length", I::translation_scale, false, 4, 0, 3},
        {"boost-catmull-rom", "Boost.Math catmull_rom, centripetal (alpha = 1/2)", 1, 0, "centripetal (sum of sqrt chord)", I::similarity, true, 4, 4, 3},
    };
    return methods;
}

const MethodInfo& method_info(const std::string& name) {
    std::string known;
    for (const MethodInfo& m : interpolation_methods()) {
        if (m.name == name) return m;
        known += (known.empty() ? "" : ", ") + m.name;
    }
    fail_input("cagd::compare::method_info", "unknown method '" + name + "'; known: " + known);
}

namespace {

const fairness::PseudoSplineTables& pseudo_spline_tables() {
    // The 36-node fast table, built once per process (about 0.2 s on two threads).
    static const fairness::PseudoSplineTables tables =
        fairness::PseudoSplineTables::from(fairness::PseudoEnergyTable::build({36, fairness::NodePlacement::periodic}, fairness::TableMethod::fast));
    return tables;
}

std::vector<double> unit_nodes(Eigen::Index nodes) {
    std::vector<double> u(static_cast<std::size_t>(nodes));
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = static_cast<double>(i);
    return u;
}

// Chord lengths |P_{k+1} − P_k| of the spans (closed: the closing span last).
std::vector<double> chord_lengths(const PointList& p, bool closed) {
    std::vector<double> h;
    const Eigen::Index n = p.rows(), spans = closed ? n : n - 1;
    for (Eigen::Index k = 0; k < spans; ++k) h.push_back((p.row((k + 1) % n) - p.row(k)).norm());
    return h;
}

Interpolant unit_span_interpolant(std::shared_ptr<const Curve> curve, Eigen::Index nodes, std::vector<double> dtau_du) {
    return {std::move(curve), unit_nodes(nodes), std::move(dtau_du)};
}

// A piecewise cubic through the points with τ-derivatives `slopes` at the nodes (rows as the points;
// closed: the closing node's slope is row 0) and τ-lengths h per span, in unit-span Hermite form.
Interpolant hermite_from_slopes(const PointList& p, const Eigen::MatrixXd& slopes, const std::vector<double>& h, bool closed) {
    const Eigen::Index n = p.rows(), spans = static_cast<Eigen::Index>(h.size());
    Eigen::MatrixXd nodes(spans + 1, p.cols()), d0(spans, p.cols()), d1(spans, p.cols());
    for (Eigen::Index k = 0; k <= spans; ++k) nodes.row(k) = p.row(k % n);
    for (Eigen::Index k = 0; k < spans; ++k) {
        const double hk = h[static_cast<std::size_t>(k)];
        d0.row(k) = hk * slopes.row(k);
        d1.row(k) = hk * slopes.row(closed ? (k + 1) % n : k + 1);
    }
    return unit_span_interpolant(std::make_shared<spline::PiecewiseHermiteCurve>(nodes, d0, d1), spans + 1, h);
}

// Boost's pchip / makima on each coordinate as a function of the chord-length parameter.
template <class Interpolator>
Interpolant componentwise_chord_interpolant(const PointList& p) {
    const std::vector<double> h = chord_lengths(p, false);
    std::vector<double> tau{0.0};
    for (double hk : h) tau.push_back(tau.back() + hk);
    Eigen::MatrixXd slopes(p.rows(), p.cols());
    for (Eigen::Index c = 0; c < p.cols(); ++c) {
        std::vector<double> x = tau, y(p.col(c).data(), p.col(c).data() + p.rows());
        const Interpolator f(std::move(x), std::move(y));
        for (Eigen::Index k = 0; k < p.rows(); ++k) slopes(k, c) = f.prime(tau[static_cast<std::size_t>(k)]);
    }
    return hermite_from_slopes(p, slopes, h, false);
}

template <std::size_t D>
Interpolant catmull_rom_interpolant(const PointList& p, bool closed) {
    using Point = std::array<double, D>;
    std::vector<Point> pts(static_cast<std::size_t>(p.rows()));
    for (Eigen::Index k = 0; k < p.rows(); ++k)
        for (std::size_t c = 0; c < D; ++c) pts[static_cast<std::size_t>(k)][c] = p(k, static_cast<Eigen::Index>(c));
    const boost::math::catmull_rom<Point> cr(std::move(pts), closed, 0.5);
    const Eigen::Index n = p.rows(), spans = closed ? n : n - 1;
    std::vector<double> h;
    for (Eigen::Index k = 0; k < spans; ++k)
        h.push_back((k + 1 == n ? cr.max_parameter() : cr.parameter_at_point(static_cast<std::size_t>(k + 1))) - cr.parameter_at_point(static_cast<std::size_t>(k)));
    Eigen::MatrixXd slopes(n, p.cols());
    for (Eigen::Index k = 0; k < n; ++k) {
        // prime at the last open node is the last span's end derivative (Boost evaluates the span
        // on the left at s = max_parameter); every other node is a span start.
        const Point d = cr.prime(cr.parameter_at_point(static_cast<std::size_t>(k)));
        for (std::size_t c = 0; c < D; ++c) slopes(k, static_cast<Eigen::Index>(c)) = d[c];
    }
    return hermite_from_slopes(p, slopes, h, closed);
}

Interpolant curvature_profile_interpolant(const intrinsic::CurvatureProfileSolution& sol, const intrinsic::KnotLayout& layout) {
    const std::vector<double>& w = sol.curve->breakpoints();
    std::vector<double> nodes;
    for (int j = 0; j <= layout.spans(); ++j) nodes.push_back(w[static_cast<std::size_t>(layout.first_segment(j))]);
    return {std::make_shared<intrinsic::IntrinsicCurve>(*sol.curve), nodes, std::vector<double>(static_cast<std::size_t>(layout.spans()), 1.0)};
}

}  // namespace

InterpolationResult interpolate(const std::string& method, const PointList& points, bool closed) {
    const MethodInfo& info = method_info(method);
    const std::string who = "cagd::compare::interpolate(" + method + ")";
    if (closed && !info.supports_closed) fail_input(who, "draws open curves only (--closed is not supported)");
    require_valid_points(points, closed ? info.min_points_closed : info.min_points, true, closed, who);
    if (points.cols() < 2 || points.cols() > info.max_dimension)
        fail_input(who, "needs points of dimension 2" + std::string(info.max_dimension == 3 ? " or 3" : "") + ", got " + std::to_string(points.cols()));
    const Eigen::Index n = points.rows(), nodes = closed ? n + 1 : n;
    const std::vector<double> ones(static_cast<std::size_t>(nodes - 1), 1.0);
    InterpolationResult r;
    using fairness::InterpolationMethod;
    if (method.rfind("pseudo-spline-", 0) == 0) {
        const auto mode = method == "pseudo-spline-none" ? fairness::TangentOptimization::none
                          : method == "pseudo-spline-exact" ? fairness::TangentOptimization::exact
                                                            : fairness::TangentOptimization::approximate;
        const fairness::PseudoSplineTables& t = pseudo_spline_tables();
        auto c = std::make_shared<spline::PiecewiseHermiteCurve>(fairness::pseudo_spline(points, t.oracle(), mode, closed).curve);
        r.interpolant = unit_span_interpolant(std::move(c), nodes, ones);
    } else if (method == "cubic-a" || method == "cubic-b") {
        const bool chord = method == "cubic-b";
        auto c = std::make_shared<spline::PiecewiseHermiteCurve>(
            spline::cubic_spline_interpolant(points, chord ? spline::ParameterSpacing::chord_length : spline::ParameterSpacing::uniform, closed));
        r.interpolant = unit_span_interpolant(std::move(c), nodes, chord ? chord_lengths(points, closed) : ones);
    } else if (method == "hermite-a" || method == "hermite-b") {
        const auto rule = method == "hermite-a" ? spline::TangentRule::chord_of_neighbours : spline::TangentRule::circle;
        auto c = std::make_shared<spline::PiecewiseHermiteCurve>(
            spline::hermite_interpolant(points, spline::hermite_tangent_directions(points, rule, closed), closed));
        r.interpolant = unit_span_interpolant(std::move(c), nodes, ones);
    } else if (method.rfind("s-spline-m", 0) == 0 || method.rfind("b2-spline-m", 0) == 0) {
        locality::Options o;
        o.form = method[0] == 's' ? locality::SplineForm::s_spline : locality::SplineForm::b2_spline;
        const int m = method.back() - '0';
        o.m = {{m, m}};
        o.closed = closed;
        auto c = std::make_shared<BSplineCurve>(locality::interpolate(points, o).curve);
        r.interpolant = unit_span_interpolant(std::move(c), nodes, ones);
    } else if (method == "hosaka-c2-chord" || method == "hosaka-c2-unit") {
        spline::HosakaSplineOptions o;
        o.scale = method == "hosaka-c2-chord" ? spline::HosakaScale::chord : spline::HosakaScale::unit;
        o.closed = closed;
        auto c = std::make_shared<spline::HosakaCurve>(spline::hosaka_c2_spline(points, o).curve);
        r.interpolant = unit_span_interpolant(std::move(c), nodes, o.scale == spline::HosakaScale::chord ? chord_lengths(points, closed) : ones);
    } else if (method == "curvature-profile") {
        using namespace intrinsic;
        const std::vector<SegmentShape> free(static_cast<std::size_t>(nodes - 1), SegmentShape::free);
        const KnotLayout layout = span_layout(free);
        CurvatureProfileProblem problem{points, layout, segment_shapes(layout, free), {}, closed, 0};
        add_natural_open_ends(problem);
        require_valid_problem(problem, who);
        const CurvatureProfileSolution sol = solve_curvature_profile_auto(problem);
        r.outcome = sol.outcome;
        if (!sol.outcome.ok() || !sol.curve) return r;
        r.interpolant = curvature_profile_interpolant(sol, layout);
    } else {
        try {
            if (method == "boost-pchip") r.interpolant = componentwise_chord_interpolant<boost::math::interpolators::pchip<std::vector<double>>>(points);
            else if (method == "boost-makima") r.interpolant = componentwise_chord_interpolant<boost::math::interpolators::makima<std::vector<double>>>(points);
            else r.interpolant = points.cols() == 2 ? catmull_rom_interpolant<2>(points, closed) : catmull_rom_interpolant<3>(points, closed);
        } catch (const std::domain_error& e) {   // Boost's own precondition checks
            fail_input(who, std::string("Boost.Math refused the points: ") + e.what());
        }
    }
    return r;
}

}  // namespace cagd::compare
