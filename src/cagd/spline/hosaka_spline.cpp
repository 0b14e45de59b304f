#include "cagd/spline/hosaka_spline.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/core/points.hpp"
#include "cagd/numeric/sparse_lu.hpp"
#include "cagd/numeric/tridiagonal.hpp"

namespace cagd::spline {

namespace {
Eigen::MatrixXd stack(int m, const std::vector<Eigen::MatrixXd>& parts, const char* who) {
    if (parts.empty()) fail_input(who, "needs at least one segment");
    const Eigen::Index dim = parts.front().cols();
    Eigen::MatrixXd out(static_cast<Eigen::Index>(parts.size()) * (m + 1), dim);
    for (std::size_t s = 0; s < parts.size(); ++s) {
        if (parts[s].rows() != m + 1 || parts[s].cols() != dim)
            fail_input(who, "segment " + std::to_string(s) + ": derivative sets must be (m+1) x dim = " +
                                std::to_string(m + 1) + " x " + std::to_string(dim));
        out.middleRows(static_cast<Eigen::Index>(s) * (m + 1), m + 1) = parts[s];
    }
    return out;
}
}  // namespace

HosakaCurve::HosakaCurve(int m, const std::vector<Eigen::MatrixXd>& start, const std::vector<Eigen::MatrixXd>& end)
    : basis_(m),
      start_(stack(m, start, "cagd::spline::HosakaCurve")),
      end_(stack(m, end, "cagd::spline::HosakaCurve")) {
    validate();
}

HosakaCurve::HosakaCurve(int m, Eigen::MatrixXd start, Eigen::MatrixXd end)
    : basis_(m), start_(std::move(start)), end_(std::move(end)) {
    validate();
}

void HosakaCurve::validate() const {
    const char* who = "cagd::spline::HosakaCurve";
    if (start_.rows() < m() + 1 || start_.rows() % (m() + 1) != 0 || end_.rows() != start_.rows() ||
        end_.cols() != start_.cols() || start_.cols() < 1)
        fail_input(who, "needs (m+1) rows per segment, the same for start and end derivatives, got " +
                            std::to_string(start_.rows()) + " and " + std::to_string(end_.rows()) + " rows");
    if (!start_.allFinite() || !end_.allFinite()) fail_input(who, "derivatives must be finite");
}

std::vector<double> HosakaCurve::breakpoints() const { return unit_piece_breakpoints(segments()); }

namespace {
// Rows first.. of segment s's jet at local t into out: row k − first = Σ_{i=0..m} p_i^(k)(t) S_i +
// q_i^(k)(t) E_i (eq 18), S_i, E_i the segment's start and end derivatives.
void hosaka_jet_rows(const HosakaBasis& basis, const Eigen::MatrixXd& start, const Eigen::MatrixXd& end, int m, int s,
                     double t, int first, Eigen::Ref<Eigen::MatrixXd> out) {
    constexpr int kStackM = 15;  // the basis values on the stack up to this m
    const int dim = static_cast<int>(start.cols());
    const Eigen::Index row0 = static_cast<Eigen::Index>(s) * (m + 1);
    std::vector<double> heap(m > kStackM ? 2 * static_cast<std::size_t>(m + 1) : 0);
    double stack[2 * (kStackM + 1)];
    double* p = m > kStackM ? heap.data() : stack;
    double* q = p + m + 1;
    out.setZero();
    for (Eigen::Index r = 0; r < out.rows(); ++r) {
        basis.values(t, first + static_cast<int>(r), p, q);
        for (int i = 0; i <= m; ++i)
            for (int c = 0; c < dim; ++c) out(r, c) += p[i] * start(row0 + i, c) + q[i] * end(row0 + i, c);
    }
}
}  // namespace

void HosakaCurve::evaluate_jet(double u, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const {
    const char* who = "cagd::spline::HosakaCurve::evaluate_jet";
    const int order = first + static_cast<int>(out.rows()) - 1;
    const auto [s, t] = side == JetSide::left ? locate_unit_piece_from_left(who, u, segments(), order)
                                              : locate_unit_piece(who, u, segments(), order);
    hosaka_jet_rows(basis_, start_, end_, m(), s, t, first, out);
}

Eigen::MatrixXd HosakaCurve::segment_jet(int s, double t, int order) const {
    if (s < 0 || s >= segments() || !(t >= 0.0 && t <= 1.0) || order < 0)
        fail_input("cagd::spline::HosakaCurve::segment_jet",
                   "needs 0 <= s < " + std::to_string(segments()) + ", t in [0, 1], order >= 0; got s = " +
                       std::to_string(s) + ", t = " + full_precision(t) + ", order " + std::to_string(order));
    Eigen::MatrixXd out(order + 1, dimension());
    hosaka_jet_rows(basis_, start_, end_, m(), s, t, 0, out);
    return out;
}

namespace {
// hosaka_c2_spline; `validated`: the points have passed require_valid_points(points, o.closed ? 3 : 2, …).
HosakaSpline hosaka_c2_spline_of(const PointList& points, const HosakaSplineOptions& o, bool validated) {
    const char* who = "cagd::spline::hosaka_c2_spline";
    if (!validated) require_valid_points(points, o.closed ? 3 : 2, true, o.closed, who);
    const int np = static_cast<int>(points.rows()), dim = static_cast<int>(points.cols());
    const int n = o.closed ? np : np - 1;  // segments
    if (!o.closed && o.end == HosakaEnd::tangent)
        for (const Eigen::VectorXd* v : {&o.start_tangent, &o.end_tangent})
            if (v->size() != dim || !v->allFinite())
                fail_input(who, "tangent ends need a finite start and end tangent of dimension " + std::to_string(dim));
    Eigen::MatrixXd A(n, dim);
    for (int i = 0; i < n; ++i) A.row(i) = points.row((i + 1) % np) - points.row(i);
    // |A_i| once (the result keeps them: the registry's dτ/dt), then k_i at the join after segment i
    // (closed: every segment; open: i = 0..n−2).
    std::vector<double> lengths = o.scale == HosakaScale::unit ? std::vector<double>(static_cast<std::size_t>(n), 1.0)
                                                               : chord_lengths(points, o.closed);
    std::vector<double> k(static_cast<std::size_t>(o.closed ? n : std::max(n - 1, 0)));
    for (std::size_t i = 0; i < k.size(); ++i)
        k[i] = o.scale == HosakaScale::unit ? 1.0 : lengths[i] / lengths[(i + 1) % static_cast<std::size_t>(n)];

    // The system of eq (20) and its solution; its arrays are freed before the curve is formed
    // (peak memory).
    Eigen::MatrixXd x = [&] {
        // Unknowns: B_0..B_{n−1}, and C_{n−1} for an open curve (index n). C_i = k_i B_{i+1} otherwise.
        const int unknowns = o.closed ? n : n + 1;
        // Open: the three diagonals directly (no triplets); closed: triplets for SparseLU.
        std::vector<Eigen::Triplet<double>> trip;
        std::vector<double> sub(o.closed ? 0 : static_cast<std::size_t>(unknowns), 0.0), diag(sub), sup(sub);
        const auto add = [&](int r, int c, double v) {
            if (o.closed)
                trip.emplace_back(r, c, v);
            else
                (c == r - 1 ? sub : c == r ? diag : sup)[static_cast<std::size_t>(r)] += v;
        };
        Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, dim);
        // Adds coefficient `c` times C_i to row r.
        const auto add_C = [&](int r, int i, double c) {
            if (o.closed)
                add(r, (i + 1) % n, c * k[static_cast<std::size_t>(i)]);
            else if (i == n - 1)
                add(r, n, c);
            else
                add(r, i + 1, c * k[static_cast<std::size_t>(i)]);
        };
        int row = 0;
        if (!o.closed) {                        // start condition
            if (o.end == HosakaEnd::natural) {  // R''(0) = 6A − 4B − 2C = 0
                add(row, 0, 2.0);
                add_C(row, 0, 1.0);
                rhs.row(row) = 3.0 * A.row(0);
            } else {
                add(row, 0, 1.0);
                rhs.row(row) = o.start_tangent.transpose();
            }
            ++row;
        }
        const int joins = o.closed ? n : n - 1;
        for (int j = 0; j < joins; ++j, ++row) {  // eq (20) at the join after segment j
            const double kj = k[static_cast<std::size_t>(j)];
            const int next = (j + 1) % n;
            add(row, j, 1.0);
            add(row, next, 2.0 * kj * (1.0 + kj));
            add_C(row, next, kj * kj);
            rhs.row(row) = 3.0 * (A.row(j) + kj * kj * A.row(next));
        }
        if (!o.closed) {                        // end condition
            if (o.end == HosakaEnd::natural) {  // R''(1) = −6A + 2B + 4C = 0
                add(row, n - 1, 1.0);
                add(row, n, 2.0);
                rhs.row(row) = 3.0 * A.row(n - 1);
            } else {
                add(row, n, 1.0);
                rhs.row(row) = o.end_tangent.transpose();
            }
        }
        Eigen::MatrixXd solution;
        if (!o.closed) {
            // Tridiagonal: the Thomas algorithm, O(n). With the unknowns scaled by |A_i| (chord scale)
            // the rows become m_j + 2(1 + k_j) m_{j+1} + k_j m_{j+2} (and 2m_0 + m_1, m_{n−1} + 2m_n at
            // natural ends), diagonally dominant, so elimination without pivoting is stable; for
            // k_i = 1 the rows are B_j + 4B_{j+1} + B_{j+2} already.
            solution = numeric::solve_tridiagonal(sub, diag, sup, std::move(rhs));
        } else {
            // Cyclic (corner entries): SparseLU; the natural ordering keeps the fill to the last rows and columns.
            Eigen::SparseMatrix<double> M(unknowns, unknowns);
            M.setFromTriplets(trip.begin(), trip.end());
            numeric::SparseLu lu(numeric::ColumnOrdering::natural);
            if (!lu.compute(M)) fail_input(who, "the system of eq (20) is singular for these points");
            solution = lu.solve(rhs);
        }
        return solution;
    }();
    A.resize(0, 0);
    // The curve's derivative rows from x (B_i = x_i; C_i = k_i B_{i+1}, or the unknown C_{n−1});
    // then B and C of the result, read back from them.
    Eigen::MatrixXd start(2 * n, dim), end(2 * n, dim);
    for (int i = 0; i < n; ++i) {
        start.row(2 * i) = points.row(i);
        start.row(2 * i + 1) = x.row(i);
        end.row(2 * i) = points.row((i + 1) % np);
        if (o.closed)
            end.row(2 * i + 1) = k[static_cast<std::size_t>(i)] * x.row((i + 1) % n);
        else if (i == n - 1)
            end.row(2 * i + 1) = x.row(n);
        else
            end.row(2 * i + 1) = k[static_cast<std::size_t>(i)] * x.row(i + 1);
    }
    x.resize(0, 0);
    Eigen::MatrixXd B(n, dim), C(n, dim);
    for (int i = 0; i < n; ++i) {
        B.row(i) = start.row(2 * i + 1);
        C.row(i) = end.row(2 * i + 1);
    }
    return HosakaSpline{HosakaCurve(1, std::move(start), std::move(end)), std::move(k), std::move(B), std::move(C),
                        std::move(lengths)};
}

}  // namespace

HosakaSpline hosaka_c2_spline(const PointList& points, const HosakaSplineOptions& o) {
    return hosaka_c2_spline_of(points, o, false);
}

HosakaSpline hosaka_c2_spline(const ValidPoints& points, const HosakaSplineOptions& o) {
    return hosaka_c2_spline_of(points.points(), o, points.cover(o.closed ? 3 : 2, o.closed));
}

HosakaSplineFit hosaka_spline(const PointList& points, int m, HosakaScale scale, bool closed) {
    HosakaSplineOptions o;
    o.scale = scale;
    o.closed = closed;
    return hosaka_spline(points, m, o);
}

namespace {
// hosaka_spline; `validated`: the points have passed require_valid_points(points, o.closed ? 3 : 2, …).
HosakaSplineFit hosaka_spline_of(const PointList& points, int m, const HosakaSplineOptions& o, bool validated) {
    const char* who = "cagd::spline::hosaka_spline";
    if (m < 1) fail_input(who, "m must be >= 1, got " + std::to_string(m));
    const bool closed = o.closed, tangent_ends = o.end == HosakaEnd::tangent && !closed;
    const HosakaScale scale = o.scale;
    if (!validated) require_valid_points(points, closed ? 3 : 2, true, closed, who);
    const int np = static_cast<int>(points.rows()), dim = static_cast<int>(points.cols());
    if (tangent_ends)
        for (const Eigen::VectorXd* t : {&o.start_tangent, &o.end_tangent})
            if (t->size() != dim || !t->allFinite())
                fail_input(who, "tangent ends need two finite vectors of dimension " + std::to_string(dim) +
                                    ", got one of size " + std::to_string(t->size()));
    const int segs = closed ? np : np - 1;
    // L_i = |A_i| / λ, λ = 2^e with the mean chord in [λ/2, λ): the τ-derivatives are then solved in
    // units of λ (τ = λσ), so the system's entries L^{j−k} (1 ≤ j ≤ m < k ≤ 2m) stay near 1 at any
    // scale of the points (with L = |A_i| they underflowed from 1e±60 on: 1e60^−5 at m = 3). The
    // curve is the same: segment rows are L^j times the σ-derivatives, |A_i|^j times the τ ones.
    std::vector<double> L(static_cast<std::size_t>(segs));
    double mean = 0.0;
    for (int i = 0; i < segs; ++i) {
        L[static_cast<std::size_t>(i)] =
            scale == HosakaScale::unit ? 1.0 : (points.row((i + 1) % np) - points.row(i)).norm();
        mean += L[static_cast<std::size_t>(i)] / segs;
    }
    int exponent = 0;
    if (scale == HosakaScale::chord) std::frexp(mean, &exponent);
    for (double& l : L) l = std::ldexp(l, -exponent);
    const HosakaBasis b(m);
    // Unknown (node, j), j = 1..m: the j-th τ-derivative at the node.
    const auto unknown = [&](int node, int j) { return node * m + (j - 1); };
    const int unknowns = np * m;
    std::vector<Eigen::Triplet<double>> trip;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, dim);
    // Adds sign × (k-th τ-derivative of segment s at local t) to row r: the point values go to the rhs.
    const auto add_derivative = [&](int r, int s, double t, int k, double sign) {
        const double l = L[static_cast<std::size_t>(s)], inv = sign / std::pow(l, k);
        const int a = s, c = (s + 1) % np;
        rhs.row(r) -= inv * (b.p(0, t, k) * points.row(a) + b.q(0, t, k) * points.row(c));
        for (int j = 1; j <= m; ++j) {
            trip.emplace_back(r, unknown(a, j), inv * b.p(j, t, k) * std::pow(l, j));
            trip.emplace_back(r, unknown(c, j), inv * b.q(j, t, k) * std::pow(l, j));
        }
    };
    int row = 0;
    for (int node = 0; node < np; ++node)
        for (int k = m + 1; k <= 2 * m; ++k, ++row) {
            const bool has_left = closed || node > 0, has_right = closed || node < np - 1;
            if (has_left && has_right) {  // continuity of the k-th τ-derivative
                add_derivative(row, (node - 1 + segs) % segs, 1.0, k, 1.0);
                add_derivative(row, node % segs, 0.0, k, -1.0);
            } else if (tangent_ends && k == 2 * m) {  // clamped end: the given t-derivative replaces order 2m
                const int s = has_right ? 0 : segs - 1;
                trip.emplace_back(row, unknown(node, 1), 1.0);
                rhs.row(row) =
                    (has_right ? o.start_tangent : o.end_tangent).transpose() / L[static_cast<std::size_t>(s)];
            } else if (has_right) {  // natural start: the k-th derivative vanishes
                add_derivative(row, 0, 0.0, k, 1.0);
            } else {  // natural end
                add_derivative(row, segs - 1, 1.0, k, 1.0);
            }
        }
    Eigen::SparseMatrix<double> M(unknowns, unknowns);
    M.setFromTriplets(trip.begin(), trip.end());
    numeric::SparseLu lu;
    if (!lu.compute(M))
        return {{Status::no_solution, "hosaka: the continuity system of order m = " + std::to_string(m) +
                                          " is singular in double precision for these points (chords of very different "
                                          "lengths: a lower m may do)"},
                std::nullopt};
    const Eigen::MatrixXd x = lu.solve(rhs);
    if (!x.allFinite())
        return {{Status::not_representable, "hosaka: the continuity system of order m = " + std::to_string(m) +
                                                " overflows double precision for these points"},
                std::nullopt};
    Eigen::MatrixXd start((m + 1) * segs, dim), end((m + 1) * segs, dim);
    for (int s = 0; s < segs; ++s) {
        const int a = s, c = (s + 1) % np;
        const double l = L[static_cast<std::size_t>(s)];
        start.row(s * (m + 1)) = points.row(a);
        end.row(s * (m + 1)) = points.row(c);
        for (int j = 1; j <= m; ++j) {
            start.row(s * (m + 1) + j) = std::pow(l, j) * x.row(unknown(a, j));
            end.row(s * (m + 1) + j) = std::pow(l, j) * x.row(unknown(c, j));
        }
    }
    return {{}, HosakaCurve(m, std::move(start), std::move(end))};
}

}  // namespace

