#include "cagd/aesthetic/typical_surface.hpp"

#include <cmath>
#include <string>

#include "cagd/aesthetic/typical_bezier.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::aesthetic {

namespace {
const char* kSurfaceNetWho = "cagd::aesthetic::typical_surface_net";

void check_boundary(const Eigen::MatrixXd& b, const char* name) {
    if (b.cols() != 3 || b.rows() < 2)
        fail_input(kSurfaceNetWho, std::string(name) + " boundary must be at least 2 points in 3-D, got " +
                                       std::to_string(b.rows()) + "x" + std::to_string(b.cols()));
    if (!b.allFinite()) fail_input(kSurfaceNetWho, std::string(name) + " boundary points must be finite");
    for (Eigen::Index i = 0; i + 1 < b.rows(); ++i)
        if ((b.row(i + 1) - b.row(i)).norm() == 0.0)
            fail_input(kSurfaceNetWho, std::string(name) + " boundary: zero-length edge between points " +
                                           std::to_string(i) + " and " + std::to_string(i + 1));
}
}  // namespace

Eigen::Vector3d rotated_fourth_point(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10, const Eigen::Vector3d& p01,
                                     double angle) {
    const char* who = "cagd::aesthetic::rotated_fourth_point";
    if (!std::isfinite(angle)) fail_input(who, "angle = " + full_precision(angle) + " is not finite");
    const Eigen::Vector3d axis = p01 - p10;
    if (!(axis.norm() > 0.0)) fail_input(who, "degenerate diagonal: P(i+1,j) and P(i,j+1) coincide");
    const Eigen::Vector3d parallelogram = p10 + p01 - p00;
    return p10 + Eigen::AngleAxisd(angle, axis.normalized()) * (parallelogram - p10);
}

surface::ControlNet typical_surface_net(const Eigen::MatrixXd& u_boundary, const Eigen::MatrixXd& v_boundary,
                                        double angle) {
    check_boundary(u_boundary, "u (P(i,0))");
    check_boundary(v_boundary, "v (P(0,j))");
    if (!std::isfinite(angle)) fail_input(kSurfaceNetWho, "angle = " + full_precision(angle) + " is not finite");
    const double size = std::max(u_boundary.cwiseAbs().maxCoeff(), v_boundary.cwiseAbs().maxCoeff());
    if ((u_boundary.row(0) - v_boundary.row(0)).norm() > 1e-12 * std::max(size, 1.0))
        fail_input(kSurfaceNetWho, "the boundaries do not share P(0,0): distance " +
                                       full_precision((u_boundary.row(0) - v_boundary.row(0)).norm()));
    const Eigen::Index m = u_boundary.rows() - 1, n = v_boundary.rows() - 1;
    std::vector<std::vector<Eigen::Vector3d>> p(static_cast<std::size_t>(m + 1),
                                                std::vector<Eigen::Vector3d>(static_cast<std::size_t>(n + 1)));
    for (Eigen::Index i = 0; i <= m; ++i) p[static_cast<std::size_t>(i)][0] = u_boundary.row(i).transpose();
    for (Eigen::Index j = 0; j <= n; ++j) p[0][static_cast<std::size_t>(j)] = v_boundary.row(j).transpose();
    for (std::size_t i = 0; i < static_cast<std::size_t>(m); ++i)
        for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j)
            p[i + 1][j + 1] = rotated_fourth_point(p[i][j], p[i + 1][j], p[i][j + 1], angle);
    surface::ControlNet net;
    for (std::size_t c = 0; c < 3; ++c) {
        net[c].resize(m + 1, n + 1);
        for (Eigen::Index i = 0; i <= m; ++i)
            for (Eigen::Index j = 0; j <= n; ++j)
                net[c](i, j) =
                    p[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)](static_cast<Eigen::Index>(c));
    }
    return net;
}

surface::ControlNet log_aesthetic_typical_net(double alpha_u, double alpha_v, double length, int degree, double angle) {
    const TypicalPolygon pu = scale_one_typical_polygon(alpha_u, length, degree),
                         pv = scale_one_typical_polygon(alpha_v, length, degree);
    Eigen::MatrixXd ub = Eigen::MatrixXd::Zero(pu.points.rows(), 3), vb = Eigen::MatrixXd::Zero(pv.points.rows(), 3);
    ub.col(0) = pu.points.col(0);
    ub.col(2) = pu.points.col(1);
    vb.col(1) = pv.points.col(0);
    vb.col(2) = pv.points.col(1);
    return typical_surface_net(ub, vb, angle);
}

}  // namespace cagd::aesthetic
