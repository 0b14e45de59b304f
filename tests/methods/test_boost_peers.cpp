// The Boost peers read Boost's slopes through prime() (methods/boost_peers.hpp): the curve must be
// the one a single Boost interpolator over all the points gives, bit for bit: the derivatives at
// both ends of every span, on data that takes every branch of Boost's rules (zero secants, sign
// changes, flat coordinates, the ends).
#include <gtest/gtest.h>

#include <cmath>
// Boost 1.74's pchip.hpp and makima.hpp call isnan unqualified.
using std::isnan;
#include <array>
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/pchip.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/core/random_walk.hpp"
#include "cagd/methods/boost_peers.hpp"
#include "cagd/methods/method_registry.hpp"
#include "cagd/spline/hermite_spline.hpp"

using namespace cagd;

namespace {

template <class Interpolator>
void expect_boost_curve_bit_for_bit(const std::string& what, const PointList& p, const methods::Interpolant& curve) {
    const auto* c = dynamic_cast<const spline::PiecewiseHermiteCurve*>(curve.curve.get());
    ASSERT_NE(c, nullptr);
    std::vector<double> tau{0.0};
    for (Eigen::Index k = 1; k < p.rows(); ++k) tau.push_back(tau.back() + (p.row(k) - p.row(k - 1)).norm());
    for (Eigen::Index col = 0; col < p.cols(); ++col) {
        std::vector<double> x = tau, y(p.col(col).data(), p.col(col).data() + p.rows());
        const Interpolator f(std::move(x), std::move(y));
        for (Eigen::Index k = 0; k + 1 < p.rows();
             ++k) {  // span k's end derivatives (d/du) = h_k · Boost's slopes at its ends
            const double h = (p.row(k + 1) - p.row(k)).norm();
            ASSERT_EQ(c->start_derivatives()(k, col), h * f.prime(tau[static_cast<std::size_t>(k)]))
                << what << " node " << k << " coordinate " << col;
            ASSERT_EQ(c->end_derivatives()(k, col), h * f.prime(tau[static_cast<std::size_t>(k) + 1]))
                << what << " node " << k + 1 << " coordinate " << col;
        }
    }
}

// The curve one Boost catmull_rom over all the points gives (centripetal, α = 1/2), bit for bit:
// span k's derivatives d/du at its ends are h_k times Boost's prime at its nodes, h_k its length
// in Boost's parameter.
template <std::size_t D>
void expect_boost_catmull_rom_bit_for_bit(const std::string& what, const PointList& p, bool closed,
                                          const methods::Interpolant& curve) {
    const auto* c = dynamic_cast<const spline::PiecewiseHermiteCurve*>(curve.curve.get());
    ASSERT_NE(c, nullptr);
    std::vector<std::array<double, D>> pts(static_cast<std::size_t>(p.rows()));
    for (Eigen::Index k = 0; k < p.rows(); ++k)
        for (std::size_t j = 0; j < D; ++j) pts[static_cast<std::size_t>(k)][j] = p(k, static_cast<Eigen::Index>(j));
    const boost::math::catmull_rom<std::array<double, D>> cr(std::move(pts), closed, 0.5);
    const Eigen::Index n = p.rows(), spans = closed ? n : n - 1;
    ASSERT_EQ(c->start_derivatives().rows(), spans) << what;
    for (Eigen::Index k = 0; k < spans; ++k) {
        const double t0 = cr.parameter_at_point(static_cast<std::size_t>(k)),
                     t1 = cr.parameter_at_point(static_cast<std::size_t>(k + 1)), h = t1 - t0;
        const auto s0 = cr.prime(t0), s1 = cr.prime(cr.parameter_at_point(
                                          static_cast<std::size_t>((k + 1) % n)));  // closed: node 0's slope again
        for (std::size_t j = 0; j < D; ++j) {
            ASSERT_EQ(c->start_derivatives()(k, static_cast<Eigen::Index>(j)), h * s0[j])
                << what << " node " << k << " coordinate " << j;
            ASSERT_EQ(c->end_derivatives()(k, static_cast<Eigen::Index>(j)), h * s1[j])
                << what << " node " << (k + 1) % n << " coordinate " << j;
        }
    }
}

// Data sets named by what they exercise.
std::vector<std::pair<std::string, PointList>> data_sets() {
    std::vector<std::pair<std::string, PointList>> sets;
    sets.emplace_back("random walk of 1500", random_walk(1500, 5, 0.1, 2.0, 1.0));
    for (long n : {4L, 5L, 7L, 63L, 256L, 257L, 320L, 1100L})
        sets.emplace_back("random walk of " + std::to_string(n), random_walk(n, 9, 0.1, 2.0, 1.0));
    {  // staircase: runs of equal y (zero secants) and, with the zigzag in x, secants changing sign
        PointList p(600, 2);
        for (Eigen::Index k = 0; k < p.rows(); ++k)
            p.row(k) << (k % 2 == 0 ? 1.0 : -1.0) * 0.3 + static_cast<double>(k),
                std::floor(static_cast<double>(k) / 3.0);
        sets.emplace_back("staircase", p);
    }
    {  // 3-D, its z constant (makima's 0/0 weights) or a zigzag
        PointList p(700, 3);
        const PointList w = random_walk(700, 3, 0.1, 2.0, 1.0);
        p.leftCols(2) = w;
        for (Eigen::Index k = 0; k < p.rows(); ++k) p(k, 2) = k < 350 ? 2.5 : (k % 2 == 0 ? 1.0 : -1.0);
        sets.emplace_back("3-D, flat then zigzag z", p);
    }
    sets.emplace_back("random walk scaled by 1e-100", random_walk(900, 4, 0.1, 2.0, 1.0) * 1e-100);
    sets.emplace_back("random walk scaled by 1e100", random_walk(900, 4, 0.1, 2.0, 1.0) * 1e100);
    return sets;
}

}  // namespace

