#include "cagd/export/bezier_form.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace cagd::exports {

namespace {

constexpr const char* kToBezierWho = "cagd::exports::to_bezier";
// Interior samples per piece for the error bound (see the header), and the safety factor on the
// sampled second derivative of the error.
constexpr int kErrorSamples = 32;
constexpr double kSecondDerivativeSafety = 2.0;
// A piece shorter than this fraction of the parameter range is not halved further: the curve has
// a feature (a cusp, an infinite curvature) no polynomial piece follows.
constexpr double kShortestPiece = 1e-12;

void check_options(const ApproximationOptions& o) {
    if (o.degree != 3 && o.degree != 5)
        fail_input(kToBezierWho, "approximation degree must be 3 or 5, got " + std::to_string(o.degree));
    if (!(o.relative_tolerance >= 1e-14 && o.relative_tolerance <= 0.1))
        fail_input(kToBezierWho,
                   "relative tolerance must be in [1e-14, 0.1], got " + full_precision(o.relative_tolerance));
    if (o.max_pieces < 1)
        fail_input(kToBezierWho, "max_pieces must be at least 1, got " + std::to_string(o.max_pieces));
}

// The Hermite piece of degree q ∈ {3, 5} on [a, b] and its error bound (header).
std::pair<Eigen::MatrixXd, double> hermite_piece(const Curve& c, int q, double a, double b) {
    const int order = (q - 1) / 2;
    const Eigen::MatrixXd J0 = c.jet(a, order);
    const Eigen::MatrixXd J1 = c.jet_from_left(b, order);
    Eigen::MatrixXd control = bezier_from_end_jets(q, b - a, J0, J1);
    const BezierCurve piece(control, a, b);
    double max_e = 0.0, max_e2 = 0.0;
    const double delta = (b - a) / (kErrorSamples + 1);
    for (int j = 1; j <= kErrorSamples; ++j) {
        const double t = a + delta * j;
        const Eigen::MatrixXd r = c.jet(t, 2), s = piece.jet(t, 2);
        max_e = std::max(max_e, (r.row(0) - s.row(0)).norm());
        max_e2 = std::max(max_e2, (r.row(2) - s.row(2)).norm());
    }
    const double bound = max_e + delta * delta / 8.0 * kSecondDerivativeSafety * max_e2;
    return {std::move(control), std::isfinite(bound) ? bound : std::numeric_limits<double>::infinity()};
}

BezierForm approximate(const Curve& c, int degree, const ApproximationOptions& o) {
    BezierForm f;
    f.tolerance = o.relative_tolerance * sampled_diagonal(c);
    f.pieces.degree = degree;
    const std::vector<double> br = c.breakpoints();
    const double shortest = kShortestPiece * (c.t_max() - c.t_min());
    std::vector<Eigen::MatrixXd> accepted;
    f.pieces.breaks.push_back(br.front());
    for (std::size_t s = 0; s + 1 < br.size(); ++s) {
        // Depth-first halving keeps the accepted pieces in parameter order.
        std::vector<std::pair<double, double>> todo{{br[s], br[s + 1]}};
        while (!todo.empty()) {
            const auto [a, b] = todo.back();
            todo.pop_back();
            auto [control, bound] = hermite_piece(c, degree, a, b);
            if (bound > f.tolerance && b - a > shortest &&
                static_cast<int>(accepted.size() + todo.size()) + 2 <= o.max_pieces) {
                const double mid = 0.5 * (a + b);
                todo.emplace_back(mid, b);
                todo.emplace_back(a, mid);
                continue;
            }
            if (bound > f.tolerance && f.outcome.ok())
                f.outcome = {Status::no_convergence,
                             "the degree-" + std::to_string(degree) + " approximation reaches " +
                                 full_precision(bound) + " > tolerance " + full_precision(f.tolerance) + " on [" +
                                 full_precision(a) + ", " + full_precision(b) + "] (" +
                                 (b - a <= shortest ? "a piece of 1e-12 of the range"
                                                    : "the limit of " + std::to_string(o.max_pieces) + " pieces") +
                                 ")"};
            f.max_distance = std::max(f.max_distance, bound);
            accepted.push_back(std::move(control));
            f.pieces.breaks.push_back(b);
        }
    }
    f.pieces.control.resize(static_cast<Eigen::Index>(accepted.size()) * (degree + 1), c.dimension());
    for (std::size_t i = 0; i < accepted.size(); ++i)
        f.pieces.control.middleRows(static_cast<Eigen::Index>(i) * (degree + 1), degree + 1) = accepted[i];
    return f;
}

}  // namespace

double sampled_diagonal(const Curve& c) {
    const std::vector<double> br = c.breakpoints();
    Eigen::VectorXd lo = Eigen::VectorXd::Constant(c.dimension(), std::numeric_limits<double>::infinity()), hi = -lo;
    for (std::size_t s = 0; s + 1 < br.size(); ++s)
        for (int j = 0; j <= 32; ++j) {
            const Eigen::VectorXd x = c.point(br[s] + (br[s + 1] - br[s]) * j / 32.0);
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
        }
    return (hi - lo).norm();
}

BezierPieces exact_bezier_pieces(const Curve& c) {
    const int p = c.polynomial_degree();
    if (p < 0)
        fail_input("cagd::exports::exact_bezier_pieces",
                   "the curve is not polynomial (polynomial_degree() = " + std::to_string(p) + ")");
    BezierPieces out;
    out.degree = p;
    out.breaks = c.breakpoints();
    const int K = out.pieces();
    out.control.resize(static_cast<Eigen::Index>(K) * (p + 1), c.dimension());
    const int start_order = p / 2, end_order = std::max(0, p - p / 2 - 1);
    for (int i = 0; i < K; ++i) {
        const double a = out.breaks[static_cast<std::size_t>(i)], b = out.breaks[static_cast<std::size_t>(i) + 1];
        out.control.middleRows(static_cast<Eigen::Index>(i) * (p + 1), p + 1) =
            bezier_from_end_jets(p, b - a, c.jet(a, start_order), c.jet_from_left(b, end_order));
    }
    return out;
}

