#include "cagd/smoothing/plate_smoothing.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "cagd/smoothing/detail/grid_smoothing.hpp"

namespace cagd::smoothing {

using namespace detail;

Eigen::Matrix3d plate_energy_form(PlateEnergy energy, double nu) {
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    switch (energy) {
        case PlateEnergy::poisson:
            if (!(nu >= 0.0 && nu < 0.5))
                fail_input("cagd::smoothing::plate_energy_form",
                           "Poisson's ratio must be in [0, 0.5), got " + full_precision(nu));
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
                    const Eigen::Vector3d h(s.derivative_in(ix, iy, u, v, 2, 0), s.derivative_in(ix, iy, u, v, 0, 2),
                                            s.derivative_in(ix, iy, u, v, 1, 1));
                    total += 0.25 * rule.weights()[p] * rule.weights()[q] * hx * hy * h.dot(c * h);
                }
        }
    return total;
}

PlateSmoothing plate_smoothing(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a,
                               const Eigen::MatrixXd& lambda_in, PlateEnergy energy, double nu) {
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
                    t.emplace_back(dof(cx + (r & 1), cy + ((r >> 1) & 1), (r >> 2) & 1, (r >> 3) & 1),
                                   dof(cx + (s & 1), cy + ((s >> 1) & 1), (s >> 2) & 1, (s >> 3) & 1), k(r, s));
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

}  // namespace cagd::smoothing
