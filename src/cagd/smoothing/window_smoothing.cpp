#include "cagd/smoothing/window_smoothing.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "cagd/smoothing/detail/grid_smoothing.hpp"

namespace cagd::smoothing {

using namespace detail;

Eigen::MatrixXd discrete_orthonormal_polynomials(int points, int degree) {
    const char* who = "cagd::smoothing::discrete_orthonormal_polynomials";
    if (points < 2 || degree < 0 || degree >= points) fail_input(who, "needs points >= 2 and 0 <= degree < points");
    Eigen::VectorXd s(points);
    for (int k = 0; k < points; ++k) s(k) = k - 0.5 * (points - 1);
    Eigen::MatrixXd coefficients = Eigen::MatrixXd::Zero(degree + 1, degree + 1);
    Eigen::MatrixXd values(points, degree + 1);  // ψ_i at the points
    for (int i = 0; i <= degree; ++i) {
        Eigen::RowVectorXd c = Eigen::RowVectorXd::Zero(degree + 1);
        c(i) = 1.0;
        Eigen::VectorXd v = s.array().pow(i);
        for (int r = 0; r < 2; ++r)  // Gram–Schmidt, twice for accuracy
            for (int k = 0; k < i; ++k) {
                const double proj = values.col(k).dot(v);
                v -= proj * values.col(k);
                c -= proj * coefficients.row(k);
            }
        const double norm = v.norm();
        values.col(i) = v / norm;
        coefficients.row(i) = c / norm;
    }
    return coefficients;
}

Eigen::MatrixXd discrete_gram_matrix(const Eigen::MatrixXd& psi, int points) {
    if (points < 1) fail_input("cagd::smoothing::discrete_gram_matrix", "needs points >= 1");
    Eigen::MatrixXd values(points, psi.rows());
    for (int k = 0; k < points; ++k)
        for (Eigen::Index i = 0; i < psi.rows(); ++i) values(k, i) = polynomial(psi.row(i), k - 0.5 * (points - 1), 0);
    return values.transpose() * values;
}

Eigen::MatrixXd window_energy_matrix(const Eigen::MatrixXd& psi, PlateEnergy energy, double hx, double hy, double nu) {
    const Eigen::Matrix3d c = plate_energy_form(energy, nu);
    const int n = static_cast<int>(psi.rows());
    // a[p][q](i, k) = ∫_{−2}^{2} ψ_i^(p) ψ_k^(q) ds (4-point Gauss per unit step: exact for the degrees).
    const auto& rule = gauss4();
    Eigen::MatrixXd one[3][3];
    for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) {
            one[p][q] = Eigen::MatrixXd::Zero(n, n);
            for (int i = 0; i < n; ++i)
                for (int k = 0; k < n; ++k)
                    for (int step = -2; step < 2; ++step)
                        for (std::size_t g = 0; g < rule.nodes().size(); ++g) {
                            const double s = step + 0.5 * (rule.nodes()[g] + 1);
                            one[p][q](i, k) +=
                                0.5 * rule.weights()[g] * polynomial(psi.row(i), s, p) * polynomial(psi.row(k), s, q);
                        }
        }
    const int order[3][2] = {{2, 0}, {0, 2}, {1, 1}};  // ζxx, ζyy, ζxy
    const double scale[3] = {1 / (hx * hx), 1 / (hy * hy), 1 / (hx * hy)};
    Eigen::MatrixXd e = Eigen::MatrixXd::Zero(n * n, n * n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                for (int l = 0; l < n; ++l) {
                    double v = 0.0;
                    for (int r = 0; r < 3; ++r)
                        for (int s = 0; s < 3; ++s)
                            if (c(r, s) != 0.0)
                                v += c(r, s) * scale[r] * scale[s] * one[order[r][0]][order[s][0]](i, k) *
                                     one[order[r][1]][order[s][1]](j, l);
                    e(i + n * j, k + n * l) = hx * hy * v;
                }
    return e;
}

namespace {
// Φ: window node (p, q) (row p + 5q) × coefficient (i, j) (column i + n j).
Eigen::MatrixXd window_design(const Eigen::MatrixXd& psi) {
    const int n = static_cast<int>(psi.rows());
    Eigen::MatrixXd phi(25, n * n);
    for (int p = 0; p < 5; ++p)
        for (int q = 0; q < 5; ++q)
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    phi(p + 5 * q, i + n * j) = polynomial(psi.row(i), p - 2, 0) * polynomial(psi.row(j), q - 2, 0);
    return phi;
}
}  // namespace

std::vector<int> window_block_sizes(const Eigen::MatrixXd& psi, PlateEnergy energy, double nu) {
    const Eigen::MatrixXd phi = window_design(psi);
    const Eigen::MatrixXd m = phi.transpose() * phi + window_energy_matrix(psi, energy, 1.0, 1.0, nu);
    const int n = static_cast<int>(m.rows());
    const double floor = 1e-12 * m.cwiseAbs().maxCoeff();
    std::vector<int> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), 0);
    const auto find = [&](int v) {
        while (parent[static_cast<std::size_t>(v)] != v)
            v = parent[static_cast<std::size_t>(v)] =
                parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
        return v;
    };
    for (int r = 0; r < n; ++r)
        for (int s = r + 1; s < n; ++s)
            if (std::abs(m(r, s)) > floor) parent[static_cast<std::size_t>(find(r))] = find(s);
    std::vector<int> size(static_cast<std::size_t>(n), 0);
    for (int v = 0; v < n; ++v) ++size[static_cast<std::size_t>(find(v))];
    std::vector<int> out;
    for (int s : size)
        if (s > 0) out.push_back(s);
    std::sort(out.begin(), out.end());
    return out;
}

