// spline/hermite_spline: piecewise cubic Hermite curves, the cubic splines A and B and the Hermite
// curves A and B of pseudo_energy section 4.2.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/fairness/pseudo_spline.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "cagd/numeric/tridiagonal.hpp"
#include "cagd/spline/hermite_spline.hpp"

#include "../support/messages.hpp"
#include "../support/point_lists.hpp"

using namespace cagd;
using namespace cagd::test;
using namespace cagd::fairness;
using spline::PiecewiseHermiteCurve;

TEST(PiecewiseHermite, InterpolatesNodesAndEndDerivativesAndMatchesFiniteDifferences) {
    Eigen::MatrixXd nodes(3, 2), d0(2, 2), d1(2, 2);
    nodes << 0, 0, 1, 2, 3, 1;
    d0 << 1, 1, 2, -1;
    d1 << 0.5, 2, 1, 0;
    const PiecewiseHermiteCurve c(nodes, d0, d1);
    for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR((c.jet(k, 1).row(0) - nodes.row(k)).norm(), 0.0, 1e-15);
        EXPECT_NEAR((c.jet(k + 1, 0).row(0) - nodes.row(k + 1)).norm(), 0.0, 1e-15);
        EXPECT_NEAR((c.jet(k + 1e-300, 1).row(1) - d0.row(k)).norm(), 0.0, 1e-12) << "r'(k) = d0_k";
        EXPECT_NEAR((c.jet(k + 1 - 1e-15, 1).row(1) - d1.row(k)).norm(), 0.0, 1e-12) << "r'(k+1) = d1_k";
    }
    const double h = 1e-6;
    for (double u : {0.3, 1.6}) {
        const Eigen::MatrixXd j = c.jet(u, 3), jp = c.jet(u + h, 2), jm = c.jet(u - h, 2);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(((jp.row(k) - jm.row(k)) / (2 * h) - j.row(k + 1)).norm(), 0.0, 1e-7);
    }
    EXPECT_THROW(c.jet(2.5, 0), InvalidInput);
    EXPECT_THROW(PiecewiseHermiteCurve(nodes, d0.topRows(1), d1), InvalidInput);
}

TEST(CubicSplines, NaturalUniformSplineAIsTheBSplineInterpolantOfSb2LocalityEq10) {
    const PiecewiseHermiteCurve a =
        spline::cubic_spline_interpolant(kNewberyGarrett, spline::ParameterSpacing::uniform, false);
    const BSplineCurve b = locality::cubic_bspline_interpolant(kNewberyGarrett, false);
    EXPECT_LT(analysis::max_distance_same_parameter(a, b), 1e-12);
    const PiecewiseHermiteCurve ac =
        spline::cubic_spline_interpolant(kNewberyGarrett, spline::ParameterSpacing::uniform, true);
    const BSplineCurve bc = locality::cubic_bspline_interpolant(kNewberyGarrett, true);
    EXPECT_LT(analysis::max_distance_same_parameter(ac, bc), 1e-12) << "closed";
}

TEST(CubicSplines, ChordLengthSplineBIsC2InItsParameterWithNaturalEnds) {
    for (bool closed : {false, true}) {
        const PiecewiseHermiteCurve c =
            spline::cubic_spline_interpolant(kNewberyGarrett, spline::ParameterSpacing::chord_length, closed);
        const Eigen::MatrixXd& p = c.nodes();
        const auto h = [&](int k) { return (p.row(k + 1) - p.row(k)).norm(); };
        for (int k = 1; k <= c.spans(); ++k) {
            if (!closed && k == c.spans()) break;
            const int next = k % c.spans();
            const Eigen::MatrixXd left = c.jet(k - 1e-13, 2), right = c.jet(next == 0 ? 0.0 : k, 2);
            // dr/dτ = r'(t)/h, d²r/dτ² = r''(t)/h² on each span.
            EXPECT_NEAR((left.row(1) / h(k - 1) - right.row(1) / h(next)).norm(), 0.0, 1e-9) << "C1 at node " << k;
            EXPECT_NEAR((left.row(2) / (h(k - 1) * h(k - 1)) - right.row(2) / (h(next) * h(next))).norm(), 0.0, 1e-8)
                << "C2 at node " << k;
        }
        if (!closed) {
            EXPECT_NEAR(c.jet(0, 2).row(2).norm(), 0.0, 1e-10) << "natural start";
            EXPECT_NEAR(c.jet(c.spans(), 2).row(2).norm(), 0.0, 1e-10) << "natural end";
        }
    }
}