HosakaSplineFit hosaka_spline(const PointList& points, int m, const HosakaSplineOptions& o) {
    return hosaka_spline_of(points, m, o, false);
}

HosakaSplineFit hosaka_spline(const ValidPoints& points, int m, const HosakaSplineOptions& o) {
    return hosaka_spline_of(points.points(), m, o, points.cover(o.closed ? 3 : 2, o.closed));
}

ExplicitSpline hosaka_explicit_spline(const std::vector<double>& x, const Eigen::MatrixXd& values) {
    const char* who = "cagd::spline::hosaka_explicit_spline";
    const int n = static_cast<int>(x.size());
    if (n < 2) fail_input(who, "needs at least 2 abscissae, got " + std::to_string(n));
    if (values.rows() != n || values.cols() < 1)
        fail_input(who, "needs one value row per abscissa, got " + std::to_string(values.rows()) + " rows for " +
                            std::to_string(n));
    if (!values.allFinite()) fail_input(who, "values must be finite");
    require_increasing(x, 2, "x", who);
    const auto h = [&](int i) { return x[static_cast<std::size_t>(i + 1)] - x[static_cast<std::size_t>(i)]; };
    std::vector<Eigen::Triplet<double>> trip;
    Eigen::MatrixXd rhs(n, values.cols());
    trip.emplace_back(0, 0, 2.0);
    trip.emplace_back(0, 1, 1.0);
    rhs.row(0) = 3.0 * (values.row(1) - values.row(0)) / h(0);
    for (int i = 1; i + 1 < n; ++i) {
        trip.emplace_back(i, i - 1, 1.0 / h(i - 1));
        trip.emplace_back(i, i, 2.0 * (1.0 / h(i - 1) + 1.0 / h(i)));
        trip.emplace_back(i, i + 1, 1.0 / h(i));
        rhs.row(i) = 3.0 * (values.row(i) - values.row(i - 1)) / (h(i - 1) * h(i - 1)) +
                     3.0 * (values.row(i + 1) - values.row(i)) / (h(i) * h(i));
    }
    trip.emplace_back(n - 1, n - 2, 1.0);
    trip.emplace_back(n - 1, n - 1, 2.0);
    rhs.row(n - 1) = 3.0 * (values.row(n - 1) - values.row(n - 2)) / h(n - 2);
    Eigen::SparseMatrix<double> M(n, n);
    M.setFromTriplets(trip.begin(), trip.end());
    numeric::SparseLu lu;
    if (!lu.compute(M)) fail_input(who, "singular system of eq (23)");
    return ExplicitSpline{x, values, lu.solve(rhs)};
}

