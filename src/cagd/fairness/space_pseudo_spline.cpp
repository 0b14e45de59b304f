#include "cagd/fairness/space_pseudo_spline.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "cagd/core/errors.hpp"
#include "cagd/fairness/detail/tangent_minimisation.hpp"

namespace cagd::fairness {

namespace {

constexpr double kSpaceStraight = 1e-12;  // as the planar pseudo-spline: tangent angles below are zero

double space_angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

// A unit vector perpendicular to the unit vector e, in the plane of e and v when v is not along e
// (then v's component across e points along it), else any perpendicular.
Eigen::Vector3d perpendicular_in_plane(const Eigen::Vector3d& e, const Eigen::Vector3d& v) {
    const Eigen::Vector3d p = v - v.dot(e) * e;
    if (p.norm() > 1e-12 * std::max(1.0, v.norm())) return p.normalized();
    const Eigen::Vector3d any = std::abs(e.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return (any - any.dot(e) * e).normalized();
}

}  // namespace

SpaceTableValue ExactSpaceOracle::segment(double theta0, double theta1, double phi) const {
    const SpacePseudoEnergyMinimum m = minimize_space_pseudo_energy(theta0, theta1, phi);
    if (!m.outcome.ok())
        fail_input("cagd::fairness::ExactSpaceOracle::segment", "no minimum at (" + full_precision(theta0) + ", " +
                                                                    full_precision(theta1) + ", " +
                                                                    full_precision(phi) + "): " + m.outcome.message);
    return {m.pseudo_energy, m.r0, m.r1, m.length, m.type};
}

double SpacePseudoSpline::length_from_tables() const {
    double s = 0.0;
    for (std::size_t i = 0; i < spans.size(); ++i) s += chord_length[i] * spans[i].value.length;
    return s;
}

SpacePseudoSpline space_pseudo_spline(const PointList& points_in, const SpaceSegmentOracle& oracle,
                                      TangentOptimization mode, bool closed) {
    const char* who = "cagd::fairness::space_pseudo_spline";
    require_valid_points(points_in, closed ? 3 : 2, true, closed, who);
    if (points_in.cols() != 2 && points_in.cols() != 3)
        fail_input(who, "needs points with 2 or 3 coordinates, got " + std::to_string(points_in.cols()));
    Eigen::MatrixXd points = Eigen::MatrixXd::Zero(points_in.rows(), 3);
    points.leftCols(points_in.cols()) = points_in;
    const Eigen::Index np = points.rows();
    const Eigen::Index spans = closed ? np : np - 1;
    const auto next = [&](Eigen::Index i) { return (i + 1) % np; };
    std::vector<Eigen::Vector3d> dir(static_cast<std::size_t>(spans));  // unit chords
    SpacePseudoSpline ps{spline::PiecewiseHermiteCurve(Eigen::MatrixXd::Zero(2, 3), Eigen::MatrixXd::Zero(1, 3),
                                                       Eigen::MatrixXd::Zero(1, 3)),
                         {},
                         {},
                         {}};
    ps.chord_length.resize(static_cast<std::size_t>(spans));
    for (Eigen::Index i = 0; i < spans; ++i) {
        const Eigen::Vector3d c = (points.row(next(i)) - points.row(i)).transpose();
        ps.chord_length[static_cast<std::size_t>(i)] = c.norm();
        dir[static_cast<std::size_t>(i)] = c / c.norm();
    }
    const SegmentOracle& planar = oracle.planar();
    const auto J = [&](double theta) { return planar.angle_energy(wrap_angle(theta)); };
    ps.tangent.assign(static_cast<std::size_t>(np), Eigen::Vector3d::Zero());

    // Interior tangents: the planar rule in the plane of the two chords (see the header).
    const Eigen::Index first = closed ? 0 : 1, last = closed ? np - 1 : np - 2;
    for (Eigen::Index i = first; i <= last; ++i) {
        const Eigen::Vector3d& in = dir[static_cast<std::size_t>((i - 1 + spans) % spans)];
        const Eigen::Vector3d& out = dir[static_cast<std::size_t>(i)];
        const double tau = space_angle_between(in, out);  // the turn, in [0, π]
        if (std::abs(tau - std::numbers::pi) <= 1e-12)
            fail_input(who, "the points turn by pi at point " + std::to_string(i) +
                                " (a hairpin): no tangent direction between the chords");
        Eigen::Vector3d t = out;
        if (tau > 0.0) {
            // In-plane frame: out = (1, 0), in = (cos τ, −sin τ); α ∈ [−τ, 0] from the outgoing chord.
            const Eigen::Vector3d n = perpendicular_in_plane(out, -in);
            double a = 0.0;
            if (mode == TangentOptimization::none) {
                const Eigen::Vector3d d = in * ps.chord_length[static_cast<std::size_t>((i - 1 + spans) % spans)] +
                                          out * ps.chord_length[static_cast<std::size_t>(i)];
                a = std::atan2(d.dot(n), d.dot(out));
            } else {
                const double lin = ps.chord_length[static_cast<std::size_t>((i - 1 + spans) % spans)],
                             lout = ps.chord_length[static_cast<std::size_t>(i)];
                const auto w = [&](double alpha) { return lin * J(alpha + tau) + lout * J(alpha); };
                const std::vector<double>* breakpoints = planar.angle_energy_nodes();
                a = mode == TangentOptimization::exact && breakpoints
                        ? detail::minimise_piecewise_linear_w(w, -tau, 0.0, tau, *breakpoints)
                        : detail::minimise_w(w, -tau, 0.0, mode);
            }
            t = std::cos(a) * out + std::sin(a) * n;
        }
        ps.tangent[static_cast<std::size_t>(i)] = t.normalized();
    }
    // End tangents (eq 13): in the plane of the end chord and the neighbouring tangent.
    if (!closed) {
        if (np == 2) {
            ps.tangent[0] = ps.tangent[1] = dir[0];
        } else {
            const auto end_tangent = [&](const Eigen::Vector3d& chord,
                                         const Eigen::Vector3d& neighbour) -> Eigen::Vector3d {
                const double a = space_angle_between(chord, neighbour);  // the neighbour's angle, ≥ 0 in its plane
                if (a <= kSpaceStraight) return chord;
                const double theta1 = planar.angle_minimum(a).second;
                return std::cos(theta1) * chord + std::sin(theta1) * perpendicular_in_plane(chord, neighbour);
            };
            // As the planar α_0 = θ1(α_1 + φ_1 − φ_0) and α_n = θ1(α_{n−1}) (the segment's symmetry
            // J(θ0, θ1) = J(θ1, θ0) makes θ1(θ) the best other end for either end).
            ps.tangent[0] = end_tangent(dir[0], ps.tangent[1]);
            ps.tangent[static_cast<std::size_t>(np - 1)] =
                end_tangent(dir[static_cast<std::size_t>(spans - 1)], ps.tangent[static_cast<std::size_t>(np - 2)]);
        }
    }
    // Spans (eq 9–10).
    Eigen::MatrixXd nodes(spans + 1, 3), d0(spans, 3), d1(spans, 3);
    for (Eigen::Index i = 0; i < spans; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        const Eigen::Vector3d& e1 = dir[k];
        const Eigen::Vector3d &t0 = ps.tangent[k], &t1 = ps.tangent[static_cast<std::size_t>(next(i))];
        SpacePseudoSplineSpan s;
        s.theta0 = space_angle_between(e1, t0);
        s.theta1 = space_angle_between(e1, t1);
        // φ about e1 from the plane (e1, t0) to (e1, t1); with t0 along e1 the plane of t1 is the reference.
        const Eigen::Vector3d e2 = perpendicular_in_plane(e1, s.theta0 > kSpaceStraight ? t0 : t1), e3 = e1.cross(e2);
        s.phi = std::atan2(t1.dot(e3), t1.dot(e2));
        if (s.phi < 0.0) s.phi += 2 * std::numbers::pi;
        if (s.phi >= 2 * std::numbers::pi) s.phi = 0.0;
        if (s.theta0 <= kSpaceStraight && s.theta1 <= kSpaceStraight)
            s.value = {0.0, 1.0, 1.0, 1.0, SegmentType::c};  // the straight segment (J = 0, L = 1)
        else
            s.value = oracle.segment(s.theta0, s.theta1, s.phi);
        const double l = ps.chord_length[k];
        nodes.row(i) = points.row(i);
        d0.row(i) = (l * s.value.r0 * t0).transpose();
        d1.row(i) = (l * s.value.r1 * t1).transpose();
        ps.spans.push_back(s);
    }
    nodes.row(spans) = points.row(closed ? 0 : np - 1);
    ps.curve = spline::PiecewiseHermiteCurve(nodes, d0, d1);
    return ps;
}

}  // namespace cagd::fairness
