// core/points: point-list helpers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/pchip.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>

#include "../support/messages.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/finite.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/core/points.hpp"
#include "cagd/core/random_walk.hpp"
#include "cagd/methods/method_registry.hpp"

using std::isnan;
using namespace cagd;
using namespace cagd::compare;
using namespace cagd::methods;

TEST(Points, BoundingBoxDiagonal) {
    PointList p(3, 2);
    p << 1, 2, 4, -2, 2, 0;  // box [1, 4] × [−2, 2]: diagonal 5
    EXPECT_DOUBLE_EQ(bounding_box_diagonal(p), 5.0);
    EXPECT_DOUBLE_EQ(bounding_box_diagonal(p.topRows(1)), 0.0);
    EXPECT_DOUBLE_EQ(bounding_box_diagonal(PointList(0, 2)), 0.0);
}

namespace {

// Eigen's row norm, chord by chord: the reference chord_lengths must equal bit for bit.
std::vector<double> row_norm_chords(const PointList& p, bool closed) {
    std::vector<double> h;
    for (Eigen::Index k = 0; k + 1 < p.rows() || (closed && k < p.rows()); ++k)
        h.push_back((p.row(k + 1 == p.rows() ? 0 : k + 1) - p.row(k)).norm());
    return h;
}

}  // namespace

TEST(Points, ChordLengthsAreEigensRowNormsBitForBit) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (Eigen::Index dim = 1; dim <= 3; ++dim)
        for (Eigen::Index n : {2, 3, 7, 101}) {
            PointList p(n, dim);
            for (Eigen::Index i = 0; i < p.size(); ++i)
                p.data()[i] = std::ldexp(u(rng), static_cast<int>(i % 40) - 20);  // magnitudes 2^-20 … 2^19
            for (bool closed : {false, true}) {
                const std::vector<double> h = chord_lengths(p, closed), want = row_norm_chords(p, closed);
                ASSERT_EQ(h.size(), want.size()) << "dim " << dim << " n " << n << " closed " << closed;
                for (std::size_t k = 0; k < h.size(); ++k)
                    ASSERT_EQ(h[k], want[k]) << "chord " << k << " dim " << dim << " n " << n << " closed " << closed;
            }
        }
    EXPECT_TRUE(chord_lengths(PointList(1, 2), false).empty());
}

TEST(Points, FirstChordShorterThanFindsTheFirstShortChord) {
    PointList p(5, 2);
    p << 0, 0, 3, 4, 3, 4.5, 3, 5, 0, 0.25;  // chords 5, 0.5, 0.5, √(9 + 22.5625); closing 0.25
    EXPECT_EQ(first_chord_shorter_than(p, false, 0.4), -1);
    EXPECT_EQ(first_chord_shorter_than(p, false, 0.6), 1) << "chord 1 (0.5) is the first below 0.6";
    EXPECT_EQ(first_chord_shorter_than(p, false, 5.0), 1) << "5 is not shorter than 5";
    EXPECT_EQ(first_chord_shorter_than(p, false, 5.5), 0);
    EXPECT_EQ(first_chord_shorter_than(p, true, 0.4), 4) << "the closing chord P4P0 (0.25)";
}

TEST(Points, AllFiniteFindsEveryNonFiniteValueAtEveryPosition) {
    const double bad[] = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::quiet_NaN()};
    for (std::size_t n : {1u, 2u, 3u, 5u, 8u, 17u}) {
        // finite extremes: the largest, the smallest subnormal, −0
        std::vector<double> v(n, std::numeric_limits<double>::max());
        for (std::size_t i = 0; i < n; i += 2) v[i] = i % 4 == 0 ? -std::numeric_limits<double>::denorm_min() : -0.0;
        ASSERT_TRUE(all_finite(v.data(), n)) << n;
        for (std::size_t at = 0; at < n; ++at)
            for (double b : bad) {
                std::vector<double> w = v;
                w[at] = b;
                EXPECT_FALSE(all_finite(w.data(), n)) << b << " at " << at << " of " << n;
            }
    }
    Eigen::MatrixXd m = Eigen::MatrixXd::Ones(4, 3);
    EXPECT_TRUE(all_finite(m));
    m(3, 2) = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(all_finite(m));
}