BezierPieces elevate_degree(const BezierPieces& in, int degree) {
    if (degree < in.degree)
        fail_input("cagd::exports::elevate_degree",
                   "cannot lower degree " + std::to_string(in.degree) + " to " + std::to_string(degree));
    BezierPieces out = in;
    for (int p = in.degree; p < degree; ++p) {
        const int K = out.pieces();
        Eigen::MatrixXd next(static_cast<Eigen::Index>(K) * (p + 2), out.dimension());
        for (int i = 0; i < K; ++i) {
            const Eigen::MatrixXd b = out.piece(i);
            const Eigen::Index r0 = static_cast<Eigen::Index>(i) * (p + 2);
            next.row(r0) = b.row(0);
            next.row(r0 + p + 1) = b.row(p);
            for (int k = 1; k <= p; ++k) {
                const double w = static_cast<double>(k) / (p + 1);
                next.row(r0 + k) = w * b.row(k - 1) + (1.0 - w) * b.row(k);
            }
        }
        out.control = std::move(next);
        out.degree = p + 1;
    }
    return out;
}

BezierCurve piece_curve(const BezierPieces& pieces, int i) {
    if (i < 0 || i >= pieces.pieces())
        fail_input("cagd::exports::piece_curve",
                   "piece " + std::to_string(i) + " outside 0.." + std::to_string(pieces.pieces() - 1));
    return BezierCurve(pieces.piece(i), pieces.breaks[static_cast<std::size_t>(i)],
                       pieces.breaks[static_cast<std::size_t>(i) + 1]);
}

BezierForm to_bezier(const Curve& c, const ApproximationOptions& o) {
    check_options(o);
    if (c.polynomial_degree() >= 0) {
        BezierForm f;
        f.pieces = exact_bezier_pieces(c);
        f.exact = true;
        return f;
    }
    return approximate(c, o.degree, o);
}

BezierForm to_bezier_of_degree(const Curve& c, int degree, const ApproximationOptions& o) {
    if (degree < 1 || degree > 5) fail_input(kToBezierWho, "degree must be in 1..5, got " + std::to_string(degree));
    const int p = c.polynomial_degree();
    if (p >= 0 && p <= degree) {
        check_options(o);
        BezierForm f;
        f.pieces = elevate_degree(exact_bezier_pieces(c), degree);
        f.exact = true;
        return f;
    }
    ApproximationOptions with = o;
    with.degree = degree;
    check_options(with);
    return approximate(c, degree, with);
}

BezierPieces bezier_pieces_from_power(const PowerPieces& power) {
    const char* who = "cagd::exports::bezier_pieces_from_power";
    const std::size_t K = power.coefficients.size();
    if (K == 0 || power.breaks.size() != K + 1)
        fail_input(who, "needs one more break than pieces, has " + std::to_string(power.breaks.size()) +
                            " breaks and " + std::to_string(K) + " pieces");
    if (power.degree < 0) fail_input(who, "degree " + std::to_string(power.degree) + " < 0");
    const Eigen::Index dim = power.coefficients.front().cols();
    BezierPieces b;
    b.degree = power.degree;
    b.breaks = power.breaks;
    b.control.resize(static_cast<Eigen::Index>(K) * (power.degree + 1), dim);
    for (std::size_t i = 0; i < K; ++i) {
        const double x0 = power.breaks[i], x1 = power.breaks[i + 1];
        if (!std::isfinite(x0) || !std::isfinite(x1) || !(x0 < x1))
            fail_input(who, "breaks must be finite and increase (break " + std::to_string(i + 1) + ")");
        const Eigen::MatrixXd& c = power.coefficients[i];
        if (c.rows() != power.degree + 1 || c.cols() != dim || !c.allFinite())
            fail_input(who, "piece " + std::to_string(i) + " must have degree + 1 rows of " + std::to_string(dim) +
                                " finite coefficients");
        Eigen::MatrixXd monomial(power.degree + 1, dim);  // row j: coefficient of s^j, s = (t − x0)/h
        double hj = 1.0;
        for (int j = 0; j <= power.degree; ++j, hj *= x1 - x0) monomial.row(j) = c.row(power.degree - j) * hj;
        b.control.middleRows(static_cast<Eigen::Index>(i) * (power.degree + 1), power.degree + 1) =
            bernstein_from_monomial(monomial);
    }
    return b;
}

PowerPieces power_pieces(const BezierPieces& pieces) {
    PowerPieces w;
    w.degree = pieces.degree;
    w.breaks = pieces.breaks;
    for (int i = 0; i < pieces.pieces(); ++i) {
        const Eigen::MatrixXd monomial = monomial_from_bernstein(pieces.piece(i));
        const double h = pieces.breaks[static_cast<std::size_t>(i) + 1] - pieces.breaks[static_cast<std::size_t>(i)];
        Eigen::MatrixXd c(pieces.degree + 1, pieces.dimension());
        double hj = 1.0;
        for (int j = 0; j <= pieces.degree; ++j, hj *= h) c.row(pieces.degree - j) = monomial.row(j) / hj;
        w.coefficients.push_back(std::move(c));
    }
    return w;
}

}  // namespace cagd::exports
