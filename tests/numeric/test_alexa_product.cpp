// numeric/alexa_product: Alexa's product A ⊗ B (typical_curves eq 37) and its limit form.
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
    EXPECT_LT((numeric::alexa_product(a, Eigen::Matrix3d::Identity()) - Eigen::MatrixXd(a)).cwiseAbs().maxCoeff(),
              1e-14);
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
    EXPECT_THROW(numeric::alexa_product_limit(Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity(), 61),
                 InvalidInput);
}
