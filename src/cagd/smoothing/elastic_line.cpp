#include "cagd/smoothing/elastic_line.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "cagd/numeric/gauss_legendre.hpp"
#include "cagd/numeric/pentadiagonal.hpp"
#include "cagd/numeric/sparse_lu.hpp"
#include "cagd/numeric/tridiagonal.hpp"
#include "cagd/spline/hosaka_basis.hpp"

namespace cagd::smoothing {

namespace {

using Sparse = Eigen::SparseMatrix<double>;

void require_data(const std::vector<double>& x, const Eigen::MatrixXd& a, const char* who) {
    require_increasing(x, 2, "x", who);
    if (a.rows() != static_cast<Eigen::Index>(x.size()) || a.cols() < 1)
        fail_input(who, "needs one value row per abscissa, got " + std::to_string(a.rows()) + " rows for " +
                            std::to_string(x.size()) + " abscissae");
    for (Eigen::Index i = 0; i < a.rows(); ++i)
        for (Eigen::Index c = 0; c < a.cols(); ++c)
            if (!std::isfinite(a(i, c)))
                fail_input(who, "value a[" + std::to_string(i) + "] is " + full_precision(a(i, c)) +
                                    "; values must be finite");
}

// Q: (n+1) × (n−1), (Q M)_i = δ²M_i for M with M_0 = M_n = 0 (column c ↔ interior node c + 1).
Sparse second_difference(const std::vector<double>& x) {
    const int n = static_cast<int>(x.size()) - 1;
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(3 * static_cast<std::size_t>(std::max(n - 1, 0)));
    for (int c = 1; c < n; ++c) {
        const double left = x[static_cast<std::size_t>(c)] - x[static_cast<std::size_t>(c - 1)];
        const double right = x[static_cast<std::size_t>(c + 1)] - x[static_cast<std::size_t>(c)];
        t.emplace_back(c - 1, c - 1, 1.0 / left);
        t.emplace_back(c, c - 1, -1.0 / left - 1.0 / right);
        t.emplace_back(c + 1, c - 1, 1.0 / right);
    }
    Sparse q(n + 1, std::max(n - 1, 0));
    q.setFromTriplets(t.begin(), t.end());
    return q;
}

// The natural spline's tridiagonal C2 matrix R for the interior M_1..M_{n−1}: l_i, 2(l_i + l_{i+1}), l_{i+1}.
struct Tridiagonal {
    std::vector<double> sub, diag, sup;
};
Tridiagonal spline_matrix(const std::vector<double>& x) {
    const std::size_t n = x.size() - 1;
    Tridiagonal r;
    for (std::size_t i = 1; i < n; ++i) {
        const double left = x[i] - x[i - 1], right = x[i + 1] - x[i];
        r.sub.push_back(left);
        r.diag.push_back(2.0 * (left + right));
        r.sup.push_back(right);
    }
    return r;
}

// Node values y = a − Λ δ²M and the curve of eq (52) from the interior M.
ElasticLine assemble_line(const std::vector<double>& x, const Eigen::MatrixXd& a, const std::vector<double>& lambda,
                          const Eigen::MatrixXd& interior) {
    const Eigen::Index n = static_cast<Eigen::Index>(x.size()) - 1;
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n + 1, a.cols());
    if (n > 1) m.middleRows(1, n - 1) = interior;
    Eigen::MatrixXd y = a;
    for (Eigen::Index i = 0; i <= n; ++i) {  // δ²M_i, the terms beyond the ends dropped
        const std::size_t k = static_cast<std::size_t>(i);
        if (lambda[k] == 0.0) continue;
        if (i < n) y.row(i) -= lambda[k] * (m.row(i + 1) - m.row(i)) / (x[k + 1] - x[k]);
        if (i > 0) y.row(i) += lambda[k] * (m.row(i) - m.row(i - 1)) / (x[k] - x[k - 1]);
    }
    // Slopes of the cubic with values y and second derivatives M (the spline's y'_i).
    Eigen::MatrixXd slopes(n + 1, a.cols());
    for (Eigen::Index i = 0; i < n; ++i) {
        const double l = x[static_cast<std::size_t>(i + 1)] - x[static_cast<std::size_t>(i)];
        slopes.row(i) = (y.row(i + 1) - y.row(i)) / l - l * (2.0 * m.row(i) + m.row(i + 1)) / 6.0;
    }
    const double l = x[static_cast<std::size_t>(n)] - x[static_cast<std::size_t>(n - 1)];
    slopes.row(n) = (y.row(n) - y.row(n - 1)) / l + l * (m.row(n - 1) + 2.0 * m.row(n)) / 6.0;
    return ElasticLine{spline::ExplicitSpline{x, y, slopes}, m};
}

}  // namespace

