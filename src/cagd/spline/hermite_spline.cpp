#include "cagd/spline/hermite_spline.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/core/finite.hpp"
#include "cagd/numeric/tridiagonal.hpp"

namespace cagd::spline {

PiecewiseHermiteCurve::PiecewiseHermiteCurve(Eigen::MatrixXd nodes, Eigen::MatrixXd d0, Eigen::MatrixXd d1)
    : nodes_(std::move(nodes)), d0_(std::move(d0)), d1_(std::move(d1)) {
    const char* who = "PiecewiseHermiteCurve";
    if (d0_.rows() < 1) fail_input(who, "needs at least one span");
    if (nodes_.rows() != d0_.rows() + 1 || d1_.rows() != d0_.rows())
        fail_input(who, "needs K+1 nodes and K start/end derivatives, got " + std::to_string(nodes_.rows()) + ", " +
                            std::to_string(d0_.rows()) + ", " + std::to_string(d1_.rows()));
    if (d0_.cols() != nodes_.cols() || d1_.cols() != nodes_.cols())
        fail_input(who, "nodes and derivatives must have the same dimension");
    if (!all_finite(nodes_) || !all_finite(d0_) || !all_finite(d1_))
        fail_input(who, "nodes and derivatives must be finite");
}

namespace {

// The span scales of from_node_slopes: none, or one finite scale per span.
void require_span_scales(const char* who, const std::vector<double>& scales, Eigen::Index spans) {
    if (!scales.empty() && static_cast<Eigen::Index>(scales.size()) != spans)
        fail_input(who, "needs K span scales (or none), got " + std::to_string(scales.size()) + " for " +
                            std::to_string(spans) + " spans");
    if (!all_finite(scales.data(), scales.size())) fail_input(who, "span scales must be finite");
}

}  // namespace

PiecewiseHermiteCurve PiecewiseHermiteCurve::from_node_slopes(Eigen::MatrixXd nodes, Eigen::MatrixXd slopes,
                                                              std::vector<double> scales) {
    const char* who = "PiecewiseHermiteCurve::from_node_slopes";
    const Eigen::Index spans = nodes.rows() - 1;
    if (spans < 1) fail_input(who, "needs at least one span");
    if (slopes.rows() != spans + 1 && slopes.rows() != spans)
        fail_input(who, "needs K+1 slopes (closed: K) for K+1 nodes, got " + std::to_string(slopes.rows()) + " for " +
                            std::to_string(nodes.rows()));
    require_span_scales(who, scales, spans);
    if (slopes.cols() != nodes.cols()) fail_input(who, "nodes and slopes must have the same dimension");
    if (!all_finite(nodes) || !all_finite(slopes)) fail_input(who, "nodes and slopes must be finite");
    PiecewiseHermiteCurve c;
    c.d0_.resize(spans, slopes.cols());
    c.d1_.resize(spans, slopes.cols());
    for (Eigen::Index k = 0; k < spans; ++k) {
        const double h = scales.empty() ? 1.0 : scales[static_cast<std::size_t>(k)];
        const Eigen::Index next = k + 1 == slopes.rows() ? 0 : k + 1;  // closed: m_K = m_0
        for (Eigen::Index col = 0; col < slopes.cols(); ++col) {
            c.d0_(k, col) = scales.empty() ? slopes(k, col) : h * slopes(k, col);
            c.d1_(k, col) = scales.empty() ? slopes(next, col) : h * slopes(next, col);
        }
    }
    c.nodes_ = std::move(nodes);
    return c;
}

std::vector<double> PiecewiseHermiteCurve::breakpoints() const { return unit_piece_breakpoints(spans()); }

namespace {
// Row j of the basis: the j-th derivatives of H0..H3 at t (zero for j > 3).
[[gnu::always_inline]] inline void hermite_basis_row(int j, double t, double h[4]) {
    switch (j) {
        case 0:
            h[0] = 2 * t * t * t - 3 * t * t + 1, h[1] = -2 * t * t * t + 3 * t * t, h[2] = t * t * t - 2 * t * t + t,
            h[3] = t * t * t - t * t;
            return;
        case 1:
            h[0] = 6 * t * t - 6 * t, h[1] = -6 * t * t + 6 * t, h[2] = 3 * t * t - 4 * t + 1, h[3] = 3 * t * t - 2 * t;
            return;
        case 2: h[0] = 12 * t - 6, h[1] = -12 * t + 6, h[2] = 6 * t - 4, h[3] = 6 * t - 2; return;
        case 3: h[0] = 12, h[1] = -12, h[2] = 6, h[3] = 6; return;
        default: h[0] = h[1] = h[2] = h[3] = 0.0;
    }
}
}  // namespace

void PiecewiseHermiteCurve::evaluate_jet(double u, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const {
    const char* who = "cagd::spline::PiecewiseHermiteCurve::evaluate_jet";
    const int last = first + static_cast<int>(out.rows()) - 1;
    const PieceLocation at = side == JetSide::left ? locate_unit_piece_from_left(who, u, spans(), last)
                                                   : locate_unit_piece(who, u, spans(), last);
    const int k = at.piece;
    const double t = at.t;
    const Eigen::Index dim = nodes_.cols();
    double h[4];
    for (int j = first; j <= last; ++j) {
        if (j > 3) {  // a cubic's higher derivatives
            out.row(j - first).setZero();
            continue;
        }
        hermite_basis_row(j, t, h);
        for (Eigen::Index c = 0; c < dim; ++c)
            out(j - first, c) = h[0] * nodes_(k, c) + h[1] * nodes_(k + 1, c) + h[2] * d0_(k, c) + h[3] * d1_(k, c);
    }
}

std::optional<double> PiecewiseHermiteCurve::span_offset_bound(const Curve& other, double t0, double t1, double u0,
                                                               double u1) const {
    const auto* o = dynamic_cast<const PiecewiseHermiteCurve*>(&other);
    if (o == nullptr || o->spans() != spans() || o->dimension() != dimension() || !(t0 == u0 && t1 == u1) ||
        !(0.0 <= t0 && t0 <= t1 && t1 <= spans()))
        return std::nullopt;
    // The spans evaluate_jet reads for t ∈ [t0, t1] (JetSide::right): nodes i0..i1 + 1, derivatives i0..i1.
    const auto i0 = static_cast<Eigen::Index>(std::min(static_cast<int>(t0), spans() - 1)),
               i1 = static_cast<Eigen::Index>(std::min(static_cast<int>(t1), spans() - 1)), count = i1 - i0 + 1;
    const bool equal = nodes_.middleRows(i0, count + 1) == o->nodes_.middleRows(i0, count + 1) &&
                       d0_.middleRows(i0, count) == o->d0_.middleRows(i0, count) &&
                       d1_.middleRows(i0, count) == o->d1_.middleRows(i0, count);
    return equal ? std::optional<double>(0.0) : std::nullopt;
}

namespace {

// Nodes with the first repeated at the end for a closed curve.
Eigen::MatrixXd span_nodes(const PointList& points, bool closed) {
    if (!closed) return points;
    Eigen::MatrixXd n(points.rows() + 1, points.cols());
    n << points, points.row(0);
    return n;
}

}  // namespace

namespace {
constexpr const char* kCubicSplineWho = "cubic_spline_interpolant";

// cubic_spline_interpolant of points that passed require_valid_points(points, closed ? 3 : 2, …).
PiecewiseHermiteCurve cubic_spline_of_valid_points(const PointList& points, ParameterSpacing spacing, bool closed) {
    Eigen::MatrixXd nodes = span_nodes(points, closed);
    const int spans = static_cast<int>(nodes.rows()) - 1;
    const int dim = static_cast<int>(points.cols());
    // h_k: 1, or the chord |P_{k+1} − P_k| as core/points' chord_lengths forms it (the registry's
    // node parameters are its running sum). Uniform: no array of ones.
    const bool uniform = spacing == ParameterSpacing::uniform;
    std::vector<double> chords = uniform ? std::vector<double>{} : chord_lengths(points, closed);
    const auto h = [&](int k) { return uniform ? 1.0 : chords[static_cast<std::size_t>(k)]; };
    // Unknowns m_0..m_{N−1}: N = n+1 for open, N = spans (m_K = m_0) for closed. Row k holds
    // hn m_{k−1} + 2(hp + hn) m_k + hp m_{k+1}: strictly diagonally dominant, so the Thomas
    // algorithm needs no pivoting (numeric/tridiagonal.hpp); closed: cyclic, the corners
    // A(0, N−1) = sub[0] and A(N−1, 0) = sup[N−1].
    const int N = closed ? spans : spans + 1;
    // Row k: its entries, and its right-hand side written to rhs[c·stride], from the chords and
    // Δ_k = P_{k+1} − P_k formed where used (no n-long arrays of them: at 10^5 points and more the
    // cost of a construction is mostly memory). Open: the ends' rows 2m_0 + m_1 = 3Δ_0/h_0 and
    // m_{K−1} + 2m_K = 3Δ_{K−1}/h_{K−1}.
    const auto row = [&](std::size_t r, double* rhs, std::size_t stride) -> numeric::TridiagonalRow {
        const int k = static_cast<int>(r);
        const auto delta = [&](int span, int c) { return nodes(span + 1, c) - nodes(span, c); };
        if (!closed && (k == 0 || k == N - 1)) {
            const int span = k == 0 ? 0 : spans - 1;
            for (int c = 0; c < dim; ++c) rhs[static_cast<std::size_t>(c) * stride] = 3.0 * delta(span, c) / h(span);
            return k == 0 ? numeric::TridiagonalRow{0.0, 2.0, 1.0} : numeric::TridiagonalRow{1.0, 2.0, 0.0};
        }
        const int prev = k == 0 ? spans - 1 : k - 1;  // span ending at node k (closed: node 0 ends the last)
        const int next = k;                           // span starting at node k (k < spans here)
        const double hp = h(prev), hn = h(next);
        for (int c = 0; c < dim; ++c)
            rhs[static_cast<std::size_t>(c) * stride] = 3.0 * (hn * delta(prev, c) / hp + hp * delta(next, c) / hn);
        return {hn, 2.0 * (hp + hn), hp};
    };
    Eigen::MatrixXd m(N, dim);
    if (closed) {  // Sherman–Morrison on the three diagonals
        const auto size = static_cast<std::size_t>(N);
        std::vector<double> sub, diag, sup;
        sub.reserve(size), diag.reserve(size), sup.reserve(size);
        for (int k = 0; k < N; ++k) {
            const numeric::TridiagonalRow a = row(static_cast<std::size_t>(k), m.data() + k, size);
            sub.push_back(a.sub), diag.push_back(a.diag), sup.push_back(a.sup);
        }
        m = numeric::solve_cyclic_tridiagonal(sub, diag, sup, m);
    } else {
        numeric::solve_tridiagonal_rows(static_cast<std::size_t>(N), static_cast<std::size_t>(dim), row, m.data());
    }
    // Span k's d0 = h_k m_k, d1 = h_k m_{k+1} (uniform: h_k = 1).
    return PiecewiseHermiteCurve::from_node_slopes(std::move(nodes), std::move(m), std::move(chords));
}

}  // namespace

PiecewiseHermiteCurve cubic_spline_interpolant(const PointList& points, ParameterSpacing spacing, bool closed) {
    require_valid_points(points, closed ? 3 : 2, true, closed, kCubicSplineWho);
    return cubic_spline_of_valid_points(points, spacing, closed);
}

PiecewiseHermiteCurve cubic_spline_interpolant(const ValidPoints& points, ParameterSpacing spacing) {
    const bool closed = points.closed();
    if (!points.cover(closed ? 3 : 2, closed))
        return cubic_spline_interpolant(points.points(), spacing, closed);  // checked as a PointList
    return cubic_spline_of_valid_points(points.points(), spacing, closed);
}

namespace {

// The directions of hermite_tangent_directions, handed to put(i, t_i) in the order i = 1, 2, …,
// n − 1 (closed: …, n − 1, 0; open: then 0 and n − 1), with rows of type Row: Eigen::RowVector3d
// (planar points padded with z = 0, which changes no norm or dot product) so that no row allocates
// (at 10^6 points four temporaries per point took a quarter of the construction), or RowVectorXd.
// Each chord and its length is formed once, and no index wraps by a modulo (an integer division
// per point); the arithmetic per direction is the same as written in the header.
// With `with_interior` false only the two open ends are put (the interior is the caller's:
// planar_hermite_interior).
template <class Row, class Put>
void tangent_directions_with(const PointList& points, TangentRule rule, bool closed, const char* who, Put&& put,
                             bool with_interior = true) {
    const Eigen::Index n = points.rows(), dim = points.cols();
    const auto at = [&](Eigen::Index i) -> Row {
        if constexpr (Row::SizeAtCompileTime == Eigen::Dynamic) {
            return points.row(i);
        } else {
            Row r = Row::Zero();
            r.head(dim) = points.row(i);
            return r;
        }
    };
    const auto unit_row = [](const Row& v) -> Row { return v / v.norm(); };
    // t_i from a = P_i − P_{i−1}, b = P_{i+1} − P_i and P_{i+1} − P_{i−1}.
    const auto interior = [&](Eigen::Index i, const Row& a, double la, const Row& b, double lb,
                              const Row& across) -> Row {
        const Row d = rule == TangentRule::circle ? Row(lb / la * a + la / lb * b) : across;
        const double length = d.norm();  // once: the check and the division use the same value
        // A reversal leaves d = 0 (Hermite A: P_{i−1} = P_{i+1}) or tiny by cancellation.
        if (length <= 1e-14 * (la + lb))
            fail_input(who, "the curve reverses at point " + std::to_string(i) +
                                " (turning angle π), where no tangent direction is defined");
        return d / length;
    };
    Row before = at(closed ? n - 1 : 0), here = at(closed ? 0 : 1);
    Row a = here - before;
    double la = a.norm();
    const double first_chord = la;  // open: |P_1 − P_0|
    Row first_interior = at(0);     // t_1 (set in the loop), for an open circle end
    for (Eigen::Index i = closed ? 0 : 1; with_interior && i < (closed ? n : n - 1); ++i) {
        const Row next = at(i + 1 == n ? 0 : i + 1), b = next - here;
        const double lb = b.norm();
        const Row t = interior(i, a, la, b, lb, next - before);
        if (!closed && i == 1) first_interior = t;
        put(i, t, la, lb);
        before = here, here = next, a = b, la = lb;
    }
    if (closed) return;
    if (!with_interior) {                   // t_1 and the last chord, as the loop would have left them
        if (rule == TangentRule::circle) {  // (n ≥ 3 for the circle rule)
            const Row b = at(2) - at(1);
            first_interior = interior(1, a, la, b, b.norm(), at(2) - at(0));
        }
        la = (at(n - 1) - at(n - 2)).norm();
    }
    // (la is now |P_{n−1} − P_{n−2}|, the last chord.)
    if (rule == TangentRule::chord_of_neighbours) {
        put(0, unit_row(at(1) - at(0)), 0.0, first_chord);
        put(n - 1, unit_row(at(n - 1) - at(n - 2)), la, 0.0);
        return;
    }
    // Circle end: reflect the middle tangent of the three end points.
    const Row ah = unit_row(at(1) - at(0));
    put(0, Row(2.0 * first_interior.dot(ah) * ah - first_interior), 0.0, first_chord);
    const Row p3 = at(n - 3), p2 = at(n - 2), p1 = at(n - 1), am = p2 - p3, bm = p1 - p2;
    const Row tm = interior(n - 2, am, am.norm(), bm, bm.norm(), p1 - p3), bh = unit_row(p1 - p2);
    put(n - 1, Row(2.0 * tm.dot(bh) * bh - tm), la, 0.0);
}

// put(i, t_i, |P_i − P_{i−1}|, |P_{i+1} − P_i|) for every point (closed: indices modulo n; open: 0
// for the chord an end point lacks): the chords are those the directions were computed from.
template <class Put>
void tangent_directions(const PointList& points, TangentRule rule, bool closed, const char* who, Put&& put) {
    if (points.cols() <= 3)
        tangent_directions_with<Eigen::RowVector3d>(points, rule, closed, who, put);
    else
        tangent_directions_with<Eigen::RowVectorXd>(points, rule, closed, who, put);
}

// The interior tangents of a planar Hermite spline into d0 (span starts) and d1 (span ends): the
// arithmetic of tangent_directions_with (|v| = √(x² + y²): its padded z adds exactly 0), column by
// column over contiguous arrays with no dependence from one point to the next, so that the compiler
// vectorises it (the per-point loop waited on its square roots and divisions: 60 % of a 10^6-point
// construction). The same curve bit for bit; a reversal is reported at the first point the per-point
// loop would have stopped at.
void planar_hermite_interior(const PointList& points, TangentRule rule, bool closed, const char* who,
                             Eigen::MatrixXd& d0, Eigen::MatrixXd& d1) {
    const Eigen::Index n = points.rows(), spans = closed ? n : n - 1, first = closed ? 0 : 1, last = closed ? n : n - 1;
    const double *x = points.col(0).data(), *y = points.col(1).data();
    std::vector<double> cx(static_cast<std::size_t>(spans)), cy(cx.size()),
        h(cx.size());  // chord k = P_{k+1} − P_k, |chord k|
    for (Eigen::Index k = 0; k < spans; ++k) {
        const Eigen::Index j = k + 1 == n ? 0 : k + 1;
        cx[static_cast<std::size_t>(k)] = x[j] - x[k], cy[static_cast<std::size_t>(k)] = y[j] - y[k];
    }
    for (std::size_t k = 0; k < h.size(); ++k) h[k] = std::sqrt(cx[k] * cx[k] + cy[k] * cy[k]);
    double *d0x = d0.col(0).data(), *d0y = d0.col(1).data(), *d1x = d1.col(0).data(), *d1y = d1.col(1).data();
    const bool circle = rule == TangentRule::circle;
    bool reversal = false;
    const auto direction = [&](Eigen::Index i, double& dx,
                               double& dy) {  // d_i before normalising; true when it reverses
        const Eigen::Index before = i == 0 ? n - 1 : i - 1, after = i + 1 == n ? 0 : i + 1;
        const auto b = static_cast<std::size_t>(before), k = static_cast<std::size_t>(i);
        const double la = h[b], lb = h[k];
        if (circle) {
            const double ra = lb / la, rb = la / lb;
            dx = ra * cx[b] + rb * cx[k], dy = ra * cy[b] + rb * cy[k];
        } else {
            dx = x[after] - x[before], dy = y[after] - y[before];
        }
        const double length = std::sqrt(dx * dx + dy * dy);
        dx /= length, dy /= length;
        return length <= 1e-14 * (la + lb);
    };
    for (Eigen::Index i = first; i < last; ++i) {
        double tx = 0.0, ty = 0.0;
        reversal |= direction(i, tx, ty);
        const auto b = static_cast<std::size_t>(i == 0 ? n - 1 : i - 1), k = static_cast<std::size_t>(i);
        d0x[i] = h[k] * tx, d0y[i] = h[k] * ty;
        d1x[b] = h[b] * tx, d1y[b] = h[b] * ty;
    }
    if (!reversal) return;
    for (Eigen::Index i = first; i < last; ++i) {
        double tx = 0.0, ty = 0.0;
        if (direction(i, tx, ty))
            fail_input(who, "the curve reverses at point " + std::to_string(i) +
                                " (turning angle π), where no tangent direction is defined");
    }
}

const char* directions_who(TangentRule rule) {
    return rule == TangentRule::circle ? "hermite_tangent_directions (circle, Hermite B)"
                                       : "hermite_tangent_directions (chord of neighbours, Hermite A)";
}

}  // namespace

Eigen::MatrixXd hermite_tangent_directions(const PointList& points, TangentRule rule, bool closed) {
    const char* who = directions_who(rule);
    require_valid_points(points, (closed || rule == TangentRule::circle) ? 3 : 2, true, closed, who);
    Eigen::MatrixXd t(points.rows(), points.cols());
    tangent_directions(points, rule, closed, who,
                       [&](Eigen::Index i, const auto& r, double, double) { t.row(i) = r.head(points.cols()); });
    return t;
}

namespace {

// hermite_spline of points that passed require_valid_points(points, (closed || circle) ? 3 : 2, …).
PiecewiseHermiteCurve hermite_spline_of_valid_points(const PointList& points, TangentRule rule, bool closed) {
    const char* who = directions_who(rule);
    const Eigen::Index n = points.rows(), dim = points.cols(), spans = closed ? n : n - 1;
    Eigen::MatrixXd nodes = span_nodes(points, closed), d0(spans, dim), d1(spans, dim);
    // t_i starts span i and ends span i − 1 (closed: t_0 also ends span n − 1); the chords, |nodes_{k+1}
    // − nodes_k| (the same differences), come with it.
    const auto put = [&](Eigen::Index i, const auto& r, double before, double after) {
        if (i > 0) d1.row(i - 1) = before * r.head(dim);
        if (i < spans) d0.row(i) = after * r.head(dim);
        if (closed && i == 0) d1.row(n - 1) = before * r.head(dim);
    };
    if (dim == 2) {  // planar: the interior column-wise (planar_hermite_interior), the open ends as below
        planar_hermite_interior(points, rule, closed, who, d0, d1);
        if (!closed) tangent_directions_with<Eigen::RowVector3d>(points, rule, closed, who, put, false);
    } else {
        tangent_directions(points, rule, closed, who, put);
    }
    return PiecewiseHermiteCurve(std::move(nodes), std::move(d0), std::move(d1));
}

Eigen::Index hermite_spline_min_points(TangentRule rule, bool closed) {
    return (closed || rule == TangentRule::circle) ? 3 : 2;
}

}  // namespace

PiecewiseHermiteCurve hermite_spline(const PointList& points, TangentRule rule, bool closed) {
    require_valid_points(points, hermite_spline_min_points(rule, closed), true, closed, directions_who(rule));
    return hermite_spline_of_valid_points(points, rule, closed);
}

PiecewiseHermiteCurve hermite_spline(const ValidPoints& points, TangentRule rule) {
    const bool closed = points.closed();
    if (!points.cover(hermite_spline_min_points(rule, closed), closed))
        return hermite_spline(points.points(), rule, closed);  // checked as a PointList
    return hermite_spline_of_valid_points(points.points(), rule, closed);
}

PiecewiseHermiteCurve hermite_interpolant(const PointList& points, const Eigen::MatrixXd& directions, bool closed) {
    const char* who = "hermite_interpolant";
    require_valid_points(points, closed ? 3 : 2, true, closed, who);
    if (directions.rows() != points.rows() || directions.cols() != points.cols())
        fail_input(who, "needs one direction per point, got " + std::to_string(directions.rows()) + " for " +
                            std::to_string(points.rows()) + " points");
    Eigen::MatrixXd nodes = span_nodes(points, closed);
    const Eigen::Index spans = nodes.rows() - 1, n = points.rows();
    Eigen::MatrixXd d0(spans, points.cols()), d1(spans, points.cols());
    for (Eigen::Index k = 0; k < spans; ++k) {
        const double l = (nodes.row(k + 1) - nodes.row(k)).norm();
        d0.row(k) = l * directions.row(k);
        d1.row(k) = l * directions.row((k + 1) % n);
    }
    return PiecewiseHermiteCurve(std::move(nodes), std::move(d0), std::move(d1));
}

}  // namespace cagd::spline
