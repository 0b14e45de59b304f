// analysis::frenet_jet, the one kernel of κ, dκ/ds, τ and dτ/ds, against curves whose geometry is
// known in closed form, and the flatness policy's signs.
#include <gtest/gtest.h>

#include <cmath>

#include "cagd/analysis/frenet_jet.hpp"
#include "cagd/core/errors.hpp"

namespace {

using cagd::analysis::frenet_jet;
using cagd::analysis::FrenetJet;

TEST(FrenetJet, ACircleTraversedAtAnySpeedHasCurvatureOneOverItsRadius) {
    // r(t) = R (cos ωt, sin ωt): κ = 1/R (left turn: +), dκ/ds = 0; clockwise: −1/R.
    const double R = 2.5, w = 3.0, t = 0.7;
    for (const double sense : {1.0, -1.0}) {
        Eigen::MatrixXd D(3, 2);
        D << -R * w * std::sin(w * t), sense * R * w * std::cos(w * t),          //
            -R * w * w * std::cos(w * t), -sense * R * w * w * std::sin(w * t),  //
            R * w * w * w * std::sin(w * t), -sense * R * w * w * w * std::cos(w * t);
        const FrenetJet f = frenet_jet(D);
        ASSERT_TRUE(f.regular);
        EXPECT_NEAR(f.speed, R * w, 1e-14);
        EXPECT_NEAR(f.curvature, sense / R, 1e-15) << "κ = ±1/R, sense " << sense;
        EXPECT_NEAR(f.curvature_rate, 0.0, 1e-14) << "dκ/ds = 0 on a circle";
        EXPECT_TRUE(std::isnan(f.torsion)) << "a planar curve has no torsion field";
    }
}

TEST(FrenetJet, AClothoidsCurvatureGrowsLinearlyInArcLength) {
    // Tangent angle θ(s) = a s²/2 (unit speed): r' = (cos θ, sin θ), r'' = θ' (−sin θ, cos θ),
    // r''' = θ'' (−sin θ, cos θ) − θ'² (cos θ, sin θ), so κ = θ' = a s, dκ/ds = a.
    const double a = 0.8, s = 1.3, th = 0.5 * a * s * s, k = a * s;
    Eigen::MatrixXd D(3, 2);
    D << std::cos(th), std::sin(th), -k * std::sin(th), k * std::cos(th), -a * std::sin(th) - k * k * std::cos(th),
        a * std::cos(th) - k * k * std::sin(th);
    const FrenetJet f = frenet_jet(D);
    EXPECT_NEAR(f.curvature, k, 1e-15) << "κ = a s";
    EXPECT_NEAR(f.curvature_rate, a, 1e-14) << "dκ/ds = a";
}

TEST(FrenetJet, AHelixHasConstantCurvatureAndTorsion) {
    // r(t) = (R cos t, R sin t, c t): κ = R/(R² + c²), τ = c/(R² + c²), both rates 0.
    const double R = 1.5, c = 0.4, t = 2.1;
    Eigen::MatrixXd D(4, 3);
    D << -R * std::sin(t), R * std::cos(t), c,    //
        -R * std::cos(t), -R * std::sin(t), 0.0,  //
        R * std::sin(t), -R * std::cos(t), 0.0,   //
        R * std::cos(t), R * std::sin(t), 0.0;
    const FrenetJet f = frenet_jet(D);
    const double h = R * R + c * c;
    EXPECT_NEAR(f.curvature, R / h, 1e-15) << "κ = R/(R² + c²)";
    EXPECT_NEAR(f.torsion, c / h, 1e-15) << "τ = c/(R² + c²)";
    EXPECT_NEAR(f.curvature_rate, 0.0, 1e-14);
    EXPECT_NEAR(f.torsion_rate, 0.0, 1e-14);
}

TEST(FrenetJet, TheTwistedCubicsTorsionAndItsRateMatchTheClosedForm) {
    // r(t) = (t, t², t³): |r' × r''|² = 36t⁴ + 36t² + 4, τ = 12/(36t⁴ + 36t² + 4), speed
    // sqrt(1 + 4t² + 9t⁴); dτ/ds = τ'(t)/speed with τ'(t) = −12 (144t³ + 72t)/(36t⁴ + 36t² + 4)².
    const double t = 0.6;
    Eigen::MatrixXd D(4, 3);
    D << 1.0, 2 * t, 3 * t * t, 0.0, 2.0, 6 * t, 0.0, 0.0, 6.0, 0.0, 0.0, 0.0;
    const FrenetJet f = frenet_jet(D);
    const double q = 36 * std::pow(t, 4) + 36 * t * t + 4, v = std::sqrt(1 + 4 * t * t + 9 * std::pow(t, 4));
    EXPECT_NEAR(f.torsion, 12.0 / q, 1e-14);
    EXPECT_NEAR(f.torsion_rate, -12.0 * (144 * std::pow(t, 3) + 72 * t) / (q * q) / v, 1e-13);
    // κ = sqrt(q)/v³, and dκ/ds against a central difference of κ(t) over ds.
    EXPECT_NEAR(f.curvature, std::sqrt(q) / (v * v * v), 1e-14);
    const auto kappa_at = [](double u) {
        return std::sqrt(36 * std::pow(u, 4) + 36 * u * u + 4) / std::pow(1 + 4 * u * u + 9 * std::pow(u, 4), 1.5);
    };
    const double h = 1e-5;
    EXPECT_NEAR(f.curvature_rate, (kappa_at(t + h) - kappa_at(t - h)) / (2 * h) / v, 1e-8);
}

TEST(FrenetJet, AStraightPointHasNoSignAndNoTorsion) {
    Eigen::MatrixXd D(3, 3);
    D << 1.0, 0.0, 0.0, 1e-13, 0.0, 0.0, 0.0, 1e-13, 0.0;  // r'' along r': κ = 0 exactly
    const FrenetJet f = frenet_jet(D);
    EXPECT_EQ(f.curvature, 0.0);
    EXPECT_EQ(f.curvature_rate, 0.0) << "a space curve that stays straight: dκ/ds = 0";
    EXPECT_TRUE(std::isnan(f.torsion));
    EXPECT_EQ(cagd::analysis::curvature_sign(1e-12, 100.0), 0) << "|κ|·D = 1e-10 ≤ 1e-9: straight";
    EXPECT_EQ(cagd::analysis::curvature_sign(-1e-10, 1e2), -1) << "|κ|·D = 1e-8 > 1e-9: turns right";
    EXPECT_EQ(cagd::analysis::curvature_sign(std::nan(""), 1.0), 0);
    EXPECT_EQ(cagd::analysis::curvature_rate_sign(1e-12, 10.0), 0) << "|κ'|·D² = 1e-10";
    EXPECT_EQ(cagd::analysis::curvature_rate_sign(1e-12, 1e3), 1) << "|κ'|·D² = 1e-6";
    FrenetJet bent;
    bent.regular = true, bent.curvature = 1e-12, bent.torsion = 5.0;
    EXPECT_TRUE(std::isnan(cagd::analysis::defined_torsion(bent, 1.0)));
    EXPECT_EQ(cagd::analysis::defined_torsion(bent, 1e4), 5.0);
}

// A circle of radius R in the parameter c·t, at scales where v³ under- or overflowed: κ = 1/R,
// dκ/ds = 0 and, for a helix of radius R and pitch R, τ = 1/(2R), wherever those are representable.
TEST(FrenetJet, AnyRepresentableScaleOfCurveAndParameter) {
    for (const double R : {1e-150, 1e-120, 1.0, 1e140, 1e150})
        for (const double c : {1e-100, 1.0, 1e100}) {
            const double t = 0.7, s = std::sin(t), k = std::cos(t);
            Eigen::MatrixXd plane(3, 2), space(3, 3);
            plane << -R * s * c, R * k * c, -R * k * c * c, -R * s * c * c, R * s * c * c * c, -R * k * c * c * c;
            space << -R * s * c, R * k * c, R * c, -R * k * c * c, -R * s * c * c, 0.0, R * s * c * c * c,
                -R * k * c * c * c, 0.0;
            if (!std::isnormal(R * c) || !std::isnormal(R * c * c) || !std::isnormal(R * c * c * c))
                continue;  // the jet itself
            const FrenetJet p = frenet_jet(plane), h = frenet_jet(space);
            EXPECT_NEAR(p.curvature * R, 1.0, 1e-14) << "R = " << R << ", c = " << c;
            EXPECT_NEAR(p.curvature_rate * R * R, 0.0, 1e-14) << "R = " << R << ", c = " << c;
            EXPECT_NEAR(h.curvature * R, 0.5, 1e-14) << "helix, R = " << R << ", c = " << c;
            EXPECT_NEAR(h.torsion * R, 0.5, 1e-14) << "helix, R = " << R << ", c = " << c;
        }
}

TEST(FrenetJet, ZeroSpeedIsNotRegularAndItsCurvatureIsNaN) {
    Eigen::MatrixXd D(2, 2);
    D << 0.0, 0.0, 1.0, 0.0;
    const FrenetJet f = frenet_jet(D);
    EXPECT_FALSE(f.regular);
    EXPECT_TRUE(std::isnan(f.curvature));
}

TEST(FrenetJet, RefusesTooFewRowsAndOtherDimensions) {
    try {
        (void)frenet_jet(Eigen::MatrixXd::Ones(1, 2));
        FAIL() << "one row accepted";
    } catch (const cagd::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("got 1"), std::string::npos) << e.what();
    }
    try {
        (void)frenet_jet(Eigen::MatrixXd::Ones(2, 4));
        FAIL() << "dimension 4 accepted";
    } catch (const cagd::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("got 4"), std::string::npos) << e.what();
    }
}

TEST(SignChanges, SkipZerosAndCloseTheLoopWhenAsked) {
    EXPECT_EQ(cagd::analysis::sign_changes({1, 0, 0, 1, -1, 0, -1, 1}, false), 2);
    EXPECT_EQ(cagd::analysis::sign_changes({1, -1, 0}, true), 2) << "closed: from −1 back to 1";
    EXPECT_EQ(cagd::analysis::sign_changes({0, 0}, true), 0);
}

}  // namespace