// require_valid_points finds a coinciding consecutive pair wherever it is (its pass runs by blocks
// of 1024 pairs: both sides of a block's edge, the last pair, the closing pair) and names it; pairs
// that differ in one coordinate only, or by the smallest subnormal, pass; −0 and +0 coincide.
// (require_valid_points_with_extent too: the same checks in its own pass, the same messages.)
TEST(Points, RequireValidPointsNamesEveryCoincidingPair) {
    for (const bool with_extent : {false, true}) {
        const auto message = [with_extent](const PointList& p, bool closed) -> std::string {
            try {
                if (with_extent)
                    (void)require_valid_points_with_extent(p, 2, closed, "test");
                else
                    require_valid_points(p, 2, true, closed, "test");
            } catch (const InvalidInput& e) {
                return e.what();
            }
            return "";
        };
        SCOPED_TRACE(with_extent ? "require_valid_points_with_extent" : "require_valid_points");
        for (Eigen::Index dim = 1; dim <= 3; ++dim)
            for (Eigen::Index n : {2, 3, 1024, 1025, 1026, 2050}) {
                PointList p(n, dim);
                for (Eigen::Index i = 0; i < n; ++i)
                    for (Eigen::Index k = 0; k < dim; ++k)
                        p(i, k) = static_cast<double>(i) + 0.5 * static_cast<double>(k);
                const std::string where = "dim " + std::to_string(dim) + " n " + std::to_string(n);
                ASSERT_EQ(message(p, false), "") << where;
                ASSERT_EQ(message(p, n >= 3), "") << where;
                for (Eigen::Index i :
                     {Eigen::Index{0}, Eigen::Index{1022}, Eigen::Index{1023}, Eigen::Index{1024}, n - 2}) {
                    if (i < 0 || i + 1 >= n) continue;
                    PointList q = p;
                    q.row(i + 1) = q.row(i);
                    const std::string named = cagd::point_label(i) + " and " + cagd::point_label(i + 1) + " coincide";
                    EXPECT_NE(message(q, false).find(named), std::string::npos)
                        << where << " pair " << i << ": " << message(q, false);
                    q(i + 1, dim - 1) = std::nextafter(q(i, dim - 1), 1e300);  // one coordinate differs, by one ulp
                    EXPECT_EQ(message(q, false), "") << where << " pair " << i;
                }
                if (n >= 3) {
                    PointList q = p;
                    q.row(n - 1) = q.row(0);
                    EXPECT_EQ(message(q, false), "") << where << ": open, the last point may equal the first";
                    const std::string named = cagd::point_label(n - 1) + " and point 1 (row 0) coincide";
                    EXPECT_NE(message(q, true).find(named), std::string::npos) << where << ": " << message(q, true);
                }
            }
        PointList z(3, 2);
        z << 0.0, 1.0, -0.0, 1.0, 2.0, 2.0;
        EXPECT_NE(message(z, false).find("point 1 (row 0) and point 2 (row 1) coincide"), std::string::npos)
            << "−0 and +0 are the same coordinate";
        z << 0.0, 1.0, std::numeric_limits<double>::denorm_min(), 1.0, 2.0, 2.0;
        EXPECT_EQ(message(z, false), "") << "distinct by the smallest subnormal";
    }
}