surface::CartesianSurface local_orthogonal_smoothing(const std::vector<double>& x, const std::vector<double>& y,
                                                     const Eigen::MatrixXd& a, double lambda, PlateEnergy energy,
                                                     double nu) {
    const char* who = "cagd::smoothing::local_orthogonal_smoothing";
    node_lambda(x, y, a, Eigen::MatrixXd::Constant(1, 1, lambda), true, who);
    for (const auto* g : {&x, &y}) {
        const char* name = g == &x ? "x" : "y";
        if (g->size() < 5)
            fail_input(who, std::string("needs at least 5 ") + name + " grid lines (5 x 5 windows), got " +
                                std::to_string(g->size()));
        const double step = ((*g).back() - (*g).front()) / static_cast<double>(g->size() - 1);
        for (std::size_t i = 1; i < g->size(); ++i)
            if (std::abs((*g)[i] - (*g)[i - 1] - step) > 1e-9 * step)
                fail_input(who, std::string("needs equally spaced ") + name + " (eq 60's windows), step " +
                                    std::to_string(i) + " is " + full_precision((*g)[i] - (*g)[i - 1]) + ", mean " +
                                    full_precision(step));
    }
    const double hx = x[1] - x[0], hy = y[1] - y[0];
    const Eigen::MatrixXd psi = discrete_orthonormal_polynomials(5, 3);
    const Eigen::MatrixXd phi = window_design(psi);
    const Eigen::LDLT<Eigen::MatrixXd> solver(phi.transpose() * phi +
                                              lambda * window_energy_matrix(psi, energy, hx, hy, nu));
    const int nx = static_cast<int>(x.size()), ny = static_cast<int>(y.size());
    std::vector<Eigen::MatrixXd> nodes;
    for (int b = 0; b < ny; ++b)
        for (int i = 0; i < nx; ++i) {
            const int ca = std::clamp(i, 2, nx - 3), cb = std::clamp(b, 2, ny - 3);
            Eigen::VectorXd window(25);
            for (int p = 0; p < 5; ++p)
                for (int q = 0; q < 5; ++q) window(p + 5 * q) = a(ca - 2 + p, cb - 2 + q);
            const Eigen::VectorXd c = solver.solve(phi.transpose() * window);
            Eigen::MatrixXd node = Eigen::MatrixXd::Zero(2, 2);
            for (int di = 0; di <= 1; ++di)
                for (int dj = 0; dj <= 1; ++dj) {
                    double v = 0.0;
                    for (int k = 0; k < 4; ++k)
                        for (int l = 0; l < 4; ++l)
                            v += c(k + 4 * l) * polynomial(psi.row(k), i - ca, di) * polynomial(psi.row(l), b - cb, dj);
                    node(di, dj) = v / (std::pow(hx, di) * std::pow(hy, dj));
                }
            nodes.push_back(node);
        }
    return surface::CartesianSurface(1, x, y, std::move(nodes));
}

}  // namespace cagd::smoothing