TEST(HermiteCurves, CircleTangentsAreThoseOfTheCircumcircle) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-3, 3);
    for (int trial = 0; trial < 50; ++trial) {
        PointList p(3, 2);
        for (int i = 0; i < 3; ++i) p.row(i) << u(rng), u(rng);
        // Circumcentre by the perpendicular bisectors.
        const Eigen::Vector2d a = p.row(0), b = p.row(1), c = p.row(2);
        Eigen::Matrix2d m;
        m << 2 * (b - a).transpose(), 2 * (c - a).transpose();
        if (std::abs(m.determinant()) < 1e-3) continue;
        const Eigen::Vector2d rhs(b.squaredNorm() - a.squaredNorm(), c.squaredNorm() - a.squaredNorm());
        const Eigen::Vector2d centre = m.partialPivLu().solve(rhs);
        const Eigen::MatrixXd t = spline::hermite_tangent_directions(p, spline::TangentRule::circle, false);
        for (int i = 0; i < 3; ++i) {
            const Eigen::Vector2d radius = p.row(i).transpose() - centre;
            EXPECT_NEAR(t.row(i).dot(radius), 0.0, 1e-9) << "tangent ⟂ radius at point " << i;
            EXPECT_NEAR(t.row(i).norm(), 1.0, 1e-14);
        }
        // All three tangents turn the same way round the circle (a consistent orientation).
        const double s0 = Eigen::Vector2d(p.row(0).transpose() - centre).x() * t(0, 1) -
                          Eigen::Vector2d(p.row(0).transpose() - centre).y() * t(0, 0);
        const double s1 = Eigen::Vector2d(p.row(1).transpose() - centre).x() * t(1, 1) -
                          Eigen::Vector2d(p.row(1).transpose() - centre).y() * t(1, 0);
        const double s2 = Eigen::Vector2d(p.row(2).transpose() - centre).x() * t(2, 1) -
                          Eigen::Vector2d(p.row(2).transpose() - centre).y() * t(2, 0);
        EXPECT_GT(s0 * s1, 0.0);
        EXPECT_GT(s1 * s2, 0.0);
    }
}

TEST(HermiteCurves, HermiteAUsesNeighbourChordsAndChordLengthMagnitudes) {
    const Eigen::MatrixXd t =
        spline::hermite_tangent_directions(kNewberyGarrett, spline::TangentRule::chord_of_neighbours, false);
    EXPECT_NEAR(angle_of(t.row(0)), angle_of(kNewberyGarrett.row(1) - kNewberyGarrett.row(0)), 1e-14);
    EXPECT_NEAR(angle_of(t.row(5)), angle_of(kNewberyGarrett.row(6) - kNewberyGarrett.row(4)), 1e-14);
    const PiecewiseHermiteCurve c = spline::hermite_interpolant(kNewberyGarrett, t, false);
    EXPECT_NEAR(c.start_derivatives().row(3).norm(), (kNewberyGarrett.row(4) - kNewberyGarrett.row(3)).norm(), 1e-14);
    EXPECT_NEAR(c.end_derivatives().row(3).norm(), (kNewberyGarrett.row(4) - kNewberyGarrett.row(3)).norm(), 1e-14);
    EXPECT_THROW(spline::hermite_tangent_directions(points({{0, 0}, {1, 0}, {0, 0.0}}),
                                                    spline::TangentRule::chord_of_neighbours, false),
                 InvalidInput)
        << "P0 = P2: no direction (and coincident points)";
    EXPECT_THROW(spline::hermite_tangent_directions(points({{0, 0}, {1, 0}, {0.0, 0.0}, {2, 0}}),
                                                    spline::TangentRule::circle, false),
                 InvalidInput)
        << "an exact reversal with equal chords";
}

