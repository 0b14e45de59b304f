// Curvature, arc length, enclosed area through the Curve interface, with known values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/sampled_curve_measures.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/spline/bezier.hpp"
#include "cagd/spline/bspline.hpp"

using namespace cagd;

TEST(Analysis, ParabolaCurvatureAndLength) {
    // y = x² on [0, 1] as a quadratic Bézier: κ(0) = 2, κ(1) = 2/5^{3/2}; L = (2√5 + asinh 2)/4.
    Eigen::MatrixXd b(3, 2);
    b << 0, 0, 0.5, 0, 1, 1;
    const BezierCurve c(b);
    EXPECT_NEAR(analysis::signed_curvature(c, 0.0), 2.0, 1e-14);
    EXPECT_NEAR(analysis::curvature(c, 1.0), 2.0 / std::pow(5.0, 1.5), 1e-14);
    const double L = (2 * std::sqrt(5.0) + std::asinh(2.0)) / 4.0;
    EXPECT_NEAR(analysis::arc_length(c), L, 1e-14);
    const auto r = analysis::romberg_arc_length(c, 1e-13);
    ASSERT_TRUE(r.outcome.ok());
    EXPECT_NEAR(r.value, L, 1e-13);
}

TEST(Analysis, OnePassLengthAndEnergyEqualTheSeparatePasses) {
    // piece_length_and_bending_energy evaluates the derivatives once per node; its two sums must be
    // piece_arc_length and piece_bending_energy bit for bit (the comparison table depends on it).
    Eigen::MatrixXd control(5, 2);
    control << 0, 0, 1, 2, 3, -1, 4, 1, 6, 0;
    const BSplineCurve curve(3, {0, 0, 0, 0, 0.4, 1, 1, 1, 1}, control);
    for (const auto& [a, b] : {std::pair{0.0, 0.4}, std::pair{0.4, 1.0}, std::pair{0.1, 0.3}})
        for (int pieces : {1, 2, 5}) {
            const auto [length, energy] = analysis::piece_length_and_bending_energy(curve, a, b, pieces);
            EXPECT_EQ(length, analysis::piece_arc_length(curve, a, b, pieces)) << a << " " << pieces;
            EXPECT_EQ(energy, analysis::piece_bending_energy(curve, a, b, pieces)) << a << " " << pieces;
            EXPECT_GT(energy, 0.0);
        }
}

TEST(Analysis, AreaOfClosedPolylineSquareIsOne) {
    Eigen::MatrixXd p(5, 2);
    p << 0, 0, 1, 0, 1, 1, 0, 1, 0, 0;
    const BSplineCurve sq(1, {0, 0, 1, 2, 3, 4, 4}, p);
    EXPECT_NEAR(analysis::enclosed_area(sq), 1.0, 1e-15);
    EXPECT_NEAR(analysis::arc_length(sq), 4.0, 1e-14);
}

TEST(Analysis, SingularPointIsAnError) {
    Eigen::MatrixXd b(3, 2);
    b << 0, 0, 0, 0, 1, 1;  // r'(0) = 0
    EXPECT_THROW(analysis::curvature(BezierCurve(b), 0.0), InvalidInput);
    Eigen::MatrixXd s(2, 3);
    s << 0, 0, 0, 1, 1, 1;
    EXPECT_THROW(analysis::signed_curvature(BezierCurve(s), 0.5), InvalidInput);
}

TEST(Analysis, NormalOffsetIsSignedDistanceAlongLeftNormal) {
    Eigen::MatrixXd a(2, 2), b(2, 2);
    b << 0, 0, 1, 0;  // along +x: left normal is +y
    a << 0, 0.5, 1, 0.5;
    EXPECT_NEAR(analysis::normal_offset(BezierCurve(a), BezierCurve(b), 0.3), 0.5, 1e-15);
    EXPECT_NEAR(analysis::normal_offset(BezierCurve(b), BezierCurve(a), 0.3), -0.5, 1e-15);
}

