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

TEST(AlexaProduct, IsTheSimultaneousRotationAndCommutes) {
    const Eigen::Matrix3d a = curvature_rotation(0.4), b = torsion_rotation(-0.7);
    const Eigen::MatrixXd ab = numeric::alexa_product(a, b);
    EXPECT_LT((ab - Eigen::MatrixXd(numeric::rotation_from_vector({-0.7, 0.0, 0.4}))).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_LT((ab - numeric::alexa_product(b, a)).cwiseAbs().maxCoeff(), 1e-15);
    // Not the ordinary product: rotations about different axes do not commute.
    EXPECT_GT((ab - Eigen::MatrixXd(a * b)).cwiseAbs().maxCoeff(), 1e-2);
    // Commuting factors (same axis): the ordinary product.
    const Eigen::Matrix3d c = curvature_rotation(0.25);
    EXPECT_LT((numeric::alexa_product(a, c) - Eigen::MatrixXd(a * c)).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_LT((numeric::alexa_product(a, Eigen::Matrix3d::Identity()) - Eigen::MatrixXd(a)).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(AlexaProduct, LimitDefinitionConvergesLikeOneOverN) {
    const Eigen::Matrix3d a = curvature_rotation(0.4), b = torsion_rotation(0.7);
    const Eigen::MatrixXd exact = numeric::alexa_product(a, b);
    const double coef = numeric::alexa_limit_error_coefficient(a, b);
    // ‖[θ_z e_z×, θ_x e_x×]‖_F / 2 = θ_z θ_x / √2 is the small-angle value; exp's derivative shrinks it here.
    EXPECT_LT(coef, 0.4 * 0.7 / std::sqrt(2.0));
    EXPECT_GT(coef, 0.9 * 0.4 * 0.7 / std::sqrt(2.0));
    for (int k : {8, 12}) {
        const double n = std::ldexp(1.0, k);
        EXPECT_NEAR((numeric::alexa_product_limit(a, b, k) - exact).norm() * n, coef, 4.0 / n * coef) << "k = " << k;
    }
}

TEST(AlexaProduct, RejectsMatricesWithoutARealLogarithm) {
    const Eigen::Matrix3d half_turn = curvature_rotation(std::numbers::pi);
    EXPECT_THROW(numeric::alexa_product(half_turn, Eigen::Matrix3d::Identity()), InvalidInput);
    EXPECT_THROW(numeric::alexa_product(Eigen::Matrix2d::Identity(), Eigen::Matrix3d::Identity()), InvalidInput);
    Eigen::Matrix3d bad = Eigen::Matrix3d::Identity();
    bad(0, 1) = std::nan("");
    EXPECT_THROW(numeric::alexa_product(bad, Eigen::Matrix3d::Identity()), InvalidInput);
    EXPECT_THROW(numeric::alexa_product_limit(Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity(), 61), InvalidInput);
}

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
        const Eigen::Vector3d expect = d.dot(ex) * d * s + std::sin(w * s) / w * perp + (1.0 - std::cos(w * s)) / w * d.cross(perp);
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
    for (FrenetComposition comp : {FrenetComposition::kappa_then_tau, FrenetComposition::tau_then_kappa, FrenetComposition::alexa}) {
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
    EXPECT_THROW(space_typical_polygon_from_rotations({0.1, 0.1}, {0.1, 0.1}, 0.1, FrenetComposition::alexa, 2.0 * Eigen::Matrix3d::Identity()), InvalidInput);
    Eigen::MatrixXd straight(4, 3);
    straight << 0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 1, 0;
    EXPECT_THROW(polygon_frenet_angles(straight), InvalidInput);
    Eigen::MatrixXd repeated(4, 3);
    repeated << 0, 0, 0, 1, 0, 0, 1, 0, 0, 3, 1, 0;
    EXPECT_THROW(polygon_frenet_angles(repeated), InvalidInput);
}

TEST(Torsion, RateMatchesDifferencesOfTorsion) {
    Eigen::MatrixXd cp(6, 3);
    cp << 0, 0, 0, 1, 0.2, 0, 2, 1, 0.3, 2.5, 2, 1, 2, 3, 2.2, 1, 3.5, 3;
    const BezierCurve c(cp);
    const double h = 1e-5;
    for (double t : {0.1, 0.4, 0.77}) {
        const double speed = c.jet(t, 1).row(1).norm();
        const double fd = (analysis::torsion(c, t + h) - analysis::torsion(c, t - h)) / (2 * h) / speed;
        EXPECT_NEAR(analysis::torsion_arc_derivative(c, t), fd, 1e-6 * std::max(1.0, std::abs(fd))) << "t = " << t;
    }
    Eigen::MatrixXd planar(4, 2);
    planar << 0, 0, 1, 1, 2, 0, 3, 1;
    EXPECT_THROW(analysis::torsion(BezierCurve(planar), 0.5), InvalidInput);
    // A planar curve embedded in 3-D has no torsion: every LTG sample is skipped.
    Eigen::MatrixXd flat(4, 3);
    flat << 0, 0, 0, 1, 1, 0, 2, 0, 0, 3, 1, 0;
    EXPECT_EQ(analysis::log_torsion_graph(BezierCurve(flat), 0.0, 1.0, 10).skipped, 10);
    EXPECT_THROW(analysis::ltg_slope(BezierCurve(flat), 0.0, 1.0, 10), InvalidInput);
}

namespace {
// z = x² + y² over [0, 1]² as a bi-quadratic Bézier patch (Bernstein coefficients of t²: 0, 0, 1).
surface::ControlNet paraboloid_net() {
    surface::ControlNet net;
    for (auto& c : net) c.resize(3, 3);
    const double sq[3] = {0.0, 0.0, 1.0};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            net[0](i, j) = i / 2.0;
            net[1](i, j) = j / 2.0;
            net[2](i, j) = sq[i] + sq[j];
        }
    return net;
}
}  // namespace

TEST(BezierPatch, ParaboloidCurvatureMatchesTheMongeFormulas) {
    const surface::BezierPatch patch(paraboloid_net());
    for (double x : {0.0, 0.3, 1.0})
        for (double y : {0.2, 0.9}) {
            const analysis::SurfaceJet2 j = patch.jet(x, y);
            EXPECT_NEAR(j.s(2), x * x + y * y, 1e-15);
            const double w = 1.0 + 4 * x * x + 4 * y * y;
            const analysis::SurfaceCurvatures c = analysis::surface_curvatures(j);
            EXPECT_NEAR(c.gaussian, 4.0 / (w * w), 1e-13);
            EXPECT_NEAR(c.mean, (2.0 * (1 + 4 * y * y) + 2.0 * (1 + 4 * x * x)) / (2.0 * std::pow(w, 1.5)), 1e-13);
        }
}

TEST(BezierPatch, GridAndDeCasteljauAgreeAtDegree24) {
    const surface::ControlNet net = log_aesthetic_typical_net(-0.5, -0.6, 1.0, 24, 0.3);
    const surface::BezierPatch patch(net);
    const std::vector<double> us{0.0, 0.31, 1.0}, vs{0.05, 0.5, 0.93};
    const surface::SurfaceGrid g = patch.evaluate_grid(us, vs);
    for (Eigen::Index a = 0; a < 3; ++a)
        for (Eigen::Index b = 0; b < 3; ++b) {
            const analysis::SurfaceJet2 x = g.jet(a, b), y = patch.jet_de_casteljau(us[static_cast<std::size_t>(a)], vs[static_cast<std::size_t>(b)]);
            EXPECT_LT((x.s - y.s).norm(), 1e-13);
            EXPECT_LT((x.suv - y.suv).norm(), 1e-10);
            EXPECT_LT((x.svv - y.svv).norm(), 1e-10);
            EXPECT_LT((x.suu - y.suu).norm(), 1e-10);
        }
    EXPECT_THROW(patch.jet(1.2, 0.5), InvalidInput);
    surface::ControlNet bad = net;
    bad[1].resize(3, 3);
    EXPECT_THROW(surface::BezierPatch{bad}, InvalidInput);
}

TEST(SurfaceCurvature, RejectsSingularPoints) {
    analysis::SurfaceJet2 j;
    j.s = j.suu = j.suv = j.svv = Eigen::Vector3d::Zero();
    j.su = Eigen::Vector3d::UnitX();
    j.sv = 2.0 * Eigen::Vector3d::UnitX();
    EXPECT_THROW(analysis::surface_curvatures(j), InvalidInput);
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
            for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(flat[c](i, j), flat[c](i, 0) + flat[c](0, j) - flat[c](0, 0), 1e-14);
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
    EXPECT_THROW(rotated_fourth_point(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX(), 0.1), InvalidInput);
}