// hermite_spline is hermite_interpolant of hermite_tangent_directions in one pass: the same nodes
// and end derivatives to the last bit, for both rules, open and closed, planar and space points.
TEST(HermiteCurves, OnePassCurveIsTheInterpolantOfTheDirections) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
    for (const int dim : {2, 3})
        for (const bool closed : {false, true})
            for (const spline::TangentRule rule :
                 {spline::TangentRule::chord_of_neighbours, spline::TangentRule::circle})
                for (const int n : {3, 4, 50}) {
                    PointList p(n, dim);
                    for (Eigen::Index i = 0; i < n; ++i)
                        for (Eigen::Index c = 0; c < dim; ++c) p(i, c) = coordinate(rng);
                    const PiecewiseHermiteCurve one = spline::hermite_spline(p, rule, closed);
                    const PiecewiseHermiteCurve two =
                        spline::hermite_interpolant(p, spline::hermite_tangent_directions(p, rule, closed), closed);
                    ASSERT_EQ(one.spans(), closed ? n : n - 1);
                    EXPECT_EQ(one.nodes(), two.nodes());
                    EXPECT_EQ(one.start_derivatives(), two.start_derivatives())
                        << n << " points, dim " << dim << (closed ? ", closed" : ", open");
                    EXPECT_EQ(one.end_derivatives(), two.end_derivatives())
                        << n << " points, dim " << dim << (closed ? ", closed" : ", open");
                }
}

TEST(HermiteCurves, PlanarColumnWisePathIsTheSpaceCurvesBitForBit) {
    // Planar points take a column-wise path (planar_hermite_interior); the same points with z = 0
    // take the per-point one. Their x and y derivatives must agree exactly, and a reversal must be
    // reported at the same (first) point.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> turn(-1.0, 1.0), chord(0.1, 2.0);
    for (const int n : {2, 3, 4, 10000}) {
        PointList p(n, 2);
        double angle = 0.0;
        p.row(0) << 0.0, 0.0;
        for (Eigen::Index i = 1; i < n; ++i) {
            angle += turn(rng);
            const double r = chord(rng);
            p.row(i) = p.row(i - 1) + Eigen::RowVector2d(r * std::cos(angle), r * std::sin(angle));
        }
        PointList space = PointList::Zero(n, 3);
        space.leftCols(2) = p;
        for (const bool closed : {false, true})
            for (const spline::TangentRule rule :
                 {spline::TangentRule::chord_of_neighbours, spline::TangentRule::circle}) {
                if (n < 3 && (closed || rule == spline::TangentRule::circle)) continue;
                const PiecewiseHermiteCurve planar = spline::hermite_spline(p, rule, closed),
                                            spatial = spline::hermite_spline(space, rule, closed);
                EXPECT_EQ(planar.start_derivatives(), spatial.start_derivatives().leftCols(2))
                    << n << (closed ? " closed" : " open");
                EXPECT_EQ(planar.end_derivatives(), spatial.end_derivatives().leftCols(2))
                    << n << (closed ? " closed" : " open");
            }
    }
    PointList reverses(7, 2);
    reverses << 0, 0, 1, 0, 2, 1, 3, 0, 2, 1, 3, 0, 5,
        5;  // reverses at points 3 and 4 (P_2 = P_4, P_3 = P_5): the first is named
    for (const spline::TangentRule rule : {spline::TangentRule::chord_of_neighbours, spline::TangentRule::circle})
        for (const bool closed : {false, true}) {
            try {
                spline::hermite_spline(reverses, rule, closed);
                ADD_FAILURE() << "a reversal accepted";
            } catch (const InvalidInput& e) {
                EXPECT_NE(std::string(e.what()).find("reverses at point 3 "), std::string::npos) << e.what();
            }
        }
}

// from_node_slopes forms span k's d0_k = h_k m_k and d1_k = h_k m_{k+1} (closed: m_K = m_0; no
// scales: h_k = 1, d0_k = m_k exactly), bit for bit.
TEST(PiecewiseHermiteCurve, FromNodeSlopesFormsTheDerivativePairs) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    for (int dim = 1; dim <= 3; ++dim)
        for (bool closed : {false, true})
            for (bool scaled : {false, true}) {
                const int spans = 9, slopes = closed ? spans : spans + 1;
                Eigen::MatrixXd nodes(spans + 1, dim), m(slopes, dim);
                for (Eigen::Index i = 0; i < nodes.rows(); ++i)
                    for (int c = 0; c < dim; ++c)
                        nodes(i, c) = coordinate(rng) + (c == 0 ? static_cast<double>(i) : 0.0);
                for (Eigen::Index i = 0; i < m.rows(); ++i)
                    for (int c = 0; c < dim; ++c) m(i, c) = coordinate(rng);
                std::vector<double> h;
                if (scaled)
                    for (int k = 0; k < spans; ++k) h.push_back(0.5 + std::abs(coordinate(rng)));
                const PiecewiseHermiteCurve c = PiecewiseHermiteCurve::from_node_slopes(nodes, m, h);
                const std::string what = std::to_string(dim) + "-D, " + (closed ? "closed" : "open") +
                                         (scaled ? ", scaled" : ", unit scales");
                for (int k = 0; k < spans; ++k) {
                    const int next = k + 1 == slopes ? 0 : k + 1;
                    for (int col = 0; col < dim; ++col) {
                        const double hk = scaled ? h[static_cast<std::size_t>(k)] : 1.0;
                        ASSERT_EQ(c.start_derivatives()(k, col), scaled ? hk * m(k, col) : m(k, col))
                            << what << " span " << k;
                        ASSERT_EQ(c.end_derivatives()(k, col), scaled ? hk * m(next, col) : m(next, col))
                            << what << " span " << k;
                    }
                }
            }
}