// The extent is the largest |coordinate| and the smallest squared chord (closing chord included
// when closed), as Eigen forms them from the rows, bit for bit: over several blocks of 1024 chords,
// with the extremes placed at a block's edges, the last chord and the closing one. A NaN or too few
// points give require_valid_points' own message.
TEST(Points, RequireValidPointsWithExtentGivesTheLargestCoordinateAndShortestChord) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    for (Eigen::Index dim = 1; dim <= 3; ++dim)
        for (Eigen::Index n : {2, 3, 1025, 2600})
            for (const bool closed : {false, true}) {
                if (closed && n < 3) continue;
                PointList p(n, dim);
                for (Eigen::Index i = 0; i < p.size(); ++i) p.data()[i] = u(rng);
                for (Eigen::Index at : {Eigen::Index{1023}, Eigen::Index{1024}, n - 1}) {
                    if (at >= n) continue;
                    PointList q = p;
                    q(at, dim - 1) = -7.5;                                        // the largest |coordinate|
                    if (at > 0) q.row(at - 1) = q.row(at), q(at - 1, 0) += 1e-9;  // the shortest chord ends there
                    const PointExtent e = require_valid_points_with_extent(q, 2, closed, "test");
                    double shortest = std::numeric_limits<double>::infinity();
                    for (Eigen::Index k = 0; k + 1 < n || (closed && k < n); ++k)
                        shortest = std::min(shortest, (q.row(k + 1 == n ? 0 : k + 1) - q.row(k)).squaredNorm());
                    const std::string where = "dim " + std::to_string(dim) + " n " + std::to_string(n) +
                                              (closed ? " closed" : " open") + " at " + std::to_string(at);
                    EXPECT_EQ(e.largest_abs_coordinate, q.cwiseAbs().maxCoeff()) << where;
                    EXPECT_EQ(e.largest_abs_coordinate, 7.5) << where;
                    EXPECT_EQ(e.shortest_squared_chord, shortest) << where;
                }
                if (closed) {  // the closing chord the shortest
                    PointList q = p;
                    q.row(n - 1) = q.row(0);
                    q(n - 1, 0) += 1e-12;
                    EXPECT_EQ(require_valid_points_with_extent(q, 3, true, "test").shortest_squared_chord,
                              (q.row(0) - q.row(n - 1)).squaredNorm())
                        << n << " " << dim;
                }
            }
    PointList bad(3, 2);
    bad << 0, 0, 1, std::numeric_limits<double>::quiet_NaN(), 2, 2;
    const std::string m =
        cagd::test::invalid_input_message([&] { (void)require_valid_points_with_extent(bad, 2, false, "test"); });
    EXPECT_NE(m.find("point 2 (row 1) coordinate y is nan"), std::string::npos) << m;
    const std::string few = cagd::test::invalid_input_message(
        [&] { (void)require_valid_points_with_extent(bad.topRows(1), 2, false, "test"); });
    EXPECT_NE(few.find("needs at least 2 points, got 1"), std::string::npos) << few;
}

// validate_points: require_valid_points_with_extent's checks and messages, its extent, and the
// proof's coverage: a construction needing no more points than it checked for, closed as it was.
TEST(Points, ValidPointsKeepWhatWasCheckedAndCoverNoMore) {
    PointList p(4, 2);
    p << 0, 0, 1, 0, 1, 1, 0, 1;
    const ValidPoints open = validate_points(p, 3, false, "test");
    EXPECT_EQ(&open.points(), &p);
    EXPECT_EQ(open.min_count(), 3);
    EXPECT_FALSE(open.closed());
    EXPECT_EQ(open.extent().largest_abs_coordinate, 1.0);
    EXPECT_EQ(open.extent().shortest_squared_chord, 1.0);
    EXPECT_TRUE(open.cover(2, false));
    EXPECT_TRUE(open.cover(3, false));
    EXPECT_FALSE(open.cover(4, false)) << "checked for 3 points, not 4";
    EXPECT_FALSE(open.cover(3, true)) << "the closing chord was not checked";
    EXPECT_TRUE(validate_points(p, 3, true, "test").cover(3, true));
    // Widened to a construction of 4 points without a second pass; refused beyond the list's size.
    const ValidPoints four = open.at_least(4, "test");
    EXPECT_EQ(&four.points(), &p);
    EXPECT_TRUE(four.cover(4, false));
    EXPECT_FALSE(four.cover(4, true));
    EXPECT_EQ(open.at_least(2, "test").min_count(), 3) << "never narrower than what was checked";
    const std::string few = cagd::test::invalid_input_message([&] { (void)open.at_least(5, "test"); });
    EXPECT_NE(few.find("needs at least 5 points, got 4"), std::string::npos) << few;
    PointList bad = p;
    bad(2, 0) = std::numeric_limits<double>::infinity();
    const std::string m = cagd::test::invalid_input_message([&] { (void)validate_points(bad, 2, false, "test"); });
    EXPECT_NE(m.find("point 3 (row 2) coordinate x is inf"), std::string::npos) << m;
    bad = p;
    bad.row(3) = bad.row(0);
    EXPECT_NO_THROW((void)validate_points(bad, 2, false, "test"));
    const std::string closing = cagd::test::invalid_input_message([&] { (void)validate_points(bad, 2, true, "test"); });
    EXPECT_NE(closing.find("point 4 (row 3) and point 1 (row 0) coincide"), std::string::npos) << closing;
}