SplineMatrices natural_spline_matrices(const std::vector<double>& x) {
    require_increasing(x, 3, "x", "cagd::smoothing::natural_spline_matrices");
    const Tridiagonal t = spline_matrix(x);
    const Eigen::Index inner = static_cast<Eigen::Index>(t.diag.size());
    SplineMatrices m{Eigen::MatrixXd::Zero(inner, inner), Eigen::MatrixXd(second_difference(x))};
    for (Eigen::Index c = 0; c < inner; ++c) {
        m.r(c, c) = t.diag[static_cast<std::size_t>(c)];
        if (c > 0) m.r(c, c - 1) = t.sub[static_cast<std::size_t>(c)];
        if (c + 1 < inner) m.r(c, c + 1) = t.sup[static_cast<std::size_t>(c)];
    }
    return m;
}

std::vector<double> per_point_lambda(const std::vector<double>& lambda, std::size_t count, const char* who) {
    if (lambda.size() != 1 && lambda.size() != count)
        fail_input(who, "needs one lambda for all points or one per point (" + std::to_string(count) + "), got " +
                            std::to_string(lambda.size()));
    for (std::size_t i = 0; i < lambda.size(); ++i)
        if (!std::isfinite(lambda[i]) || lambda[i] < 0.0)
            fail_input(who, "lambda[" + std::to_string(i) + "] = " + full_precision(lambda[i]) +
                                "; lambda = EI/k must be finite and >= 0");
    return lambda.size() == count ? lambda : std::vector<double>(count, lambda.front());
}

ElasticLine elastic_line(const std::vector<double>& x, const Eigen::MatrixXd& a, const std::vector<double>& lambda_in) {
    const char* who = "cagd::smoothing::elastic_line";
    require_data(x, a, who);
    const std::vector<double> lambda = per_point_lambda(lambda_in, x.size(), who);
    const std::size_t n = x.size() - 1, inner = n - 1;  // interior unknowns M_1..M_{n−1}
    if (n == 1) return assemble_line(x, a, lambda, Eigen::MatrixXd(0, a.cols()));
    // (R + 6 QᵀΛQ) in its three bands: column c ↔ node k = c + 1, whose Q column has
    // (α_k, −α_k − α_{k+1}, α_{k+1}) at rows k − 1, k, k + 1, α_k = 1/l_k.
    const auto alpha = [&](std::size_t k) { return 1.0 / (x[k] - x[k - 1]); };
    std::vector<double> diag(inner), first(inner > 0 ? inner - 1 : 0), second(inner > 1 ? inner - 2 : 0);
    Eigen::MatrixXd rhs(static_cast<Eigen::Index>(inner), a.cols());
    for (std::size_t c = 0; c < inner; ++c) {
        const std::size_t k = c + 1;
        const double ak = alpha(k), ak1 = alpha(k + 1);
        diag[c] = 2.0 * (x[k + 1] - x[k - 1]) +
                  6.0 * (lambda[k - 1] * ak * ak + lambda[k] * (ak + ak1) * (ak + ak1) + lambda[k + 1] * ak1 * ak1);
        if (c + 1 < inner)
            first[c] =
                (x[k + 1] - x[k]) + 6.0 * (-lambda[k] * (ak + ak1) * ak1 - lambda[k + 1] * ak1 * (ak1 + alpha(k + 2)));
        if (c + 2 < inner) second[c] = 6.0 * lambda[k + 1] * ak1 * alpha(k + 2);
        rhs.row(static_cast<Eigen::Index>(c)) =
            6.0 * ((a.row(static_cast<Eigen::Index>(k + 1)) - a.row(static_cast<Eigen::Index>(k))) * ak1 -
                   (a.row(static_cast<Eigen::Index>(k)) - a.row(static_cast<Eigen::Index>(k - 1))) * ak);
    }
    return assemble_line(x, a, lambda, numeric::solve_symmetric_pentadiagonal(diag, first, second, std::move(rhs)));
}

ElasticLine elastic_line(const std::vector<double>& x, const Eigen::MatrixXd& a, double lambda) {
    return elastic_line(x, a, std::vector<double>{lambda});
}

