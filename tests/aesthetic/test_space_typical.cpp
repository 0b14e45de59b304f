// typical_curves sections 4–5: Alexa's product, log-aesthetic space curves, typical Bézier space
// curves, torsion and the LTG, Bézier patches and their curvature, nonstationary typical surfaces.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cagd/aesthetic/log_aesthetic_space_curve.hpp"
#include "cagd/aesthetic/space_typical_bezier.hpp"
#include "cagd/aesthetic/typical_surface.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/analysis/surface_curvature.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/numeric/alexa_product.hpp"
#include "cagd/spline/bezier.hpp"
#include "cagd/surface/bezier_patch.hpp"

using namespace cagd;
using namespace cagd::aesthetic;

TEST(LogAestheticSpaceCurve, ConstantRatesGiveTheHelix) {
    const double k = 2.0, tau = 0.8, w = std::hypot(k, tau);
    LogAestheticSpaceParameters p;
    p.curvature = {1.5, 0.0, std::pow(1.0 / k, 1.5)};  // ρ^α = c1, ρ = 1/κ
    p.torsion = {1.2, 0.0, std::pow(1.0 / tau, 1.2)};
    p.length = 3.0;
    const LogAestheticSpaceCurve c(p);
    // Darboux vector D = (τ, 0, κ) is constant; t(s) = R_D(ωs) e_x integrated in closed form.
    const Eigen::Vector3d d = Eigen::Vector3d(tau, 0.0, k) / w, ex = Eigen::Vector3d::UnitX();
    const Eigen::Vector3d perp = ex - d.dot(ex) * d;
    for (double s : {0.0, 0.7, 1.9, 3.0}) {
        const Eigen::Vector3d expect =
            d.dot(ex) * d * s + std::sin(w * s) / w * perp + (1.0 - std::cos(w * s)) / w * d.cross(perp);
        EXPECT_LT((c.point(s) - expect).norm(), 1e-11) << "s = " << s;
        if (s > 0) {
            EXPECT_NEAR(analysis::curvature_arc_derivative(c, s), 0.0, 1e-10);
            EXPECT_NEAR(analysis::torsion(c, s), tau, 1e-10);
        }
    }
}