Eigen::RowVectorXd ExplicitSpline::evaluate(double at, int k) const {
    const char* who = "cagd::spline::ExplicitSpline::evaluate";
    if (!(at >= x.front() && at <= x.back()))
        fail_input(who, "x = " + full_precision(at) + " outside [" + full_precision(x.front()) + ", " +
                            full_precision(x.back()) + "]");
    const auto it = std::upper_bound(x.begin(), x.end(), at);
    const int i = std::clamp(static_cast<int>(it - x.begin()) - 1, 0, static_cast<int>(x.size()) - 2);
    return evaluate_in(
        i,
        (at - x[static_cast<std::size_t>(i)]) / (x[static_cast<std::size_t>(i + 1)] - x[static_cast<std::size_t>(i)]),
        k);
}

Eigen::RowVectorXd ExplicitSpline::evaluate_in(int i, double u, int k) const {
    const char* who = "cagd::spline::ExplicitSpline::evaluate_in";
    if (i < 0 || i + 1 >= static_cast<int>(x.size()))
        fail_input(who, "interval " + std::to_string(i) + " does not exist");
    if (k < 0 || k > 3) fail_input(who, "derivative order must be 0..3, got " + std::to_string(k));
    static const HosakaBasis basis(1);
    const double l = x[static_cast<std::size_t>(i + 1)] - x[static_cast<std::size_t>(i)];
    // eq (21): l^j on the j-th end derivative; d/dx = (1/l) d/du.
    return std::pow(l, -k) * (basis.p(0, u, k) * values.row(i) + basis.q(0, u, k) * values.row(i + 1) +
                              l * basis.p(1, u, k) * slopes.row(i) + l * basis.q(1, u, k) * slopes.row(i + 1));
}

double ExplicitSpline::bending_energy() const {
    double e = 0.0;
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
        const Eigen::RowVectorXd y0 = evaluate_in(static_cast<int>(i), 0.0, 2),
                                 y1 = evaluate_in(static_cast<int>(i), 1.0, 2);
        e += (x[i + 1] - x[i]) / 3.0 *
             (y0.squaredNorm() + y0.dot(y1) + y1.squaredNorm());  // ∫ of a linear function squared
    }
    return e;
}

}  // namespace cagd::spline
