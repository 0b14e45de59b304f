// The eigen-spline peer (methods/register_eigen.cpp): Eigen's global interpolation of Piegl and
// Tiller, section 9.2.1 — chord-length parameters in [0, 1], knots averaged from them, the data
// points on the curve — and its stated size limit.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/messages.hpp"
#include "cagd/methods/method_registry.hpp"
#include "cagd/spline/bspline.hpp"

using namespace cagd;
using namespace cagd::methods;

namespace {
PointList spiral_points(int n) {
    PointList p(n, 3);
    for (int i = 0; i < n; ++i)
        p.row(i) << (1.0 + 0.05 * i) * std::cos(0.9 * i), (1.0 + 0.05 * i) * std::sin(0.9 * i), 0.1 * i * (i % 3);
    return p;
}
}  // namespace

TEST(EigenPeer, KnotsAreAveragedChordLengthsAndThePointsLieOnTheCurve) {
    for (int degree : {3, 5}) {
        const PointList p = spiral_points(12);
        const InterpolationResult r = interpolate("eigen-spline", p, false, {{"degree", std::to_string(degree)}});
        ASSERT_TRUE(r.outcome.ok()) << r.outcome.message;
        const auto* b = dynamic_cast<const BSplineCurve*>(r.interpolant->curve.get());
        ASSERT_NE(b, nullptr);
        ASSERT_EQ(b->degree(), degree);
        // Chord-length parameters normalised to [0, 1].
        std::vector<double> u{0.0};
        for (int i = 1; i < p.rows(); ++i) u.push_back(u.back() + (p.row(i) - p.row(i - 1)).norm());
        for (double& x : u) x /= u.back();
        for (std::size_t i = 0; i < u.size(); ++i) EXPECT_NEAR(r.interpolant->node_parameters[i], u[i], 1e-15);
        // Knot j + p is the mean of u_j … u_{j+p−1} (j = 1 … n − p − 1); clamped at 0 and 1.
        const std::vector<double>& k = b->knots();
        ASSERT_EQ(k.size(), u.size() + static_cast<std::size_t>(degree) + 1);
        for (std::size_t j = 1; j + static_cast<std::size_t>(degree) < u.size(); ++j) {
            double mean = 0.0;
            for (int i = 0; i < degree; ++i) mean += u[j + static_cast<std::size_t>(i)] / degree;
            EXPECT_NEAR(k[j + static_cast<std::size_t>(degree)], mean, 1e-15);
        }
        for (Eigen::Index i = 0; i < p.rows(); ++i)
            EXPECT_LE((b->point(u[static_cast<std::size_t>(i)]) - p.row(i).transpose()).norm(), 1e-12);
    }
}

TEST(EigenPeer, MoreThanTwoThousandPointsAreRefusedNamingTheLimit) {
    PointList p(2001, 2);
    for (int i = 0; i < 2001; ++i) p.row(i) << i, std::sin(0.1 * i);
    const std::string message = cagd::test::invalid_input_message([&] { interpolate("eigen-spline", p, false); });
    EXPECT_NE(message.find("at most 2000"), std::string::npos) << message;
    EXPECT_THROW(interpolate("eigen-spline", spiral_points(8), true), InvalidInput);  // open curves only
}