ElasticLineIteration elastic_line_iterative(const std::vector<double>& x, const Eigen::MatrixXd& a,
                                            const std::vector<double>& lambda_in, double tolerance,
                                            int max_iterations) {
    const char* who = "cagd::smoothing::elastic_line_iterative";
    require_data(x, a, who);
    const std::vector<double> lambda = per_point_lambda(lambda_in, x.size(), who);
    if (!(tolerance > 0.0) || max_iterations < 1)
        fail_input(who, "needs tolerance > 0 and max_iterations >= 1, got " + full_precision(tolerance));
    const Sparse q = second_difference(x);
    ElasticLineIteration out;
    if (x.size() == 2) {
        out.line = assemble_line(x, a, lambda, Eigen::MatrixXd(0, a.cols()));
        return out;
    }
    const Tridiagonal r = spline_matrix(x);
    const Eigen::VectorXd weights =
        Eigen::Map<const Eigen::VectorXd>(lambda.data(), static_cast<Eigen::Index>(lambda.size()));
    const Sparse qt = q.transpose();
    const Sparse coupling = 6.0 * (qt * weights.asDiagonal() * q);
    const Eigen::MatrixXd rhs = 6.0 * (qt * a);
    Eigen::MatrixXd m = numeric::solve_tridiagonal(r.sub, r.diag, r.sup, rhs);  // λ = 0: the spline
    double previous = INFINITY;
    for (int k = 1; k <= max_iterations; ++k) {
        const Eigen::MatrixXd next = numeric::solve_tridiagonal(r.sub, r.diag, r.sup, rhs - coupling * m);
        const double step = (next - m).cwiseAbs().maxCoeff();
        m = next;
        out.iterations = k;
        if (std::isfinite(previous) && previous > 0.0) out.contraction = step / previous;
        const double size = m.cwiseAbs().maxCoeff();
        if (!std::isfinite(step) || !std::isfinite(size)) break;
        if (step <= tolerance * std::max(size, 1e-300)) {
            out.line = assemble_line(x, a, lambda, m);
            return out;
        }
        if (k > 20 && out.contraction >= 1.0) break;  // growing corrections: ρ ≥ 1
        previous = step;
    }
    out.outcome = Outcome{Status::no_convergence,
                          "the iteration from lambda = 0 did not converge: ratio of successive corrections " +
                              full_precision(out.contraction) + " after " + std::to_string(out.iterations) +
                              " iterations (it converges only when 6 R^-1 Q^T Lambda Q has spectral radius < 1)"};
    if (m.allFinite()) out.line = assemble_line(x, a, lambda, m);
    return out;
}

std::vector<double> chord_parameters(const PointList& points, const char* who) {
    require_valid_points(points, 2, true, false, who);
    std::vector<double> t(static_cast<std::size_t>(points.rows()), 0.0);
    for (Eigen::Index i = 1; i < points.rows(); ++i)
        t[static_cast<std::size_t>(i)] =
            t[static_cast<std::size_t>(i - 1)] + (points.row(i) - points.row(i - 1)).norm();
    return t;
}

ElasticLine elastic_line_parametric(const PointList& points, const std::vector<double>& lambda) {
    return elastic_line(chord_parameters(points, "cagd::smoothing::elastic_line_parametric"), points, lambda);
}