// The slopes are the solution of the system the function states (row k: hn m_{k−1} + 2(hp + hn) m_k
// + hp m_{k+1} = 3(hn Δ_{k−1}/hp + hp Δ_k/hn), open ends 2m_0 + m_1 = 3Δ_0/h_0 and
// m_{K−1} + 2m_K = 3Δ_{K−1}/h_{K−1}), assembled here as three diagonals and a right-hand side and
// solved by solve_tridiagonal (closed: solve_cyclic_tridiagonal), bit for bit (each span's pairs
// are h_k times them): the construction forms each row as the elimination reaches it.
TEST(CubicSplines, SlopesAreTheSolveOfTheAssembledSystemBitForBit) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    for (int dim = 1; dim <= 3; ++dim)
        for (bool closed : {false, true})
            for (auto spacing : {spline::ParameterSpacing::uniform, spline::ParameterSpacing::chord_length})
                for (int n : {2, 3, 4, 31}) {
                    if (closed && n < 3) continue;
                    PointList p(n, dim);
                    for (Eigen::Index i = 0; i < p.rows(); ++i)
                        for (int c = 0; c < dim; ++c)
                            p(i, c) = coordinate(rng) + (c == 0 ? static_cast<double>(i) : 0.0);
                    const int spans = closed ? n : n - 1, N = closed ? spans : spans + 1;
                    const auto node = [&](int k) { return p.row(k % n); };
                    std::vector<double> h(static_cast<std::size_t>(spans), 1.0), sub, diag, sup;
                    if (spacing == spline::ParameterSpacing::chord_length)
                        for (int k = 0; k < spans; ++k) h[static_cast<std::size_t>(k)] = (node(k + 1) - node(k)).norm();
                    Eigen::MatrixXd rhs(N, dim);
                    for (int k = 0; k < N; ++k) {
                        if (!closed && (k == 0 || k == N - 1)) {
                            const int span = k == 0 ? 0 : spans - 1;
                            sub.push_back(k == 0 ? 0.0 : 1.0), diag.push_back(2.0), sup.push_back(k == 0 ? 1.0 : 0.0);
                            rhs.row(k) = 3.0 * (node(span + 1) - node(span)) / h[static_cast<std::size_t>(span)];
                            continue;
                        }
                        const int prev = k == 0 ? spans - 1 : k - 1, next = k;
                        const double hp = h[static_cast<std::size_t>(prev)], hn = h[static_cast<std::size_t>(next)];
                        sub.push_back(hn), diag.push_back(2.0 * (hp + hn)), sup.push_back(hp);
                        rhs.row(k) =
                            3.0 * (hn * (node(prev + 1) - node(prev)) / hp + hp * (node(next + 1) - node(next)) / hn);
                    }
                    const Eigen::MatrixXd want = closed ? numeric::solve_cyclic_tridiagonal(sub, diag, sup, rhs)
                                                        : numeric::solve_tridiagonal(sub, diag, sup, rhs);
                    const PiecewiseHermiteCurve c = spline::cubic_spline_interpolant(p, spacing, closed);
                    const std::string what =
                        std::to_string(dim) + "-D, " + std::to_string(n) + " points, " + (closed ? "closed" : "open") +
                        (spacing == spline::ParameterSpacing::uniform ? ", uniform" : ", chord length");
                    for (int k = 0; k < spans; ++k) {
                        const double hk = h[static_cast<std::size_t>(k)];
                        const Eigen::RowVectorXd m0 = want.row(k), m1 = want.row(k + 1 == N ? 0 : k + 1);
                        const Eigen::RowVectorXd d0 =
                            spacing == spline::ParameterSpacing::uniform ? m0 : Eigen::RowVectorXd(hk * m0);
                        const Eigen::RowVectorXd d1 =
                            spacing == spline::ParameterSpacing::uniform ? m1 : Eigen::RowVectorXd(hk * m1);
                        ASSERT_TRUE(c.start_derivatives().row(k) == d0 && c.end_derivatives().row(k) == d1)
                            << what << ", span " << k;
                    }
                }
}

