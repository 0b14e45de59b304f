#include "cagd/fairness/pseudo_spline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <typeinfo>

#include "cagd/core/errors.hpp"
#include "cagd/fairness/detail/tangent_minimisation.hpp"

namespace cagd::fairness {

const char* to_string(TangentOptimization m) {
    switch (m) {
        case TangentOptimization::none: return "none";
        case TangentOptimization::exact: return "exact";
        case TangentOptimization::approximate: return "approx";
    }
    return "?";
}

TangentOptimization parse_tangent_optimization(const std::string& text) {
    if (text == "none") return TangentOptimization::none;
    if (text == "exact") return TangentOptimization::exact;
    if (text == "approx" || text == "approximate") return TangentOptimization::approximate;
    fail_input("cagd::fairness::parse_tangent_optimization", "'" + text + "' is not one of none, exact, approx");
}

TableValue ExactOracle::segment(double theta0, double theta1) const {
    const PseudoEnergyMinimum m = minimize_pseudo_energy(theta0, theta1);
    if (!m.outcome.ok())
        fail_input("cagd::fairness::ExactOracle::segment", "no minimum at (" + full_precision(theta0) + ", " +
                                                               full_precision(theta1) + "): " + m.outcome.message);
    return TableValue{m.pseudo_energy, m.r0, m.r1, m.length, m.area, m.type};
}

std::pair<double, double> ExactOracle::angle_minimum(double theta) const {
    const AngleMinimum a = minimize_over_end_angle(theta);
    if (!a.outcome.ok())
        fail_input("cagd::fairness::ExactOracle::angle_minimum",
                   "no J(theta) at " + full_precision(theta) + ": " + a.outcome.message);
    return {a.pseudo_energy, a.theta1};
}

double turning_angle(const Eigen::Vector2d& incoming, const Eigen::Vector2d& outgoing) {
    return wrap_angle(std::atan2(outgoing.y(), outgoing.x()) - std::atan2(incoming.y(), incoming.x()));
}

double PseudoSpline::length_from_tables() const {
    double s = 0.0;
    for (std::size_t i = 0; i < spans.size(); ++i) s += chord_length[i] * spans[i].value.length;
    return s;
}

double PseudoSpline::pseudo_energy_from_tables() const {
    double s = 0.0;
    for (std::size_t i = 0; i < spans.size(); ++i) s += chord_length[i] * spans[i].value.pseudo_energy;
    return s;
}

namespace {

// S_0 of eq (21) over a curve's nodes (shoelace; for a closed curve the last node is the first).
double signed_polygon_area(const Eigen::MatrixXd& p) {
    double s = 0.0;
    for (Eigen::Index i = 0; i + 1 < p.rows(); ++i) s += p(i, 0) * p(i + 1, 1) - p(i, 1) * p(i + 1, 0);
    const Eigen::Index n = p.rows() - 1;
    s += p(n, 0) * p(0, 1) - p(n, 1) * p(0, 0);  // zero for a closed curve (node n = node 0)
    return 0.5 * s;
}

}  // namespace

double PseudoSpline::polygon_area() const { return signed_polygon_area(curve.nodes()); }

double PseudoSpline::area_from_tables() const {
    double s = polygon_area();
    for (std::size_t i = 0; i < spans.size(); ++i) s -= chord_length[i] * chord_length[i] * spans[i].value.area;
    return s;
}

namespace {

constexpr double kStraight = 1e-12;

using detail::minimise_w;

}  // namespace

namespace {

// What the construction produces besides the curve. `spans` null: the per-span records are not
// kept, only their sums (pseudo_spline_curve).
struct ConstructionOutputs {
    std::vector<double>& alpha;
    std::vector<double>& chord_angle;
    std::vector<double>& chord_length;
    std::vector<PseudoSplineSpan>* spans;
    long& oracle_calls;
    // Σ l_i L_i, Σ l_i J_i and S_0 − Σ l_i² S_i, accumulated in span order as the PseudoSpline
    // members sum them (so the two agree bit for bit).
    double length = 0.0, pseudo_energy = 0.0, area = 0.0;
};

// `validated`: the points have passed require_valid_points(points, closed ? 3 : 2, true, closed, …).
spline::PiecewiseHermiteCurve construct(const char* who, const PointList& points, const SegmentOracle& oracle,
                                        TangentOptimization mode, bool closed, TangentTie tie,
                                        ConstructionOutputs& result, bool validated = false) {
    if (!validated) require_valid_points(points, closed ? 3 : 2, true, closed, who);
    if (points.cols() != 2) fail_input(who, "needs planar points (2 columns), got " + std::to_string(points.cols()));
    if (!(tie.position >= 0.0 && tie.position <= 1.0))
        fail_input(who, "tie.position must lie in [0, 1], got " + full_precision(tie.position));
    const Eigen::Index np = points.rows();
    const Eigen::Index spans = closed ? np : np - 1;
    // Neighbours by comparison, not modulo (an integer division per use, several per point).
    const auto next = [&](Eigen::Index i) { return i + 1 == np ? Eigen::Index{0} : i + 1; };
    const auto incoming = [&](Eigen::Index i) { return i == 0 ? spans - 1 : i - 1; };  // chord ending at point i

    // (Chords and tangents are recomputed where needed rather than stored: at 10^6 points the
    // fresh memory of every array costs page faults, a quarter of the construction's time.)
    const auto chord = [&](Eigen::Index i) -> Eigen::Vector2d {
        return (points.row(next(i)) - points.row(i)).transpose();
    };
    std::vector<double>&phi = result.chord_angle, &len = result.chord_length;
    phi.resize(static_cast<std::size_t>(spans));
    len.resize(static_cast<std::size_t>(spans));
    for (Eigen::Index i = 0; i < spans; ++i) {
        const Eigen::Vector2d c = chord(i);
        phi[static_cast<std::size_t>(i)] = std::atan2(c.y(), c.x());
        len[static_cast<std::size_t>(i)] = c.norm();
    }
    // Turn at point i (i with an incoming and an outgoing chord): φ_i − φ_{i−1}, wrapped.
    const auto turn = [&](Eigen::Index i) {
        const Eigen::Index in = incoming(i);  // i < spans: the chord leaving point i is chord i
        const double t = wrap_angle(phi[static_cast<std::size_t>(i)] - phi[static_cast<std::size_t>(in)]);
        if (std::abs(std::abs(t) - std::numbers::pi) <= 1e-12)
            fail_input(who, "the points turn by pi at point " + std::to_string(i) +
                                " (a hairpin): no tangent direction between the chords, the pseudo-energy table is "
                                "undefined there");
        return t;
    };

    std::vector<double>& alphas = result.alpha;
    alphas.assign(static_cast<std::size_t>(np), 0.0);
    if (result.spans) result.spans->reserve(static_cast<std::size_t>(spans));
    // The paper's tables (TableOracle itself, not a subclass) are called without the virtual call:
    // eq (12) reads J(θ) six times per point in the approximate mode.
    const TableOracle* table =
        typeid(oracle) == typeid(TableOracle) ? static_cast<const TableOracle*>(&oracle) : nullptr;
    const auto J = [&](double theta) {
        ++result.oracle_calls;
        const double t = wrap_angle(theta);
        return table ? table->TableOracle::angle_energy(t) : oracle.angle_energy(t);
    };

    // Interior tangent directions (eq 12). J(θ) linear between these angles makes the exact mode's
    // minimisation a finite search (pseudo_spline.hpp).
    const std::vector<double>* breakpoints = oracle.angle_energy_nodes();
    const Eigen::Index first = closed ? 0 : 1, last = closed ? np - 1 : np - 2;
    for (Eigen::Index i = first; i <= last; ++i) {
        const double tau = turn(i);  // φ_i − φ_{i−1}
        const std::size_t in = static_cast<std::size_t>(incoming(i)), out = static_cast<std::size_t>(i);
        double a = 0.0;
        if (std::abs(tau) > 0.0) {
            if (mode == TangentOptimization::none) {
                const Eigen::Vector2d d =
                    chord(static_cast<Eigen::Index>(in)) + chord(static_cast<Eigen::Index>(out));  // P_{i+1} − P_{i−1}
                a = wrap_angle(std::atan2(d.y(), d.x()) - phi[out]);
            } else {
                const auto w = [&](double alpha) { return len[in] * J(alpha + tau) + len[out] * J(alpha); };
                const double lo = std::min(0.0, -tau), hi = std::max(0.0, -tau);
                a = mode == TangentOptimization::exact && breakpoints
                        ? detail::minimise_piecewise_linear_w(w, lo, hi, tau, *breakpoints, tie)
                        : minimise_w(w, lo, hi, mode, tie);
            }
        }
        alphas[static_cast<std::size_t>(i)] = a;
    }
    // End tangents (eq 13).
    if (!closed) {
        if (np == 2) {
            alphas[0] = alphas[1] = 0.0;
        } else {
            const double end_angle_at_p1 = wrap_angle(alphas[1] + phi[1] - phi[0]);
            alphas[0] = std::abs(end_angle_at_p1) <= kStraight ? 0.0 : oracle.angle_minimum(end_angle_at_p1).second;
            const double a = alphas[static_cast<std::size_t>(np - 2)];
            alphas[static_cast<std::size_t>(np - 1)] = std::abs(a) <= kStraight ? 0.0 : oracle.angle_minimum(a).second;
        }
    }

    // Unit tangent at a point: direction φ_i + α_i (the last point of an open curve: φ_{n−1} + α_n,
    // α_n being relative to the incoming chord). The span loop carries each from the span that
    // ends at a point to the one that starts there.
    const auto tangent = [&](Eigen::Index i) {
        const double psi =
            phi[static_cast<std::size_t>(std::min<Eigen::Index>(i, spans - 1))] + alphas[static_cast<std::size_t>(i)];
        return Eigen::Vector2d(std::cos(psi), std::sin(psi));
    };
    Eigen::Vector2d start_tangent = tangent(0);
    // Spans (eq 9, 10).
    Eigen::MatrixXd nodes(spans + 1, 2), d0(spans, 2), d1(spans, 2);
    nodes.topRows(spans) = points.topRows(spans);
    nodes.row(spans) = points.row(closed ? 0 : spans);
    result.area = signed_polygon_area(nodes);
    for (Eigen::Index i = 0; i < spans; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        PseudoSplineSpan s;
        s.theta0 = wrap_angle(alphas[k]);
        const bool last_open = !closed && i == spans - 1;
        // next(i) < spans whenever the span is not the last of an open curve
        s.theta1 = last_open ? wrap_angle(alphas[k + 1])
                             : wrap_angle(alphas[static_cast<std::size_t>(next(i))] +
                                          phi[static_cast<std::size_t>(next(i))] - phi[k]);
        if (std::abs(s.theta0) <= kStraight && std::abs(s.theta1) <= kStraight) {
            s.value = TableValue{0.0, 1.0, 1.0, 1.0, 0.0, SegmentType::c};
        } else {
            try {
                s.value = oracle.segment(s.theta0, s.theta1);
            } catch (const InvalidInput& e) {
                fail_input(who, "span " + std::to_string(i) + ": " + e.what());
            }
        }
        const double l = len[k];
        const Eigen::Vector2d end_tangent = tangent(next(i));
        d0.row(i) = (l * s.value.r0) * start_tangent.transpose();
        d1.row(i) = (l * s.value.r1) * end_tangent.transpose();
        start_tangent = end_tangent;
        result.length += l * s.value.length;
        result.pseudo_energy += l * s.value.pseudo_energy;
        result.area -= l * l * s.value.area;
        if (result.spans) result.spans->push_back(s);
    }
    return spline::PiecewiseHermiteCurve(std::move(nodes), std::move(d0), std::move(d1));
}

}  // namespace

PseudoSpline pseudo_spline(const PointList& points, const SegmentOracle& oracle, TangentOptimization mode, bool closed,
                           TangentTie tie) {
    PseudoSpline ps{spline::PiecewiseHermiteCurve(Eigen::MatrixXd::Zero(2, 2), Eigen::MatrixXd::Zero(1, 2),
                                                  Eigen::MatrixXd::Zero(1, 2)),
                    {},
                    {},
                    {},
                    {},
                    0};
    ConstructionOutputs out{ps.alpha, ps.chord_angle, ps.chord_length, &ps.spans, ps.oracle_calls};
    ps.curve = construct("cagd::fairness::pseudo_spline", points, oracle, mode, closed, tie, out);
    return ps;
}

namespace {
PseudoSplineCurve pseudo_spline_curve_of(const PointList& points, const SegmentOracle& oracle, TangentOptimization mode,
                                         bool closed, TangentTie tie, bool validated) {
    std::vector<double> alpha, chord_angle, chord_length;
    long calls = 0;
    ConstructionOutputs out{alpha, chord_angle, chord_length, nullptr, calls};
    spline::PiecewiseHermiteCurve curve =
        construct("cagd::fairness::pseudo_spline_curve", points, oracle, mode, closed, tie, out, validated);
    return PseudoSplineCurve{std::move(curve), out.length, out.area, out.pseudo_energy};
}
}  // namespace

PseudoSplineCurve pseudo_spline_curve(const PointList& points, const SegmentOracle& oracle, TangentOptimization mode,
                                      bool closed, TangentTie tie) {
    return pseudo_spline_curve_of(points, oracle, mode, closed, tie, false);
}

PseudoSplineCurve pseudo_spline_curve(const ValidPoints& points, const SegmentOracle& oracle, TangentOptimization mode,
                                      TangentTie tie) {
    const bool closed = points.closed();
    return pseudo_spline_curve_of(points.points(), oracle, mode, closed, tie, points.cover(closed ? 3 : 2, closed));
}

namespace {

// The smallest N ≥ 3 with polygon_error(N) < spline_error; polygon_error decreases in N.
template <class PolygonError>
long first_closer_polygon(const char* who, double spline_error, const PolygonError& polygon_error) {
    if (!(spline_error > 0.0 && std::isfinite(spline_error)))
        fail_input(who, "spline_error must be positive and finite, got " + full_precision(spline_error));
    long lo = 2, hi = 3;  // invariant: polygon_error(lo) ≥ spline_error (or lo = 2), search hi
    while (polygon_error(hi) >= spline_error) {
        lo = hi;
        hi *= 2;
        if (hi > 1000000000L)
            fail_input(who,
                       "spline_error " + full_precision(spline_error) + " is below every polygon error up to N = 1e9");
    }
    while (hi - lo > 1) {  // bisection on the first N below spline_error
        const long mid = lo + (hi - lo) / 2;
        (polygon_error(mid) >= spline_error ? lo : hi) = mid;
    }
    return hi;
}

}  // namespace

long equivalent_polygon_points(double spline_error, CircleMeasure measure) {
    return first_closer_polygon("cagd::fairness::equivalent_polygon_points", spline_error, [&](long n) {
        const double nd = static_cast<double>(n), x = std::numbers::pi / nd;
        return measure == CircleMeasure::perimeter ? 2.0 * std::numbers::pi - 2.0 * nd * std::sin(x)
                                                   : std::numbers::pi - 0.5 * nd * std::sin(2.0 * x);
    });
}

long equivalent_helix_polygon_points(double relative_error, double rise_over_radius) {
    const char* who = "cagd::fairness::equivalent_helix_polygon_points";
    if (!(rise_over_radius >= 0.0 && std::isfinite(rise_over_radius)))
        fail_input(who, "rise_over_radius must be finite and ≥ 0, got " + full_precision(rise_over_radius));
    const double p = rise_over_radius, turn = std::sqrt(4.0 * std::numbers::pi * std::numbers::pi + p * p);
    return first_closer_polygon(who, relative_error, [&](long n) {
        const double nd = static_cast<double>(n), half_chord = std::sin(std::numbers::pi / nd), rise = p / nd;
        // 1 − N·chord / turn, with turn − N·chord written without cancellation
        const double chord = std::sqrt(4.0 * half_chord * half_chord + rise * rise);
        return (turn * turn - nd * nd * chord * chord) / (turn * (turn + nd * chord));
    });
}

}  // namespace cagd::fairness
