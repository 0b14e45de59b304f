#include "cagd/intrinsic/design_verification.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <numbers>

namespace cagd::intrinsic {

DesignVerification verify_design(const CurvatureProfileProblem& P, const IntrinsicCurve& curve) {
    require_valid_problem(P, "intrinsic::verify_design");
    const TangentAngleSpline& psi = curve.tangent_angle();
    const KnotLayout& L = P.layout;
    if (!(psi.layout() == L))
        fail_input("intrinsic::verify_design", "the curve's knot layout differs from the problem's");
    const auto& w = psi.breakpoints();
    using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
    DesignVerification v;
    Eigen::Vector2d r = P.points.row(0).transpose();
    for (int i = 0; i < L.spans(); ++i) {
        for (int j = L.first_segment(i); j < L.end_segment(i); ++j) {
            const double a = w[static_cast<std::size_t>(j)], b = w[static_cast<std::size_t>(j) + 1];
            auto angle = [&](double s) { return psi.jet_in_segment(j, std::clamp(s, a, b), 0)(0); };
            // Shifted by 2 so that the relative error test of the adaptive rule is meaningful where the
            // integral vanishes (sin ψ on a horizontal line).
            r(0) += GK::integrate([&](double s) { return std::cos(angle(s)) + 2.0; }, a, b, 15, 1e-14) - 2.0 * (b - a);
            r(1) += GK::integrate([&](double s) { return std::sin(angle(s)) + 2.0; }, a, b, 15, 1e-14) - 2.0 * (b - a);
        }
        const Eigen::Index target = (i + 1) % P.points.rows();
        v.interpolation_error = std::max(v.interpolation_error, (r - P.points.row(target).transpose()).norm());
    }
    for (int j = 0; j < L.segments(); ++j) {
        const SegmentShape shape = P.shapes[static_cast<std::size_t>(j)];
        if (shape != SegmentShape::line && shape != SegmentShape::arc) continue;
        const double a = w[static_cast<std::size_t>(j)], d = w[static_cast<std::size_t>(j) + 1] - a;
        const double mid = psi.jet_in_segment(j, a + 0.5 * d, 1)(1);
        for (int m = 0; m < 20; ++m) {
            const double kappa = psi.jet_in_segment(j, a + (m + 0.5) / 20.0 * d, 1)(1);
            if (shape == SegmentShape::line)
                v.line_curvature = std::max(v.line_curvature, std::abs(kappa));
            else
                v.arc_curvature_spread = std::max(v.arc_curvature_spread, std::abs(kappa - mid));
        }
    }
    for (int g = 1; g < L.segments(); ++g) {
        const double s = w[static_cast<std::size_t>(g)];
        const Eigen::VectorXd left = psi.jet_in_segment(g - 1, s, 1), right = psi.jet_in_segment(g, s, 1);
        v.angle_jump = std::max(v.angle_jump, std::abs(right(0) - left(0)));
        double& jump = L.geometric_continuity(g) >= 2 ? v.g2_curvature_jump : v.g1_curvature_jump;
        jump = std::max(jump, std::abs(right(1) - left(1)));
    }
    if (P.closed) {
        const int k = L.segments();
        const Eigen::VectorXd start = psi.jet_in_segment(0, 0.0, 1), end = psi.jet_in_segment(k - 1, psi.length(), 1);
        v.closing_angle = end(0) - start(0) - 2.0 * std::numbers::pi * closing_turns(P);
        v.closing_curvature = end(1) - start(1);
    }
    return v;
}

}  // namespace cagd::intrinsic