TEST(LogAestheticSpaceCurve, GraphsAreLinesOfSlopesAlphaAndBeta) {
    LogAestheticSpaceParameters p;
    p.curvature = {-0.7, 2.0, 0.5};
    p.torsion = {2.5, 1.0, 0.3};
    p.length = 1.5;
    const LogAestheticSpaceCurve c(p);
    EXPECT_NEAR(analysis::lcg_slope(c, 0.0, 1.5, 50).slope, -0.7, 1e-8);
    EXPECT_NEAR(analysis::ltg_slope(c, 0.0, 1.5, 50).slope, 2.5, 1e-8);
    const Eigen::Matrix3d f = c.frame(1.5);
    EXPECT_LT((f.transpose() * f - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-11);
    // Singular start (normalised law): the position is still finite and the frame orthonormal.
    const LogAestheticSpaceCurve n(normalized_log_aesthetic_space_parameters(1.5, 1.2, 1.0));
    EXPECT_TRUE(n.point(1.0).allFinite());
    EXPECT_NEAR(n.curvature_angle(1.0), 1.5, 1e-14);  // θ_κ = α s^{(α−1)/α} at s = 1
    EXPECT_THROW(n.jet(0.0, 2), InvalidInput);        // κ unbounded at s = 0
}

TEST(LogAestheticSpaceCurve, RejectsBadParameters) {
    EXPECT_THROW(normalized_log_aesthetic_space_parameters(1.0, 1.2, 1.0), InvalidInput);
    EXPECT_THROW(normalized_log_aesthetic_space_parameters(1.5, 0.5, 1.0), InvalidInput);
    EXPECT_NO_THROW(normalized_log_aesthetic_space_parameters(1.5, 0.5, 1.0, 0.2));
    EXPECT_THROW(normalized_log_aesthetic_space_parameters(1.5, 1.2, 0.0), InvalidInput);
    EXPECT_THROW(normalized_log_aesthetic_space_parameters(std::nan(""), 1.2, 1.0), InvalidInput);
    LogAestheticSpaceParameters p;
    p.curvature = {1.5, -1.0, 1.0};  // c s + d = 0 at s = L = 1: singular end
    EXPECT_THROW(LogAestheticSpaceCurve{p}, InvalidInput);
    p.curvature = {1.5, -2.0, 1.0};  // negative on (0.5, 1]
    EXPECT_THROW(LogAestheticSpaceCurve{p}, InvalidInput);
}

TEST(SpaceTypicalPolygon, DihedralAnglesShowWhichTorsionRotationIsLost) {
    const LogAestheticSpaceParameters p = normalized_log_aesthetic_space_parameters(1.5, 1.2, 1.0, 0.1);
    const int n = 30;
    for (FrenetComposition comp :
         {FrenetComposition::kappa_then_tau, FrenetComposition::tau_then_kappa, FrenetComposition::alexa}) {
        const SpaceTypicalPolygon poly = space_typical_polygon(p, n, comp);
        ASSERT_EQ(poly.points.rows(), n + 1);
        for (int j = 0; j < n; ++j) EXPECT_NEAR((poly.points.row(j + 1) - poly.points.row(j)).norm(), 1.0 / n, 1e-15);
        const PolygonFrenetAngles a = polygon_frenet_angles(poly.points);
        ASSERT_EQ(a.dihedral.size(), static_cast<std::size_t>(n - 2));
        const auto& rt = poly.torsion_rotations;
        for (std::size_t j = 0; j < a.dihedral.size(); ++j) {
            if (comp == FrenetComposition::kappa_then_tau) {
                EXPECT_NEAR(a.dihedral[j], rt[j], 1e-13);
                EXPECT_NEAR(a.turning[j], poly.curvature_rotations[j], 1e-13);
            } else if (comp == FrenetComposition::tau_then_kappa) {
                EXPECT_NEAR(a.dihedral[j], rt[j + 1], 1e-13);
            } else {  // symmetric splitting: third order in the angles
                const double h = std::max(rt[j], poly.curvature_rotations[j]);
                EXPECT_NEAR(a.dihedral[j], 0.5 * (rt[j] + rt[j + 1]), h * h * h) << "j = " << j;
            }
        }
    }
}

TEST(SpaceTypicalPolygon, RejectsBadInput) {
    const LogAestheticSpaceParameters p = normalized_log_aesthetic_space_parameters(1.5, 1.2, 1.0);
    EXPECT_THROW(space_typical_polygon(p, 2), InvalidInput);
    EXPECT_THROW(space_typical_polygon_from_rotations({0.1, 0.1}, {0.1}, 0.1), InvalidInput);
    EXPECT_THROW(space_typical_polygon_from_rotations({0.1, 0.1}, {0.1, 0.1}, 0.0), InvalidInput);
    EXPECT_THROW(space_typical_polygon_from_rotations({0.1, 4.0}, {0.1, 0.1}, 0.1), InvalidInput);
    EXPECT_THROW(space_typical_polygon_from_rotations({0.1, 0.1}, {0.1, 0.1}, 0.1, FrenetComposition::alexa,
                                                      2.0 * Eigen::Matrix3d::Identity()),
                 InvalidInput);
    Eigen::MatrixXd straight(4, 3);
    straight << 0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 1, 0;
    EXPECT_THROW(polygon_frenet_angles(straight), InvalidInput);
    Eigen::MatrixXd repeated(4, 3);
    repeated << 0, 0, 0, 1, 0, 0, 1, 0, 0, 3, 1, 0;
    EXPECT_THROW(polygon_frenet_angles(repeated), InvalidInput);
}

TEST(TypicalSurface, RotationAboutTheDiagonalKeepsEdgesAndZeroAngleGivesATranslationSurface) {
    const Eigen::Vector3d p00(0, 0, 0), p10(1, 0, 0.2), p01(0.1, 1, -0.1);
    const Eigen::Vector3d r = rotated_fourth_point(p00, p10, p01, 0.7);
    EXPECT_NEAR((r - p10).norm(), (p01 - p00).norm(), 1e-15);
    EXPECT_NEAR((r - p01).norm(), (p10 - p00).norm(), 1e-15);
    EXPECT_GT((r - (p10 + p01 - p00)).norm(), 0.1);
    EXPECT_LT((rotated_fourth_point(p00, p10, p01, 0.0) - (p10 + p01 - p00)).norm(), 1e-15);

    const surface::ControlNet flat = log_aesthetic_typical_net(-0.5, -0.6, 1.0, 10, 0.0);
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j)
            for (std::size_t c = 0; c < 3; ++c)
                EXPECT_NEAR(flat[c](i, j), flat[c](i, 0) + flat[c](0, j) - flat[c](0, 0), 1e-14);
    const surface::ControlNet turned = log_aesthetic_typical_net(-0.5, -0.6, 1.0, 10, 0.2);
    auto pt = [&](int i, int j) { return Eigen::Vector3d(turned[0](i, j), turned[1](i, j), turned[2](i, j)); };
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) {
            EXPECT_NEAR((pt(i + 1, j + 1) - pt(i, j + 1)).norm(), 0.1, 1e-14);
            EXPECT_NEAR((pt(i + 1, j + 1) - pt(i + 1, j)).norm(), 0.1, 1e-14);
        }
}

TEST(TypicalSurface, RejectsBadBoundaries) {
    Eigen::MatrixXd u(3, 3), v(3, 3);
    u << 0, 0, 0, 1, 0, 0, 2, 0, 0.1;
    v << 0, 0, 0, 0, 1, 0, 0, 2, 0.1;
    EXPECT_NO_THROW(typical_surface_net(u, v, 0.1));
    EXPECT_THROW(typical_surface_net(u, v, std::nan("")), InvalidInput);
    Eigen::MatrixXd shifted = v;
    shifted.row(0) << 0.5, 0, 0;
    EXPECT_THROW(typical_surface_net(u, shifted, 0.1), InvalidInput);
    Eigen::MatrixXd repeated = u;
    repeated.row(1) = repeated.row(0);
    repeated.row(0).setZero();
    EXPECT_THROW(typical_surface_net(repeated, v, 0.1), InvalidInput);
    EXPECT_THROW(typical_surface_net(u.leftCols(2), v, 0.1), InvalidInput);
    EXPECT_THROW(rotated_fourth_point(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX(), 0.1),
                 InvalidInput);
}
