// analysis/curvature_monotonicity: the numerator of dκ/dt as a Bernstein polynomial.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <random>

#include "cagd/aesthetic/class_a.hpp"
#include "cagd/aesthetic/cubic_bspline_monotonicity.hpp"
#include "cagd/aesthetic/log_aesthetic_curve.hpp"
#include "cagd/aesthetic/typical_bezier.hpp"
#include "cagd/analysis/curvature_monotonicity.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/core/bernstein_polynomial.hpp"
#include "cagd/core/errors.hpp"

using namespace cagd;
using namespace cagd::aesthetic;

TEST(CurvatureMonotonicity, NumeratorHasTheSignOfTheCurvatureDerivative) {
    Eigen::MatrixXd cp(6, 2);
    cp << 0, 0, 1, 0.2, 2, 0.8, 2.6, 1.9, 2.8, 3.1, 2.5, 4.0;
    const BezierCurve c(cp);
    const BernsteinPolynomial h = analysis::curvature_derivative_numerator(c);
    const BernsteinPolynomial q = analysis::squared_curvature_derivative_numerator(c);
    for (double t = 0.05; t < 0.96; t += 0.05) {
        const double e = 1e-6;
        const double dk = (analysis::signed_curvature(c, t + e) - analysis::signed_curvature(c, t - e)) / (2 * e);
        const double g = c.jet(t, 1).row(1).squaredNorm();
        EXPECT_NEAR(h(t) / std::pow(g, 2.5), dk, 1e-5 * (1 + std::abs(dk)));
        const double k = analysis::signed_curvature(c, t);
        EXPECT_NEAR(q(t) / std::pow(g, 4), 2 * k * dk, 1e-5 * (1 + std::abs(k * dk)));
    }
    Eigen::MatrixXd sp(5, 3);
    sp << 0, 0, 0, 1, 0, 0.1, 2, 1, 0.3, 2.2, 2, 1, 1.5, 3, 1.4;
    const BezierCurve s(sp);
    const BernsteinPolynomial tn = analysis::torsion_derivative_numerator(s);
    auto torsion = [&](double t) {
        const Eigen::MatrixXd j = s.jet(t, 3);
        const Eigen::Vector3d a = j.row(1), b = j.row(2), d = j.row(3);
        return a.cross(b).dot(d) / a.cross(b).squaredNorm();
    };
    for (double t = 0.1; t < 0.95; t += 0.1) {
        const double e = 1e-6;
        const Eigen::MatrixXd j = s.jet(t, 2);
        const double qq = Eigen::Vector3d(j.row(1)).cross(Eigen::Vector3d(j.row(2))).squaredNorm();
        const double dt = (torsion(t + e) - torsion(t - e)) / (2 * e);
        EXPECT_NEAR(tn(t) / (qq * qq), dt, 1e-5 * (1 + std::abs(dt)));
    }
}
