#include "cagd/smoothing/surface_smoothing.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "cagd/core/errors.hpp"
#include "cagd/core/points.hpp"
#include "cagd/numeric/gauss_legendre.hpp"
#include "cagd/smoothing/elastic_line.hpp"

namespace cagd::smoothing {

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

// Validates the grid and heights; returns λ expanded to one per node.
Eigen::MatrixXd node_lambda(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda, bool allow_zero, const char* who) {
    require_increasing(x, 2, "x", who);
    require_increasing(y, 2, "y", who);
    const Eigen::Index nx = static_cast<Eigen::Index>(x.size()), ny = static_cast<Eigen::Index>(y.size());
    if (a.rows() != nx || a.cols() != ny)
        fail_input(who, "heights must be " + std::to_string(nx) + " x " + std::to_string(ny) + " (x by y), got " + std::to_string(a.rows()) + " x " + std::to_string(a.cols()));
    for (Eigen::Index i = 0; i < nx; ++i)
        for (Eigen::Index j = 0; j < ny; ++j)
            if (!std::isfinite(a(i, j))) fail_input(who, "height at node (" + std::to_string(i) + ", " + std::to_string(j) + ") is " + full_precision(a(i, j)));
    const bool scalar = lambda.rows() == 1 && lambda.cols() == 1;
    if (!scalar && (lambda.rows() != nx || lambda.cols() != ny))
        fail_input(who, "lambda must be one value or one per node (" + std::to_string(nx) + " x " + std::to_string(ny) + ")");
    Eigen::MatrixXd out = scalar ? Eigen::MatrixXd::Constant(nx, ny, lambda(0, 0)) : lambda;
    for (Eigen::Index i = 0; i < nx; ++i)
        for (Eigen::Index j = 0; j < ny; ++j)
            if (!std::isfinite(out(i, j)) || out(i, j) < 0.0 || (!allow_zero && out(i, j) == 0.0))
                fail_input(who, "lambda at node (" + std::to_string(i) + ", " + std::to_string(j) + ") is " + full_precision(out(i, j)) +
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

const numeric::GaussLegendreRule& gauss4() {
    static const numeric::GaussLegendreRule rule(4);
    return rule;
}

// Local m = 1 Hermite function of a cell side: corner c (0 left, 1 right), derivative order i of
// the node unknown, k-th derivative in the physical coordinate, side length h.
double hermite1(const spline::HosakaBasis& b, int c, int i, double h, double u, int k) {
    const double f = c == 0 ? b.p(i, u, k) : b.q(i, u, k);
    return f * std::pow(h, i - k);
}

double polynomial(const Eigen::RowVectorXd& coefficients, double s, int k) {
    double v = 0.0;
    for (Eigen::Index p = coefficients.size() - 1; p >= k; --p) {
        double falling = 1.0;
        for (int r = 0; r < k; ++r) falling *= static_cast<double>(p - r);
        v = v * s + coefficients(p) * falling;
    }
    // Horner above multiplies by s once per degree above k: correct for the derivative's power basis.
    return v;
}

}  // namespace

// ---- elastic net -------------------------------------------------------------------------------

ElasticNet elastic_net(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda_in) {
    const char* who = "cagd::smoothing::elastic_net";
    const Eigen::MatrixXd lambda = node_lambda(x, y, a, lambda_in, true, who);
    const long nx = static_cast<long>(x.size()), ny = static_cast<long>(y.size());
    const long px = (nx - 2) * ny, qy = nx * (ny - 2), nodes = nx * ny;
    // Unknowns: P at (i, j), i = 1..nx−2 (index (i−1) + (nx−2) j), then Q at (i, j), j = 1..ny−2.
    Triplets d, r;
    for (long j = 0; j < ny; ++j) {
        const auto node = [&](std::size_t i) { return static_cast<long>(i) + nx * j; };
        const auto col = [&](std::size_t i) { return static_cast<long>(i) - 1 + (nx - 2) * j; };
        add_second_difference(x, node, col, d);
        add_spline_matrix(x, col, r);
    }
    for (long i = 0; i < nx; ++i) {
        const auto node = [&](std::size_t j) { return i + nx * static_cast<long>(j); };
        const auto col = [&](std::size_t j) { return px + i + nx * (static_cast<long>(j) - 1); };
        add_second_difference(y, node, col, d);
        add_spline_matrix(y, col, r);
    }
    const long unknowns = px + qy;
    ElasticNet out;
    out.values = a;
    out.xx = Eigen::MatrixXd::Zero(nx, ny);
    out.yy = Eigen::MatrixXd::Zero(nx, ny);
    out.system_size = unknowns;
    if (unknowns == 0) return out;
    Sparse dm(nodes, unknowns), system(unknowns, unknowns);
    dm.setFromTriplets(d.begin(), d.end());
    system.setFromTriplets(r.begin(), r.end());
    const Eigen::VectorXd weights = Eigen::Map<const Eigen::VectorXd>(lambda.data(), nodes);  // column-major: i + nx j
    const Eigen::VectorXd data = Eigen::Map<const Eigen::VectorXd>(a.data(), nodes);
    const Sparse dt = dm.transpose();
    system += 6.0 * (dt * weights.asDiagonal() * dm);
    Eigen::SimplicialLDLT<Sparse> ldlt(system);
    if (ldlt.info() != Eigen::Success) fail_input(who, "the net's system (54) could not be factorised");
    const Eigen::VectorXd u = ldlt.solve(6.0 * (dt * data));
    out.factor_nonzeros = static_cast<long>(ldlt.matrixL().nestedExpression().nonZeros());
    const Eigen::VectorXd reaction = dm * u;  // δ_i²ζ^(2,0) + δ_j²ζ^(0,2) at every node
    for (long j = 0; j < ny; ++j)
        for (long i = 0; i < nx; ++i) {
            out.values(i, j) = a(i, j) - lambda(i, j) * reaction(i + nx * j);
            if (i > 0 && i + 1 < nx) out.xx(i, j) = u(i - 1 + (nx - 2) * j);
            if (j > 0 && j + 1 < ny) out.yy(i, j) = u(px + i + nx * (j - 1));
        }
    return out;
}

// ---- plates ------------------------------------------------------------------------------------

Eigen::Matrix3d plate_energy_form(PlateEnergy energy, double nu) {
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    switch (energy) {
        case PlateEnergy::poisson:
            if (!(nu >= 0.0 && nu < 0.5)) fail_input("cagd::smoothing::plate_energy_form", "Poisson's ratio must be in [0, 0.5), got " + full_precision(nu));
            c << 1, nu, 0, nu, 1, 0, 0, 0, 2 * (1 - nu);
            break;
        case PlateEnergy::no_poisson: c << 1, 0, 0, 0, 1, 0, 0, 0, 2; break;
        case PlateEnergy::no_twist: c << 1, 0, 0, 0, 1, 0, 0, 0, 0; break;
        case PlateEnergy::mean_curvature: c << 1, 1, 0, 1, 1, 0, 0, 0, 0; break;
    }
    return c;
}

double plate_energy(const surface::CartesianSurface& s, PlateEnergy energy, double nu) {
    const Eigen::Matrix3d c = plate_energy_form(energy, nu);
    const auto& rule = gauss4();
    double total = 0.0;
    for (std::size_t cx = 0; cx + 1 < s.x().size(); ++cx)
        for (std::size_t cy = 0; cy + 1 < s.y().size(); ++cy) {
            const double hx = s.x()[cx + 1] - s.x()[cx], hy = s.y()[cy + 1] - s.y()[cy];
            for (std::size_t p = 0; p < rule.nodes().size(); ++p)
                for (std::size_t q = 0; q < rule.nodes().size(); ++q) {
                    const double u = 0.5 * (rule.nodes()[p] + 1), v = 0.5 * (rule.nodes()[q] + 1);
                    const int ix = static_cast<int>(cx), iy = static_cast<int>(cy);
                    const Eigen::Vector3d h(s.derivative_in(ix, iy, u, v, 2, 0), s.derivative_in(ix, iy, u, v, 0, 2), s.derivative_in(ix, iy, u, v, 1, 1));
                    total += 0.25 * rule.weights()[p] * rule.weights()[q] * hx * hy * h.dot(c * h);
                }
        }
    return total;
}

PlateSmoothing plate_smoothing(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda_in, PlateEnergy energy,
                               double nu) {
    const char* who = "cagd::smoothing::plate_smoothing";
    const Eigen::MatrixXd lambda = node_lambda(x, y, a, lambda_in, false, who);
    const Eigen::Matrix3d c = plate_energy_form(energy, nu);
    static const spline::HosakaBasis basis(1);
    const auto& rule = gauss4();
    const long nx = static_cast<long>(x.size()), ny = static_cast<long>(y.size()), unknowns = 4 * nx * ny;
    const auto dof = [&](long i, long j, int di, int dj) { return 4 * (i + nx * j) + di + 2 * dj; };
    Triplets t;
    for (long cx = 0; cx + 1 < nx; ++cx)
        for (long cy = 0; cy + 1 < ny; ++cy) {
            const double hx = x[static_cast<std::size_t>(cx + 1)] - x[static_cast<std::size_t>(cx)];
            const double hy = y[static_cast<std::size_t>(cy + 1)] - y[static_cast<std::size_t>(cy)];
            Eigen::Matrix<double, 16, 16> k = Eigen::Matrix<double, 16, 16>::Zero();
            for (std::size_t p = 0; p < rule.nodes().size(); ++p)
                for (std::size_t q = 0; q < rule.nodes().size(); ++q) {
                    const double u = 0.5 * (rule.nodes()[p] + 1), v = 0.5 * (rule.nodes()[q] + 1);
                    Eigen::Matrix<double, 3, 16> b;
                    for (int l = 0; l < 16; ++l) {  // l = corner x (bit 0), corner y (bit 1), di (bit 2), dj (bit 3)
                        const int ca = l & 1, cb = (l >> 1) & 1, di = (l >> 2) & 1, dj = (l >> 3) & 1;
                        b(0, l) = hermite1(basis, ca, di, hx, u, 2) * hermite1(basis, cb, dj, hy, v, 0);
                        b(1, l) = hermite1(basis, ca, di, hx, u, 0) * hermite1(basis, cb, dj, hy, v, 2);
                        b(2, l) = hermite1(basis, ca, di, hx, u, 1) * hermite1(basis, cb, dj, hy, v, 1);
                    }
                    k += (0.25 * rule.weights()[p] * rule.weights()[q] * hx * hy) * (b.transpose() * c * b);
                }
            for (int r = 0; r < 16; ++r)
                for (int s = 0; s < 16; ++s)
                    t.emplace_back(dof(cx + (r & 1), cy + ((r >> 1) & 1), (r >> 2) & 1, (r >> 3) & 1), dof(cx + (s & 1), cy + ((s >> 1) & 1), (s >> 2) & 1, (s >> 3) & 1), k(r, s));
        }
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
    for (long j = 0; j < ny; ++j)
        for (long i = 0; i < nx; ++i) {
            t.emplace_back(dof(i, j, 0, 0), dof(i, j, 0, 0), 1.0 / lambda(i, j));
            rhs(dof(i, j, 0, 0)) = a(i, j) / lambda(i, j);
        }
    Sparse h(unknowns, unknowns);
    h.setFromTriplets(t.begin(), t.end());
    int terms = 0;
    const double floor = 1e-13 * h.coeffs().cwiseAbs().maxCoeff();
    for (long col = 0; col < unknowns; ++col) {  // symmetric: columns are the equations
        int n = 0;
        for (Sparse::InnerIterator it(h, col); it; ++it) n += std::abs(it.value()) > floor;
        terms = std::max(terms, n);
    }
    Eigen::SimplicialLDLT<Sparse> ldlt(h);
    if (ldlt.info() != Eigen::Success) fail_input(who, "the plate system could not be factorised");
    const Eigen::VectorXd z = ldlt.solve(rhs);
    std::vector<Eigen::MatrixXd> nodes;
    for (long j = 0; j < ny; ++j)
        for (long i = 0; i < nx; ++i) {
            Eigen::MatrixXd n(2, 2);
            n << z(dof(i, j, 0, 0)), z(dof(i, j, 0, 1)), z(dof(i, j, 1, 0)), z(dof(i, j, 1, 1));
            nodes.push_back(n);
        }
    return PlateSmoothing{surface::CartesianSurface(1, x, y, std::move(nodes)), terms, unknowns};
}

// ---- method (ii) -----------------------------------------------------------------------------------

BoundaryPlateSurface::BoundaryPlateSurface(int m, double y0, double y1, spline::ExplicitSpline boundary_data) : basis_(m), y0_(y0), y1_(y1), data_(std::move(boundary_data)) {
    if (!(y1 > y0)) fail_input("cagd::smoothing::BoundaryPlateSurface", "needs y0 < y1, got " + full_precision(y0) + ", " + full_precision(y1));
    if (data_.values.cols() != 2 * (m + 1)) fail_input("cagd::smoothing::BoundaryPlateSurface", "needs 2(m+1) boundary functions");
}

double BoundaryPlateSurface::derivative(double x, double y, int a, int b) const {
    const int m = basis_.m();
    if (a < 0 || a > 2 || b < 0) fail_input("cagd::smoothing::BoundaryPlateSurface::derivative", "needs 0 <= a <= 2 and b >= 0");
    const double l = y1_ - y0_, v = (y - y0_) / l;
    const Eigen::RowVectorXd f = data_.evaluate(x, a);
    double s = 0.0;
    for (int j = 0; j <= m; ++j) s += std::pow(l, j) * (f(j) * basis_.p(j, v, b) + f(m + 1 + j) * basis_.q(j, v, b));
    return s / std::pow(l, b);
}

BoundaryPlateSmoothing boundary_plate_smoothing(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda_in,
                                                PlateEnergy energy, int m, double nu) {
    const char* who = "cagd::smoothing::boundary_plate_smoothing";
    const Eigen::MatrixXd lambda = node_lambda(x, y, a, lambda_in, false, who);
    if (m < 1 || m > 4) fail_input(who, "needs 1 <= m <= 4, got " + std::to_string(m));
    const Eigen::Matrix3d c = plate_energy_form(energy, nu);
    const spline::HosakaBasis basis(m);
    const Eigen::Index nx = static_cast<Eigen::Index>(x.size()), ny = static_cast<Eigen::Index>(y.size());
    const double y0 = y.front(), y1 = y.back(), l = y1 - y0;
    // Prescribed boundary lines: the boundary rows smoothed by the elastic line.
    const auto row_lambda = [&](Eigen::Index j) {
        std::vector<double> v(static_cast<std::size_t>(nx));
        for (Eigen::Index i = 0; i < nx; ++i) v[static_cast<std::size_t>(i)] = lambda(i, j);
        return v;
    };
    const Eigen::VectorXd lower = elastic_line(x, a.col(0), row_lambda(0)).values().col(0);
    const Eigen::VectorXd upper = elastic_line(x, a.col(ny - 1), row_lambda(ny - 1)).values().col(0);
    const spline::ExplicitSpline cardinal = spline::hosaka_explicit_spline(x, Eigen::MatrixXd::Identity(nx, nx));
    const spline::ExplicitSpline known = spline::hosaka_explicit_spline(x, (Eigen::MatrixXd(nx, 2) << lower, upper).finished());
    const Eigen::Index unknowns = 2 * m * nx;  // (side k, order j = 1..m, node u) → (k m + j − 1) nx + u
    // ζ and its three second derivatives at (x, y) as known part + row · c.
    const auto rows = [&](double xx, double yy, Eigen::Matrix<double, 4, Eigen::Dynamic>& phi, Eigen::Vector4d& zeta0) {
        const double v = (yy - y0) / l;
        phi.setZero(4, unknowns);
        for (int dx = 0; dx <= 2; ++dx) {
            const Eigen::RowVectorXd s = cardinal.evaluate(xx, dx), k0 = known.evaluate(xx, dx);
            for (int dy = 0; dy <= 2; ++dy) {
                const int r = dx == 0 && dy == 0 ? 0 : dx == 2 && dy == 0 ? 1 : dx == 0 && dy == 2 ? 2 : dx == 1 && dy == 1 ? 3 : -1;
                if (r < 0) continue;
                const double scale = 1.0 / std::pow(l, dy);
                zeta0(r) = (k0(0) * basis.p(0, v, dy) + k0(1) * basis.q(0, v, dy)) * scale;
                for (int side = 0; side < 2; ++side)
                    for (int j = 1; j <= m; ++j) {
                        const double g = std::pow(l, j) * (side == 0 ? basis.p(j, v, dy) : basis.q(j, v, dy)) * scale;
                        phi.block(r, (side * m + j - 1) * nx, 1, nx) = g * s;
                    }
            }
        }
    };
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(unknowns, unknowns);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(unknowns);
    Eigen::Matrix<double, 4, Eigen::Dynamic> phi(4, unknowns);
    Eigen::Vector4d zeta0;
    const auto& rule = gauss4();
    for (Eigen::Index cx = 0; cx + 1 < nx; ++cx)
        for (Eigen::Index cy = 0; cy + 1 < ny; ++cy) {
            const double hx = x[static_cast<std::size_t>(cx + 1)] - x[static_cast<std::size_t>(cx)], hy = y[static_cast<std::size_t>(cy + 1)] - y[static_cast<std::size_t>(cy)];
            for (std::size_t p = 0; p < rule.nodes().size(); ++p)
                for (std::size_t q = 0; q < rule.nodes().size(); ++q) {
                    const double xx = x[static_cast<std::size_t>(cx)] + 0.5 * (rule.nodes()[p] + 1) * hx;
                    const double yy = y[static_cast<std::size_t>(cy)] + 0.5 * (rule.nodes()[q] + 1) * hy;
                    rows(xx, yy, phi, zeta0);
                    const double w = 0.25 * rule.weights()[p] * rule.weights()[q] * hx * hy;
                    // Order of h in the energy form: (ζxx, ζyy, ζxy) = rows 1, 2, 3.
                    const Eigen::MatrixXd b = phi.bottomRows(3);
                    h.noalias() += w * b.transpose() * c * b;
                    g.noalias() -= w * b.transpose() * (c * zeta0.tail<3>());
                }
        }
    for (Eigen::Index i = 0; i < nx; ++i)
        for (Eigen::Index j = 0; j < ny; ++j) {
            rows(x[static_cast<std::size_t>(i)], y[static_cast<std::size_t>(j)], phi, zeta0);
            const double w = 1.0 / lambda(i, j);
            h.noalias() += w * phi.row(0).transpose() * phi.row(0);
            g.noalias() += w * phi.row(0).transpose() * (a(i, j) - zeta0(0));
        }
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(h);
    if (ldlt.info() != Eigen::Success) fail_input(who, "the boundary-emphasised system could not be factorised");
    const Eigen::VectorXd coefficients = ldlt.solve(g);
    Eigen::MatrixXd boundary(nx, 2 * (m + 1));
    boundary.col(0) = lower;
    boundary.col(m + 1) = upper;
    for (int side = 0; side < 2; ++side)
        for (int j = 1; j <= m; ++j) boundary.col(side * (m + 1) + j) = coefficients.segment((side * m + j - 1) * nx, nx);
    return BoundaryPlateSmoothing{BoundaryPlateSurface(m, y0, y1, spline::hosaka_explicit_spline(x, boundary)), unknowns};
}

// ---- approximation 1 -----------------------------------------------------------------------------

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
                            one[p][q](i, k) += 0.5 * rule.weights()[g] * polynomial(psi.row(i), s, p) * polynomial(psi.row(k), s, q);
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
                            if (c(r, s) != 0.0) v += c(r, s) * scale[r] * scale[s] * one[order[r][0]][order[s][0]](i, k) * one[order[r][1]][order[s][1]](j, l);
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
                for (int j = 0; j < n; ++j) phi(p + 5 * q, i + n * j) = polynomial(psi.row(i), p - 2, 0) * polynomial(psi.row(j), q - 2, 0);
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
        while (parent[static_cast<std::size_t>(v)] != v) v = parent[static_cast<std::size_t>(v)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
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

surface::CartesianSurface local_orthogonal_smoothing(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, double lambda, PlateEnergy energy,
                                                     double nu) {
    const char* who = "cagd::smoothing::local_orthogonal_smoothing";
    node_lambda(x, y, a, Eigen::MatrixXd::Constant(1, 1, lambda), true, who);
    for (const auto* g : {&x, &y}) {
        const char* name = g == &x ? "x" : "y";
        if (g->size() < 5) fail_input(who, std::string("needs at least 5 ") + name + " grid lines (5 x 5 windows), got " + std::to_string(g->size()));
        const double step = ((*g).back() - (*g).front()) / static_cast<double>(g->size() - 1);
        for (std::size_t i = 1; i < g->size(); ++i)
            if (std::abs((*g)[i] - (*g)[i - 1] - step) > 1e-9 * step)
                fail_input(who, std::string("needs equally spaced ") + name + " (eq 60's windows), step " + std::to_string(i) + " is " + full_precision((*g)[i] - (*g)[i - 1]) +
                                    ", mean " + full_precision(step));
    }
    const double hx = x[1] - x[0], hy = y[1] - y[0];
    const Eigen::MatrixXd psi = discrete_orthonormal_polynomials(5, 3);
    const Eigen::MatrixXd phi = window_design(psi);
    const Eigen::LDLT<Eigen::MatrixXd> solver(phi.transpose() * phi + lambda * window_energy_matrix(psi, energy, hx, hy, nu));
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
                        for (int l = 0; l < 4; ++l) v += c(k + 4 * l) * polynomial(psi.row(k), i - ca, di) * polynomial(psi.row(l), b - cb, dj);
                    node(di, dj) = v / (std::pow(hx, di) * std::pow(hy, dj));
                }
            nodes.push_back(node);
        }
    return surface::CartesianSurface(1, x, y, std::move(nodes));
}

// ---- approximation 2 -----------------------------------------------------------------------------

surface::CartesianSurface net_spline_smoothing(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda) {
    return surface::cartesian_spline_surface(x, y, elastic_net(x, y, a, lambda).values);
}

}  // namespace cagd::smoothing