TEST(CubicSplines, SlopeFormRefusesWhatIsNotACurve) {
    const Eigen::MatrixXd nodes = Eigen::MatrixXd::Random(4, 2), slopes = Eigen::MatrixXd::Random(4, 2);
    EXPECT_NO_THROW(PiecewiseHermiteCurve::from_node_slopes(nodes, slopes, {1.0, 2.0, 3.0}));
    EXPECT_NO_THROW(PiecewiseHermiteCurve::from_node_slopes(nodes, slopes.topRows(3), {}));  // closed: m_3 = m_0
    EXPECT_THROW(PiecewiseHermiteCurve::from_node_slopes(nodes.topRows(1), slopes.topRows(1), {}), InvalidInput);
    EXPECT_THROW(PiecewiseHermiteCurve::from_node_slopes(nodes, slopes.topRows(2), {}), InvalidInput);
    EXPECT_THROW(PiecewiseHermiteCurve::from_node_slopes(nodes, slopes, {1.0, 2.0}), InvalidInput);
    EXPECT_THROW(PiecewiseHermiteCurve::from_node_slopes(nodes, Eigen::MatrixXd::Random(4, 3), {}), InvalidInput);
    Eigen::MatrixXd bad = slopes;
    bad(2, 1) = std::nan("");
    EXPECT_THROW(PiecewiseHermiteCurve::from_node_slopes(nodes, bad, {}), InvalidInput);
    EXPECT_THROW(PiecewiseHermiteCurve::from_node_slopes(nodes, slopes, {1.0, INFINITY, 3.0}), InvalidInput);
}

// The constructions on points validated already (ValidPoints) are the PointList ones bit for bit;
// where the proof does not cover them (fewer points checked for, the other closedness) they check
// the points as a PointList, with its messages.
TEST(HermiteCurves, ValidatedPointsGiveTheSameCurvesAndAreCheckedWhereTheProofFallsShort) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int dim = 2; dim <= 3; ++dim)
        for (bool closed : {false, true}) {
            PointList p(300, dim);
            for (Eigen::Index i = 0; i < p.rows(); ++i)
                for (int c = 0; c < dim; ++c) p(i, c) = static_cast<double>(i) * (c == 0) + u(rng);
            const ValidPoints valid = validate_points(p, 3, closed, "test");
            const std::string what = std::to_string(dim) + "-D, " + (closed ? "closed" : "open");
            for (auto rule : {spline::TangentRule::chord_of_neighbours, spline::TangentRule::circle}) {
                const PiecewiseHermiteCurve a = spline::hermite_spline(valid, rule),
                                            b = spline::hermite_spline(p, rule, closed);
                EXPECT_TRUE(a.nodes() == b.nodes() && a.start_derivatives() == b.start_derivatives() &&
                            a.end_derivatives() == b.end_derivatives())
                    << what;
            }
            for (auto spacing : {spline::ParameterSpacing::uniform, spline::ParameterSpacing::chord_length}) {
                const PiecewiseHermiteCurve a = spline::cubic_spline_interpolant(valid, spacing),
                                            b = spline::cubic_spline_interpolant(p, spacing, closed);
                EXPECT_TRUE(a.nodes() == b.nodes() && a.start_derivatives() == b.start_derivatives() &&
                            a.end_derivatives() == b.end_derivatives())
                    << what;
            }
        }
    PointList two(2, 2);
    two << 0, 0, 1, 0;
    const ValidPoints checked_for_two = validate_points(two, 2, false, "test");
    const std::string m = cagd::test::invalid_input_message(
        [&] { (void)spline::hermite_spline(checked_for_two, spline::TangentRule::circle); });
    EXPECT_EQ(m, cagd::test::invalid_input_message(
                     [&] { (void)spline::hermite_spline(two, spline::TangentRule::circle, false); }))
        << "Hermite B needs 3 points";
    EXPECT_NE(m.find("at least 3"), std::string::npos) << m;
}
