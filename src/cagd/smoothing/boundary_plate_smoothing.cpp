#include "cagd/smoothing/boundary_plate_smoothing.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "cagd/smoothing/elastic_line.hpp"

#include "cagd/smoothing/detail/grid_smoothing.hpp"

namespace cagd::smoothing {

using namespace detail;

BoundaryPlateSurface::BoundaryPlateSurface(int m, double y0, double y1, spline::ExplicitSpline boundary_data)
    : basis_(m), y0_(y0), y1_(y1), data_(std::move(boundary_data)) {
    if (!(y1 > y0))
        fail_input("cagd::smoothing::BoundaryPlateSurface",
                   "needs y0 < y1, got " + full_precision(y0) + ", " + full_precision(y1));
    if (data_.values.cols() != 2 * (m + 1))
        fail_input("cagd::smoothing::BoundaryPlateSurface", "needs 2(m+1) boundary functions");
}

double BoundaryPlateSurface::derivative(double x, double y, int a, int b) const {
    const int m = basis_.m();
    if (a < 0 || a > 2 || b < 0)
        fail_input("cagd::smoothing::BoundaryPlateSurface::derivative", "needs 0 <= a <= 2 and b >= 0");
    const double l = y1_ - y0_, v = (y - y0_) / l;
    const Eigen::RowVectorXd f = data_.evaluate(x, a);
    double s = 0.0;
    for (int j = 0; j <= m; ++j) s += std::pow(l, j) * (f(j) * basis_.p(j, v, b) + f(m + 1 + j) * basis_.q(j, v, b));
    return s / std::pow(l, b);
}

BoundaryPlateSmoothing boundary_plate_smoothing(const std::vector<double>& x, const std::vector<double>& y,
                                                const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda_in,
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
    const spline::ExplicitSpline known =
        spline::hosaka_explicit_spline(x, (Eigen::MatrixXd(nx, 2) << lower, upper).finished());
    const Eigen::Index unknowns = 2 * m * nx;  // (side k, order j = 1..m, node u) → (k m + j − 1) nx + u
    // ζ and its three second derivatives at (x, y) as known part + row · c.
    const auto rows = [&](double xx, double yy, Eigen::Matrix<double, 4, Eigen::Dynamic>& phi, Eigen::Vector4d& zeta0) {
        const double v = (yy - y0) / l;
        phi.setZero(4, unknowns);
        for (int dx = 0; dx <= 2; ++dx) {
            const Eigen::RowVectorXd s = cardinal.evaluate(xx, dx), k0 = known.evaluate(xx, dx);
            for (int dy = 0; dy <= 2; ++dy) {
                const int r = dx == 0 && dy == 0   ? 0
                              : dx == 2 && dy == 0 ? 1
                              : dx == 0 && dy == 2 ? 2
                              : dx == 1 && dy == 1 ? 3
                                                   : -1;
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
            const double hx = x[static_cast<std::size_t>(cx + 1)] - x[static_cast<std::size_t>(cx)],
                         hy = y[static_cast<std::size_t>(cy + 1)] - y[static_cast<std::size_t>(cy)];
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
        for (int j = 1; j <= m; ++j)
            boundary.col(side * (m + 1) + j) = coefficients.segment((side * m + j - 1) * nx, nx);
    return BoundaryPlateSmoothing{BoundaryPlateSurface(m, y0, y1, spline::hosaka_explicit_spline(x, boundary)),
                                  unknowns};
}

}  // namespace cagd::smoothing
