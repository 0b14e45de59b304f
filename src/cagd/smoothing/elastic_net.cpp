#include "cagd/smoothing/elastic_net.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "cagd/smoothing/detail/grid_smoothing.hpp"

namespace cagd::smoothing {

using namespace detail;

ElasticNet elastic_net(const std::vector<double>& x, const std::vector<double>& y, const Eigen::MatrixXd& a,
                       const Eigen::MatrixXd& lambda_in) {
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

surface::CartesianSurface net_spline_smoothing(const std::vector<double>& x, const std::vector<double>& y,
                                               const Eigen::MatrixXd& a, const Eigen::MatrixXd& lambda) {
    return surface::cartesian_spline_surface(x, y, elastic_net(x, y, a, lambda).values);
}

}  // namespace cagd::smoothing