TEST(BoostPeers, PchipSlopesAreBoostsOverAllPointsBitForBit) {
    for (const auto& [what, p] : data_sets()) {
        const methods::InterpolationResult r = methods::interpolate("boost-pchip", p, false);
        ASSERT_TRUE(r.outcome.ok()) << what << ": " << r.outcome.message;
        expect_boost_curve_bit_for_bit<boost::math::interpolators::pchip<std::vector<double>>>("boost-pchip, " + what,
                                                                                               p, *r.interpolant);
    }
}

TEST(BoostPeers, MakimaSlopesAreBoostsOverAllPointsBitForBit) {
    for (const auto& [what, p] : data_sets()) {
        const methods::InterpolationResult r = methods::interpolate("boost-makima", p, false);
        ASSERT_TRUE(r.outcome.ok()) << what << ": " << r.outcome.message;
        expect_boost_curve_bit_for_bit<boost::math::interpolators::makima<std::vector<double>>>("boost-makima, " + what,
                                                                                                p, *r.interpolant);
    }
}

// Boost's catmull_rom refuses chords whose square root is below ε = 2.2e-16 (an absolute test), so
// it is given the points scaled by a power of 4 (exact): the set scaled by 1e-100, which Boost
// itself refuses, gives the curve of the unscaled set, scaled by 1e-100 (the method's t runs over
// the spans, one unit each, at any scale).
bool refused_by_boost_catmull_rom(const std::string& what) { return what.find("1e-100") != std::string::npos; }

TEST(BoostPeers, CatmullRomSlopesAreBoostsOverAllPointsBitForBit) {
    for (const auto& [what, p] : data_sets())
        for (bool closed : {false, true}) {
            if (refused_by_boost_catmull_rom(what)) {
                const methods::InterpolationResult small = methods::interpolate("boost-catmull-rom", p, closed);
                const methods::InterpolationResult unit =
                    methods::interpolate("boost-catmull-rom", PointList(p * 1e100), closed);
                ASSERT_TRUE(small.outcome.ok() && unit.outcome.ok()) << what << ": " << small.outcome.message;
                const Curve& a = *small.interpolant->curve;
                const Curve& b = *unit.interpolant->curve;
                ASSERT_EQ(a.t_max(), b.t_max()) << what;
                for (int k = 0; k <= 200; ++k) {
                    const double t = b.t_max() * k / 200;
                    EXPECT_LE((a.point(t) * 1e100 - b.point(t)).norm(), 1e-12 * (1.0 + b.point(t).norm()))
                        << what << ", t = " << t;
                }
                continue;
            }
            const methods::InterpolationResult r = methods::interpolate("boost-catmull-rom", p, closed);
            ASSERT_TRUE(r.outcome.ok()) << what << ": " << r.outcome.message;
            const std::string name = std::string("boost-catmull-rom, ") + (closed ? "closed, " : "open, ") + what;
            if (p.cols() == 2)
                expect_boost_catmull_rom_bit_for_bit<2>(name, p, closed, *r.interpolant);
            else
                expect_boost_catmull_rom_bit_for_bit<3>(name, p, closed, *r.interpolant);
        }
}

TEST(BoostPeers, FewerThanFourPointsAreRefusedByName) {
    const PointList p = random_walk(3, 5, 0.1, 2.0, 1.0);
    try {
        methods::boost_makima_interpolant(p);
        FAIL() << "3 points accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("at least 4 points"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("got 3"), std::string::npos) << e.what();
    }
}