// `cagd analyze CURVE.csv` (analysis/sampled_curve_measures): a unit circle sampled at N + 1
// points with exact derivatives. Polyline length 2N sin(π/N), area (N/2) sin(2π/N) (the inscribed
// N-gon, exact to rounding), κ = 1 at every sample, trapezoid energy = polyline length.
TEST(SampledCurveMeasures, CircleGivesTheInscribedPolygonAndUnitCurvature) {
    const int N = 64;
    analysis::CurveSamples s;
    s.position.resize(N + 1, 2);
    s.first = Eigen::MatrixXd(N + 1, 2);
    s.second = Eigen::MatrixXd(N + 1, 2);
    for (int i = 0; i <= N; ++i) {
        const double t = 2 * std::numbers::pi * i / N;
        s.position.row(i) << std::cos(t), std::sin(t);
        s.first->row(i) << -std::sin(t), std::cos(t);
        s.second->row(i) << -std::cos(t), -std::sin(t);
        s.parameter.push_back(t);
    }
    const analysis::SampledCurveMeasures m = analysis::sampled_curve_measures(s);
    EXPECT_EQ(m.samples, N + 1);
    EXPECT_TRUE(m.closed);
    EXPECT_NEAR(m.polyline_length, 2 * N * std::sin(std::numbers::pi / N), 1e-13);
    ASSERT_TRUE(m.enclosed_area.has_value());
    EXPECT_NEAR(*m.enclosed_area, 0.5 * N * std::sin(2 * std::numbers::pi / N), 1e-13);
    ASSERT_TRUE(m.has_curvature);
    EXPECT_NEAR(m.curvature_min, 1.0, 1e-14);
    EXPECT_NEAR(m.curvature_max, 1.0, 1e-14);
    EXPECT_NEAR(m.bending_energy, m.polyline_length, 1e-13);
    // Reversed orientation: negative area and signed curvature −1.
    analysis::CurveSamples r = s;
    r.position.col(1) *= -1;
    r.first->col(1) *= -1;
    r.second->col(1) *= -1;
    const analysis::SampledCurveMeasures mr = analysis::sampled_curve_measures(r);
    EXPECT_NEAR(*mr.enclosed_area, -*m.enclosed_area, 1e-13);
    EXPECT_NEAR(mr.curvature_max, -1.0, 1e-14);
}

// A helix (cos t, sin t, c t) has κ = 1/(1 + c²); its length counts z (no silent xy projection).
TEST(SampledCurveMeasures, HelixIsMeasuredInSpace) {
    const int N = 200;
    const double c = 0.5;
    analysis::CurveSamples s;
    s.position.resize(N + 1, 3);
    s.first = Eigen::MatrixXd(N + 1, 3);
    s.second = Eigen::MatrixXd(N + 1, 3);
    for (int i = 0; i <= N; ++i) {
        const double t = 4.0 * i / N;
        s.position.row(i) << std::cos(t), std::sin(t), c * t;
        s.first->row(i) << -std::sin(t), std::cos(t), c;
        s.second->row(i) << -std::cos(t), -std::sin(t), 0;
    }
    const analysis::SampledCurveMeasures m = analysis::sampled_curve_measures(s);
    EXPECT_FALSE(m.closed);
    EXPECT_FALSE(m.enclosed_area.has_value());
    // chord of the helix over Δt = 4/N: sqrt(4 sin²(Δt/2) + c²Δt²), N of them
    const double dt = 4.0 / N;
    EXPECT_NEAR(m.polyline_length, N * std::sqrt(4 * std::pow(std::sin(dt / 2), 2) + c * c * dt * dt), 1e-12);
    EXPECT_NEAR(m.curvature_min, 1 / (1 + c * c), 1e-14);
    EXPECT_NEAR(m.curvature_max, 1 / (1 + c * c), 1e-14);
}

TEST(SampledCurveMeasures, BadSamplesAreNamed) {
    analysis::CurveSamples s;
    s.position = Eigen::MatrixXd::Zero(1, 2);
    EXPECT_THROW(analysis::sampled_curve_measures(s), InvalidInput);
    s.position = (Eigen::MatrixXd(3, 2) << 0, 0, 1, 0, 2, 0).finished();
    s.first = Eigen::MatrixXd::Zero(3, 2);
    s.second = Eigen::MatrixXd::Zero(3, 2);
    try {
        analysis::sampled_curve_measures(s);
        ADD_FAILURE() << "zero speed accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("zero speed at sample 0"), std::string::npos) << e.what();
    }
    s.first = std::nullopt;
    s.second = std::nullopt;
    s.position(1, 1) = std::numeric_limits<double>::quiet_NaN();
    try {
        analysis::sampled_curve_measures(s);
        ADD_FAILURE() << "NaN accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
    }
}
