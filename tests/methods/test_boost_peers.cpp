// The Boost peers read Boost's slopes block by block (methods/interpolant_forms.cpp): the curve must
// be the one a single Boost interpolator over all the points gives, bit for bit: the derivatives at
// both ends of every span.
#include <gtest/gtest.h>

#include <cmath>
// Boost 1.74's pchip.hpp and makima.hpp call isnan unqualified.
using std::isnan;
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/pchip.hpp>
#include <vector>

#include "cagd/core/random_walk.hpp"
#include "cagd/methods/method_registry.hpp"
#include "cagd/spline/hermite_spline.hpp"

using namespace cagd;

namespace {

template <class Interpolator>
void expect_boost_curve_bit_for_bit(const std::string& method, long n) {
    const PointList p = random_walk(n, 5, 0.1, 2.0, 1.0);
    const methods::InterpolationResult r = methods::interpolate(method, p, false);
    ASSERT_TRUE(r.outcome.ok()) << r.outcome.message;
    const auto* c = dynamic_cast<const spline::PiecewiseHermiteCurve*>(r.interpolant->curve.get());
    ASSERT_NE(c, nullptr);
    std::vector<double> tau{0.0};
    for (Eigen::Index k = 1; k < p.rows(); ++k) tau.push_back(tau.back() + (p.row(k) - p.row(k - 1)).norm());
    for (Eigen::Index col = 0; col < 2; ++col) {
        std::vector<double> x = tau, y(p.col(col).data(), p.col(col).data() + p.rows());
        const Interpolator f(std::move(x), std::move(y));
        for (Eigen::Index k = 0; k + 1 < p.rows(); ++k) {  // span k's end derivatives (d/du) = h_k · Boost's slopes at its ends
            const double h = (p.row(k + 1) - p.row(k)).norm();
            ASSERT_EQ(c->start_derivatives()(k, col), h * f.prime(tau[static_cast<std::size_t>(k)])) << method << " node " << k << " coordinate " << col;
            ASSERT_EQ(c->end_derivatives()(k, col), h * f.prime(tau[static_cast<std::size_t>(k) + 1])) << method << " node " << k + 1 << " coordinate " << col;
        }
    }
}

}  // namespace

TEST(BoostPeers, PchipSlopesAreBoostsOverAllPointsBitForBit) { expect_boost_curve_bit_for_bit<boost::math::interpolators::pchip<std::vector<double>>>("boost-pchip", 1500); }

TEST(BoostPeers, MakimaSlopesAreBoostsOverAllPointsBitForBit) { expect_boost_curve_bit_for_bit<boost::math::interpolators::makima<std::vector<double>>>("boost-makima", 1500); }