HermiteElasticLine elastic_line_hermite(const std::vector<double>& x, const Eigen::VectorXd& a,
                                        const std::vector<double>& lambda_in,
                                        const ElasticLineConstraints& constraints) {
    const char* who = "cagd::smoothing::elastic_line_hermite";
    require_data(x, a, who);
    const std::vector<double> lambda = per_point_lambda(lambda_in, x.size(), who);
    const int nodes = static_cast<int>(x.size()), dofs = 2 * nodes;  // y_i at 2i, y'_i at 2i + 1

    // Constraint rows: λ_i = 0 points, then fixed values, then slopes.
    std::vector<std::pair<int, double>> rows;  // (dof, value)
    std::set<int> fixed;
    const auto fix = [&](int dof, double value, const std::string& what) {
        if (!fixed.insert(dof).second) fail_input(who, what + " is constrained twice");
        rows.emplace_back(dof, value);
    };
    for (int i = 0; i < nodes; ++i)
        if (lambda[static_cast<std::size_t>(i)] == 0.0) fix(2 * i, a(i), point_label(i) + " (lambda = 0)");
    for (const auto& [j, c] : constraints.fixed_values) {
        if (j < 0 || j >= nodes)
            fail_input(who, "fixed value index " + std::to_string(j) + " outside 0.." + std::to_string(nodes - 1));
        if (!std::isfinite(c))
            fail_input(who, "fixed value at point " + std::to_string(j) + " is " + full_precision(c));
        fix(2 * j, c, point_label(j));
    }
    for (const auto& [slope, dof, name] : {std::tuple{constraints.start_slope, 1, "start slope"},
                                           std::tuple{constraints.end_slope, dofs - 1, "end slope"}})
        if (slope) {
            if (!std::isfinite(*slope)) fail_input(who, std::string(name) + " is " + full_precision(*slope));
            fix(dof, *slope, name);
        }

    // H = ∫ (y'')² (eq 46, exact) + springs; g = springs · a.
    static const spline::HosakaBasis basis(1);
    static const numeric::GaussLegendreRule rule(3);
    const int size = dofs + static_cast<int>(rows.size());
    std::vector<Eigen::Triplet<double>> t;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
    for (int s = 0; s + 1 < nodes; ++s) {
        const double l = x[static_cast<std::size_t>(s + 1)] - x[static_cast<std::size_t>(s)];
        const int dof[4] = {2 * s, 2 * s + 1, 2 * s + 2, 2 * s + 3};
        const auto second = [&](int b, double u) {  // d²/dx² of the basis function of local dof b
            switch (b) {
                case 0: return basis.p(0, u, 2) / (l * l);
                case 1: return basis.p(1, u, 2) / l;
                case 2: return basis.q(0, u, 2) / (l * l);
                default: return basis.q(1, u, 2) / l;
            }
        };
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                t.emplace_back(dof[r], dof[c],
                               l * rule.integrate([&](double u) { return second(r, u) * second(c, u); }, 0.0, 1.0));
    }
    for (int i = 0; i < nodes; ++i) {
        const double lam = lambda[static_cast<std::size_t>(i)];
        if (lam == 0.0) continue;
        t.emplace_back(2 * i, 2 * i, 1.0 / lam);
        rhs(2 * i) = a(i) / lam;
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const int r = dofs + static_cast<int>(k);
        t.emplace_back(r, rows[k].first, 1.0);
        t.emplace_back(rows[k].first, r, 1.0);
        rhs(r) = rows[k].second;
    }
    Sparse kkt(size, size);
    kkt.setFromTriplets(t.begin(), t.end());
    numeric::SparseLu lu;
    if (!lu.compute(kkt))
        fail_input(who, "the constrained system is singular (constraints inconsistent with the data)");
    const Eigen::VectorXd z = lu.solve(rhs);
    Eigen::MatrixXd y(nodes, 1), slopes(nodes, 1);
    for (int i = 0; i < nodes; ++i) {
        y(i, 0) = z(2 * i);
        slopes(i, 0) = z(2 * i + 1);
    }
    HermiteElasticLine out{spline::ExplicitSpline{x, y, slopes}, z.tail(static_cast<Eigen::Index>(rows.size())), 0.0};
    out.energy = elastic_line_energy(out.curve, a, lambda);
    return out;
}

double elastic_line_energy(const spline::ExplicitSpline& curve, const Eigen::VectorXd& a,
                           const std::vector<double>& lambda_in, int column) {
    const char* who = "cagd::smoothing::elastic_line_energy";
    const std::vector<double> lambda = per_point_lambda(lambda_in, curve.x.size(), who);
    if (a.size() != curve.values.rows() || column < 0 || column >= curve.values.cols())
        fail_input(who, "needs one datum per abscissa and a column of the curve, got column " + std::to_string(column));
    double springs = 0.0, bending = 0.0;
    for (Eigen::Index i = 0; i < a.size(); ++i)
        if (lambda[static_cast<std::size_t>(i)] > 0.0)
            springs += std::pow(curve.values(i, column) - a(i), 2) / lambda[static_cast<std::size_t>(i)];
    for (std::size_t s = 0; s + 1 < curve.x.size(); ++s) {
        const int seg = static_cast<int>(s);
        const double m0 = curve.evaluate_in(seg, 0.0, 2)(column),
                     m1 = curve.evaluate_in(seg, 1.0, 2)(column);  // y'' is linear
        bending += (m0 * m0 + m0 * m1 + m1 * m1) * (curve.x[s + 1] - curve.x[s]) / 3.0;
    }
    return 0.5 * springs + 0.5 * bending;
}

int inflection_count(const ElasticLine& line, int column) {
    const Eigen::VectorXd m = line.second_derivatives.col(column);
    const double floor = 1e-12 * m.cwiseAbs().maxCoeff();
    int count = 0, sign = 0;
    for (Eigen::Index i = 0; i < m.size(); ++i) {
        if (std::abs(m(i)) <= floor) continue;
        const int s = m(i) > 0 ? 1 : -1;
        if (sign != 0 && s != sign) ++count;
        sign = s;
    }
    return count;
}

}  // namespace cagd::smoothing
