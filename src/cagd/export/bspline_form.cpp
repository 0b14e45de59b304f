#include "cagd/export/bspline_form.hpp"

#include <algorithm>
#include <boost/math/special_functions/binomial.hpp>
#include <cmath>
#include <string>

namespace cagd::exports {

namespace {

// The tolerance of the continuity test and of the blossoms' spread, relative to the control
// points' bounding-box diagonal (header).
constexpr double kBlossomTolerance = 1e-13;
// Pieces join when their shared point differs by at most this, relative to the extent (header).
constexpr double kJoinTolerance = 1e-12;

void check_pieces(const BezierPieces& b, const char* who) {
    if (b.pieces() < 1 || b.degree < 0 || b.control.rows() != static_cast<Eigen::Index>(b.pieces()) * (b.degree + 1) ||
        b.dimension() < 1)
        fail_input(who, "needs at least one piece of degree >= 0 and (degree + 1) control points per piece");
    for (std::size_t i = 0; i + 1 < b.breaks.size(); ++i)
        if (!(b.breaks[i] < b.breaks[i + 1]))
            fail_input(who, "breaks must increase, got " + full_precision(b.breaks[i]) + " then " +
                                full_precision(b.breaks[i + 1]));
    if (!b.control.allFinite()) fail_input(who, "control points must be finite");
}

double control_diagonal(const BezierPieces& b) {
    return (b.control.colwise().maxCoeff() - b.control.colwise().minCoeff()).norm();
}

// The continuity order c at the join of piece L (left) and R (right), as the header defines it:
// −1 when even the positions differ by more than the tolerance.
int join_continuity(const BezierPieces& b, int L, int R, double tol) {
    const int p = b.degree;
    const Eigen::MatrixXd bl = b.piece(L), br = b.piece(R);
    const double hl = b.breaks[static_cast<std::size_t>(L) + 1] - b.breaks[static_cast<std::size_t>(L)];
    const double hr = b.breaks[static_cast<std::size_t>(R) + 1] - b.breaks[static_cast<std::size_t>(R)];
    int c = -1;
    for (int j = 0; j <= p; ++j) {
        Eigen::RowVectorXd back = Eigen::RowVectorXd::Zero(b.dimension()), forward = back;
        for (int m = 0; m <= j; ++m) {
            const double w =
                boost::math::binomial_coefficient<double>(static_cast<unsigned>(j), static_cast<unsigned>(m));
            back += ((m % 2) ? -w : w) * bl.row(p - m);
            forward += (((j - m) % 2) ? -w : w) * br.row(m);
        }
        const double ratio = std::pow(hr / hl, j);
        if ((ratio * back - forward).norm() > std::ldexp(tol, j) * std::max(1.0, ratio)) break;
        c = j;
    }
    return c;
}

// One period's knots, each with the piece whose span starts there and the multiple of the period
// its value is shifted by (clamped curves: shift 0).
struct KnotPlan {
    std::vector<double> value;
    std::vector<int> piece;  // −1: no piece starts here (the clamped end)
    std::vector<double> shift;
    void add(double v, int pc, double s, int times) {
        for (int k = 0; k < times; ++k) {
            value.push_back(v);
            piece.push_back(pc);
            shift.push_back(s);
        }
    }
};

// The blossom of piece i at the arguments u (shifted back by `shift`), by de Casteljau.
Eigen::RowVectorXd blossom(const BezierPieces& b, int i, const double* u, double shift) {
    const int p = b.degree;
    const double a = b.breaks[static_cast<std::size_t>(i)], h = b.breaks[static_cast<std::size_t>(i) + 1] - a;
    Eigen::MatrixXd w = b.piece(i);
    for (int r = 1; r <= p; ++r) {
        const double s = (u[r - 1] - shift - a) / h;
        for (int k = 0; k + r <= p; ++k) w.row(k) = (1.0 - s) * w.row(k) + s * w.row(k + 1);
    }
    return w.row(0);
}

// Control points d_0 … d_{count−1} on the knots of `plan` (each the blossom of its first
// non-empty span; spread[j] = the largest distance of the other spans' blossoms from it).
Eigen::MatrixXd blossom_control_points(const BezierPieces& b, const KnotPlan& plan, int count,
                                       std::vector<double>& spread) {
    const int p = b.degree;
    Eigen::MatrixXd d(count, b.dimension());
    spread.assign(static_cast<std::size_t>(count), 0.0);
    for (int j = 0; j < count; ++j) {
        bool first = true;
        for (int s = j; s <= j + p; ++s) {
            const std::size_t us = static_cast<std::size_t>(s);
            if (us + 1 >= plan.value.size() || !(plan.value[us] < plan.value[us + 1]) || plan.piece[us] < 0) continue;
            const Eigen::RowVectorXd v = blossom(b, plan.piece[us], plan.value.data() + j + 1, plan.shift[us]);
            if (first) {
                d.row(j) = v;
                first = false;
            } else {
                spread[static_cast<std::size_t>(j)] =
                    std::max(spread[static_cast<std::size_t>(j)], (v - d.row(j)).norm());
            }
        }
        if (first)
            fail_input("cagd::exports::to_bspline",
                       "control point " + std::to_string(j) + " touches no span (internal)");
    }
    return d;
}

KnotPlan clamped_plan(const BezierPieces& b, const std::vector<int>& mu) {
    KnotPlan plan;
    const int K = b.pieces(), p = b.degree;
    plan.add(b.breaks.front(), 0, 0.0, p + 1);
    for (int i = 1; i < K; ++i)
        plan.add(b.breaks[static_cast<std::size_t>(i)], i, 0.0, mu[static_cast<std::size_t>(i)]);
    plan.add(b.breaks.back(), -1, 0.0, p + 1);
    return plan;
}

// Raises to p the multiplicity of every break i (index into mu, 0 = the closing point of a periodic
// curve) among the knots t_{j+1} … t_{j+p} of a control point whose blossoms spread beyond tol.
// False when nothing could be raised.
bool raise_multiplicities(const KnotPlan& plan, const std::vector<double>& spread, double tol, int p, int K,
                          std::vector<int>& mu) {
    bool raised = false;
    for (std::size_t j = 0; j < spread.size(); ++j) {
        if (spread[j] <= tol) continue;
        for (std::size_t k = j + 1; k <= j + static_cast<std::size_t>(p) && k < plan.value.size(); ++k) {
            const int i = ((plan.piece[k] % K) + K) % K;
            if (plan.piece[k] >= 0 && mu[static_cast<std::size_t>(i)] < p) {
                mu[static_cast<std::size_t>(i)] = p;
                raised = true;
            }
        }
    }
    return raised;
}

}  // namespace

int first_unjoined_piece(const BezierPieces& b) {
    check_pieces(b, "cagd::exports::first_unjoined_piece");
    const double extent = std::max(control_diagonal(b), b.control.cwiseAbs().maxCoeff());
    const Eigen::Index n = b.degree + 1;
    for (Eigen::Index i = 1; i < b.pieces(); ++i)
        if ((b.control.row(i * n) - b.control.row(i * n - 1)).norm() > kJoinTolerance * extent)
            return static_cast<int>(i);
    return 0;
}

BSplineCurve bezier_pieces_curve(const BezierPieces& b) {
    check_pieces(b, "cagd::exports::bezier_pieces_curve");
    if (const int i = first_unjoined_piece(b); i > 0)
        fail_input("cagd::exports::bezier_pieces_curve",
                   "piece " + std::to_string(i) + " does not start where piece " + std::to_string(i - 1) +
                       " ends (a gap of " + full_precision((b.piece(i).row(0) - b.piece(i - 1).row(b.degree)).norm()) +
                       ")");
    const int p = std::max(b.degree, 1);
    const BezierPieces e = b.degree < 1 ? elevate_degree(b, 1) : b;
    std::vector<int> mu(static_cast<std::size_t>(e.pieces()), p);
    const KnotPlan plan = clamped_plan(e, mu);
    // Full multiplicity: the control points are the pieces' own, shared end points taken from the left.
    Eigen::MatrixXd d(static_cast<Eigen::Index>(e.pieces()) * p + 1, e.dimension());
    for (int i = 0; i < e.pieces(); ++i) d.middleRows(static_cast<Eigen::Index>(i) * p, p + 1) = e.piece(i);
    for (int i = e.pieces() - 1; i >= 0; --i) d.row(static_cast<Eigen::Index>(i) * p) = e.piece(i).row(0);
    return BSplineCurve(p, plan.value, d);
}

BSplineForm to_bspline(const BezierPieces& b_in) {
    check_pieces(b_in, "cagd::exports::to_bspline");
    const BezierPieces b = b_in.degree < 1 ? elevate_degree(b_in, 1) : b_in;
    const int K = b.pieces(), p = b.degree;
    const double tol = kBlossomTolerance * control_diagonal(b);
    std::vector<int> mu(static_cast<std::size_t>(K), p);  // mu[0] unused (clamped start)
    for (int i = 1; i < K; ++i)
        mu[static_cast<std::size_t>(i)] = std::clamp(p - join_continuity(b, i - 1, i, tol), 1, p);
    for (;;) {
        const KnotPlan plan = clamped_plan(b, mu);
        const int count = static_cast<int>(plan.value.size()) - p - 1;
        std::vector<double> spread;
        Eigen::MatrixXd d = blossom_control_points(b, plan, count, spread);
        if (*std::max_element(spread.begin(), spread.end()) > tol && raise_multiplicities(plan, spread, tol, p, K, mu))
            continue;
        return BSplineForm{BSplineCurve(p, plan.value, std::move(d)), std::vector<int>(mu.begin() + 1, mu.end()),
                           *std::max_element(spread.begin(), spread.end())};
    }
}

PeriodicBSpline periodic_bspline(const BezierPieces& b_in) {
    check_pieces(b_in, "cagd::exports::periodic_bspline");
    const BezierPieces b = b_in.degree < 1 ? elevate_degree(b_in, 1) : b_in;
    const int K = b.pieces(), p = b.degree;
    const double tol = kBlossomTolerance * control_diagonal(b);
    const double T = b.breaks.back() - b.breaks.front();
    std::vector<int> mu(static_cast<std::size_t>(K));
    for (int i = 0; i < K; ++i)
        mu[static_cast<std::size_t>(i)] = std::clamp(p - join_continuity(b, (i + K - 1) % K, i, tol), 1, p);
    if (join_continuity(b, K - 1, 0, tol) < 0) return {};  // not closed
    for (;;) {
        // One period of knots (break i repeated mu_i times), extended by whole periods on both sides.
        KnotPlan period;
        for (int i = 0; i < K; ++i)
            period.add(b.breaks[static_cast<std::size_t>(i)], i, 0.0, mu[static_cast<std::size_t>(i)]);
        const int n = static_cast<int>(period.value.size());
        KnotPlan plan;
        for (int k = 0; k <= n + 2 * p; ++k) {
            const int m = k - p;
            const int q = (m % n + n) % n;
            const double shift = T * static_cast<double>((m - q) / n);
            plan.add(period.value[static_cast<std::size_t>(q)] + shift, period.piece[static_cast<std::size_t>(q)],
                     shift, 1);
        }
        std::vector<double> spread;
        Eigen::MatrixXd d = blossom_control_points(b, plan, n + p, spread);
        // The wrapped control points must repeat the first ones.
        for (int j = 0; j < p; ++j)
            spread[static_cast<std::size_t>(j)] =
                std::max(spread[static_cast<std::size_t>(j)], (d.row(n + j) - d.row(j)).norm());
        if (*std::max_element(spread.begin(), spread.end()) > tol && raise_multiplicities(plan, spread, tol, p, K, mu))
            continue;
        if (*std::max_element(spread.begin(), spread.end()) > tol) return {};
        return PeriodicBSpline{p, plan.value, d.topRows(n)};
    }
}

}  // namespace cagd::exports
