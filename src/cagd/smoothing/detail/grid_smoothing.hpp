#pragma once
// What the surface smoothings of hosaka section 7 share (not installed: only smoothing/ .cpp files
// include it): the grid and λ checks, the second differences and spline rows of a grid line, the
// 4-point Gauss rule of the cell integrals, the m = 1 Hermite functions of a cell side.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cmath>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/core/points.hpp"
#include "cagd/numeric/gauss_legendre.hpp"
#include "cagd/spline/hosaka_basis.hpp"

namespace cagd::smoothing::detail {

using Sparse = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

// Validates the grid and heights; returns λ expanded to one per node.
inline Eigen::MatrixXd node_lambda(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a,
                                   const Eigen::MatrixXd& lambda, bool allow_zero, const char* who) {
    require_increasing(x, 2, "x", who);
    require_increasing(y, 2, "y", who);
    const Eigen::Index nx = static_cast<Eigen::Index>(x.size()), ny = static_cast<Eigen::Index>(y.size());
    if (a.rows() != nx || a.cols() != ny)
        fail_input(who, "heights must be " + std::to_string(nx) + " x " + std::to_string(ny) + " (x by y), got " +
                            std::to_string(a.rows()) + " x " + std::to_string(a.cols()));
    for (Eigen::Index i = 0; i < nx; ++i)
        for (Eigen::Index j = 0; j < ny; ++j)
            if (!std::isfinite(a(i, j)))
                fail_input(who, "height at node (" + std::to_string(i) + ", " + std::to_string(j) + ") is " +
                                    full_precision(a(i, j)));
    const bool scalar = lambda.rows() == 1 && lambda.cols() == 1;
    if (!scalar && (lambda.rows() != nx || lambda.cols() != ny))
        fail_input(
            who, "lambda must be one value or one per node (" + std::to_string(nx) + " x " + std::to_string(ny) + ")");
    Eigen::MatrixXd out = scalar ? Eigen::MatrixXd::Constant(nx, ny, lambda(0, 0)) : lambda;
    for (Eigen::Index i = 0; i < nx; ++i)
        for (Eigen::Index j = 0; j < ny; ++j)
            if (!std::isfinite(out(i, j)) || out(i, j) < 0.0 || (!allow_zero && out(i, j) == 0.0))
                fail_input(who, "lambda at node (" + std::to_string(i) + ", " + std::to_string(j) + ") is " +
                                    full_precision(out(i, j)) +
                                    (allow_zero ? "; it must be finite and >= 0" : "; it must be finite and > 0"));
    return out;
}

// δ² along one grid direction, as triplets: unknown column `col(c)` for interior line index c feeds
// rows node(c − 1), node(c), node(c + 1) with 1/l_c, −1/l_c − 1/l_{c+1}, 1/l_{c+1}.
template <typename Node, typename Col>
void add_second_difference(const std::vector<double>& g, Node node, Col col, Triplets& t) {
    for (std::size_t c = 1; c + 1 < g.size(); ++c) {
        const double left = g[c] - g[c - 1], right = g[c + 1] - g[c];
        t.emplace_back(node(c - 1), col(c), 1.0 / left);
        t.emplace_back(node(c), col(c), -1.0 / left - 1.0 / right);
        t.emplace_back(node(c + 1), col(c), 1.0 / right);
    }
}

// The spline C2 matrix along one line (interior unknowns), as triplets at offset `base`.
template <typename Col>
void add_spline_matrix(const std::vector<double>& g, Col col, Triplets& t) {
    for (std::size_t c = 1; c + 1 < g.size(); ++c) {
        const double left = g[c] - g[c - 1], right = g[c + 1] - g[c];
        t.emplace_back(col(c), col(c), 2.0 * (left + right));
        if (c > 1) t.emplace_back(col(c), col(c - 1), left);
        if (c + 2 < g.size()) t.emplace_back(col(c), col(c + 1), right);
    }
}

inline const numeric::GaussLegendreRule& gauss4() {
    static const numeric::GaussLegendreRule rule(4);
    return rule;
}

// Local m = 1 Hermite function of a cell side: corner c (0 left, 1 right), derivative order i of
// the node unknown, k-th derivative in the physical coordinate, side length h.
inline double hermite1(const spline::HosakaBasis& b, int c, int i, double h, double u, int k) {
    const double f = c == 0 ? b.p(i, u, k) : b.q(i, u, k);
    return f * std::pow(h, i - k);
}

inline double polynomial(const Eigen::RowVectorXd& coefficients, double s, int k) {
    double v = 0.0;
    for (Eigen::Index p = coefficients.size() - 1; p >= k; --p) {
        double falling = 1.0;
        for (int r = 0; r < k; ++r) falling *= static_cast<double>(p - r);
        v = v * s + coefficients(p) * falling;
    }
    // Horner above multiplies by s once per degree above k: correct for the derivative's power basis.
    return v;
}

}  // namespace cagd::smoothing::detail
