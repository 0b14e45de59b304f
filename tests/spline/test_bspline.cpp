// B-spline and Bézier evaluation, knot insertion, degree elevation, Bézier extraction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/spline/bspline.hpp"

using namespace cagd;

namespace {
BSplineCurve random_curve(int degree, int n, unsigned seed, bool uniform) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0), gap(0.2, 1.5);
    std::vector<double> knots{0.0};
    for (int i = 1; i < n + degree + 1; ++i) knots.push_back(knots.back() + (uniform ? 1.0 : gap(rng)));
    Eigen::MatrixXd c(n, 2);
    for (int i = 0; i < n; ++i) c.row(i) << u(rng), u(rng);
    return BSplineCurve(degree, knots, c);
}
}  // namespace

TEST(BSpline, BasisIsAPartitionOfUnityWithMatchingDerivatives) {
    const BSplineCurve c = random_curve(4, 9, 1, false);
    for (int k = 0; k <= 40; ++k) {
        const double t = c.t_min() + (c.t_max() - c.t_min()) * k / 40.0;
        const int span = c.find_span(t);
        const Eigen::MatrixXd N = basis_function_derivatives(4, c.knots(), span, t, 2);
        EXPECT_NEAR(N.row(0).sum(), 1.0, 1e-14) << "Σ N_i(t) = 1 at t = " << t;
        EXPECT_NEAR(N.row(1).sum(), 0.0, 1e-12) << "Σ N_i'(t) = 0";
    }
}

// find_span starts from the span it found last, then from a bucket index on curves of many spans;
// it must return the span of the definition (U_s ≤ t < U_{s+1}, the last non-empty one at t_max) for any knots: uneven
// gaps, repeated knots (empty spans), a cluster of knots in one bucket, ends clamped or not, and t on the knots and
// just beside them.
TEST(BSpline, FindSpanIsTheSpanOfTheDefinitionOnManySpans) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> gap(0.1, 2.0), unit(0.0, 1.0);
    for (const int variant : {0, 1, 2}) {
        const int degree = 3, n = 500;
        std::vector<double> knots(static_cast<std::size_t>(n + degree + 1));
        double x = 0.0;
        for (std::size_t i = 0; i < knots.size(); ++i) {
            const bool repeat = variant == 1 && i % 7 == 3, cluster = variant == 2 && i > 200 && i < 260;
            if (i > 0 && !repeat) x += cluster ? 1e-6 : gap(rng);
            knots[i] = (variant == 2 && (i <= static_cast<std::size_t>(degree))) ? 0.0 : x;  // variant 2: clamped start
        }
        const BSplineCurve c(degree, knots, Eigen::MatrixXd::Zero(n, 2));
        const auto by_definition = [&](double t) {
            if (t >= c.t_max()) {
                int s = n - 1;
                while (s > degree && knots[static_cast<std::size_t>(s)] == knots[static_cast<std::size_t>(s) + 1]) --s;
                return s;
            }
            return static_cast<int>(std::upper_bound(knots.begin() + degree, knots.begin() + n, t) - knots.begin()) - 1;
        };
        std::vector<double> ts;
        for (int i = degree; i <= n; ++i) {
            const double k = knots[static_cast<std::size_t>(i)];
            ts.insert(ts.end(), {k, std::nextafter(k, -1e300), std::nextafter(k, 1e300)});
        }
        for (int i = 0; i < 20000; ++i) ts.push_back(c.t_min() + unit(rng) * (c.t_max() - c.t_min()));
        for (double t : ts) {
            if (t < c.t_min() || t > c.t_max()) continue;
            ASSERT_EQ(c.find_span(t), by_definition(t)) << "variant " << variant << ", t = " << t;
        }
        // find_span first tries the span it found last: in a shuffled order each t follows another
        // span's (and a knot follows the ulps beside it), and outside the domain it leaves no hint
        // that a t inside would take.
        std::shuffle(ts.begin(), ts.end(), rng);
        for (double t : ts) {
            if (t < c.t_min() || t > c.t_max()) continue;
            (void)c.find_span(std::nextafter(c.t_min(), -1e300));
            ASSERT_EQ(c.find_span(t), by_definition(t)) << "variant " << variant << ", t = " << t;
            const double below = std::max(c.t_min(), std::nextafter(t, -1e300));
            ASSERT_EQ(c.find_span(below), by_definition(below))
                << "variant " << variant << ", t = " << below << " after " << t;
        }
    }
}

TEST(BSpline, DerivativesMatchCentralDifferences) {
    const BSplineCurve c = random_curve(3, 8, 2, false);
    const double h = 1e-5;
    for (double s : {0.13, 0.41, 0.77}) {
        const double t = c.t_min() + s * (c.t_max() - c.t_min());
        const Eigen::MatrixXd J = c.jet(t, 2);
        const Eigen::RowVectorXd fd1 = (c.point(t + h) - c.point(t - h)).transpose() / (2 * h);
        const Eigen::RowVectorXd fd2 = (c.point(t + h) - 2 * c.point(t) + c.point(t - h)).transpose() / (h * h);
        EXPECT_LT((J.row(1) - fd1).norm(), 1e-8);
        EXPECT_LT((J.row(2) - fd2).norm(), 1e-4);
    }
}

TEST(BSpline, KnotInsertionLeavesTheCurveUnchanged) {
    const BSplineCurve c = random_curve(3, 10, 3, false);
    BSplineCurve d = insert_knot(c, 0.37 * c.t_min() + 0.63 * c.t_max());
    d = insert_knot(d, c.knots()[5]);  // raise an existing knot's multiplicity
    EXPECT_EQ(d.control_points().rows(), c.control_points().rows() + 2);
    EXPECT_LT(analysis::max_distance_same_parameter(c, d), 1e-14);
}

TEST(BSpline, DegreeElevationLeavesTheCurveUnchanged) {
    const BSplineCurve c = random_curve(3, 9, 4, false);
    const BSplineCurve e = elevate_degree(c);
    EXPECT_EQ(e.degree(), 4);
    EXPECT_DOUBLE_EQ(e.t_min(), c.t_min());
    EXPECT_DOUBLE_EQ(e.t_max(), c.t_max());
    EXPECT_LT(analysis::max_distance_same_parameter(c, e), 1e-12);
}

TEST(BSpline, ElevatedUniformCubicHasDoubleKnotsAndKnownControls) {
    // Uniform cubic → quartic with double knots: d̂_{2i+1} = (c_i + c_{i+1})/2 and
    // d̂_{2i} = (c_{i−1} + 10 c_i + c_{i+1})/12 (derived from eq (7) and eq (9) of sb2_locality).
    const BSplineCurve c = random_curve(3, 12, 5, true);
    const BSplineCurve e = elevate_degree(c);
    const auto& C = c.control_points();
    const auto& D = e.control_points();
    for (std::size_t k = 5; k + 5 < e.knots().size(); k += 2) EXPECT_EQ(e.knots()[k], e.knots()[k + 1]);
    // Find the control of e associated with c_i: knots of c at integers 0.., c_i centred at i+2.
    // e's control 2j+1 (odd) is centred between; locate by matching the formula, with index offset.
    int matched = 0;
    for (Eigen::Index j = 1; j + 1 < D.rows(); ++j)
        for (Eigen::Index i = 1; i + 1 < C.rows(); ++i)
            if ((D.row(j) - (C.row(i - 1) + 10 * C.row(i) + C.row(i + 1)) / 12.0).norm() < 1e-12 &&
                (D.row(j + 1) - (C.row(i) + C.row(i + 1)) / 2.0).norm() < 1e-12)
                ++matched;
    EXPECT_GE(matched, 6);
}

TEST(BSpline, BezierSegmentsReproduceTheCurve) {
    const BSplineCurve c = random_curve(4, 9, 6, false);
    const auto segs = bezier_segments(c);
    EXPECT_EQ(segs.size(), c.breakpoints().size() - 1);
    for (const auto& s : segs) {
        EXPECT_LT(analysis::max_distance_same_parameter(c, s, s.t_min(), s.t_max(), 33), 1e-12);
        EXPECT_LT((s.jet(s.t_max(), 2) - c.jet(s.t_max() - 1e-15, 2)).norm(), 1e-8);
    }
}

TEST(BSpline, SingleBasisFunctionMatchesCurveBasis) {
    // Uniform cubic B-spline at its centre: 2/3; at ±1 from the centre: 1/6.
    const std::vector<double> k{0, 1, 2, 3, 4};
    EXPECT_NEAR(bspline_basis(3, k, 2.0), 2.0 / 3.0, 1e-15);
    EXPECT_NEAR(bspline_basis(3, k, 1.0), 1.0 / 6.0, 1e-15);
    EXPECT_EQ(bspline_basis(3, k, -0.1), 0.0);
    EXPECT_EQ(bspline_basis(3, k, 4.0), 0.0);
    EXPECT_NEAR(bspline_basis(3, k, 2.0, 1), 0.0, 1e-15);
    EXPECT_NEAR(bspline_basis(3, k, 1.0, 1), 0.5, 1e-14);
}

TEST(BSpline, RejectsBadInput) {
    Eigen::MatrixXd c = Eigen::MatrixXd::Zero(4, 2);
    EXPECT_THROW(BSplineCurve(3, {0, 1, 2, 3, 4, 5, 6}, c), InvalidInput);     // too few knots
    EXPECT_THROW(BSplineCurve(3, {0, 1, 2, 3, 5, 4, 6, 7}, c), InvalidInput);  // decreasing
    EXPECT_THROW(BSplineCurve(3, {0, 0, 0, 0, 0, 1, 1, 1}, c), InvalidInput);  // multiplicity 5
    c(1, 0) = NAN;
    EXPECT_THROW(BSplineCurve(3, {0, 1, 2, 3, 4, 5, 6, 7}, c), InvalidInput);
    const BSplineCurve ok = random_curve(3, 5, 7, true);
    EXPECT_THROW(ok.jet(ok.t_max() + 0.1, 0), InvalidInput);
    EXPECT_THROW(BezierCurve(Eigen::MatrixXd::Zero(3, 2), 1.0, 1.0), InvalidInput);
}

// jet_into and derivatives_into go through Taylor rows unrolled for degrees 2..5 in 2 and 3
// dimensions (a loop otherwise), and derivatives_into skips the position; all must be jet()'s
// values bit for bit — on knots (Piegl & Tiller A2.3) and between them — and jet() must be the
// definition's values to rounding, at every degree.
TEST(BSpline, JetIntoAndDerivativesIntoAreTheJetBitForBit) {
    for (const int degree : {1, 2, 3, 5, 6, 10, 11})  // 10, 11: past the unrolled degrees (and 8·2 + 10 = 8·3 + 2)
        for (const int dim : {2, 3}) {
            std::mt19937 rng(static_cast<unsigned>(7 * degree + dim));
            std::uniform_real_distribution<double> u(-1.0, 1.0), gap(0.2, 1.5);
            const int n = 90;
            std::vector<double> knots{0.0};
            for (int i = 1; i < n + degree + 1; ++i) knots.push_back(knots.back() + gap(rng));
            Eigen::MatrixXd control(n, dim);
            for (int i = 0; i < n; ++i)
                for (int e = 0; e < dim; ++e) control(i, e) = u(rng);
            const BSplineCurve c(degree, knots, control);
            std::vector<double> ts{c.t_min(), c.t_max(), knots[static_cast<std::size_t>(degree) + 5]};
            for (int i = 0; i < 200; ++i) ts.push_back(c.t_min() + (c.t_max() - c.t_min()) * (i + 0.37) / 200.0);
            JetMatrix J;
            for (double t : ts) {
                // jet() itself against the definition, Σ N^(d)_{i,p}(t) P_i by Piegl & Tiller A2.3 (the
                // Taylor form differs by rounding only: 1e-9 of the jet's size at these degrees).
                const int span = c.find_span(t);
                const Eigen::MatrixXd by_basis = basis_function_derivatives(degree, knots, span, t, kJetCapacity - 1) *
                                                 control.middleRows(span - degree, degree + 1);
                const Eigen::MatrixXd taylor = c.jet(t, kJetCapacity - 1);
                EXPECT_LT((taylor - by_basis).norm(), 1e-9 * (1.0 + by_basis.norm()))
                    << "degree " << degree << ", dim " << dim << ", t " << t;
                for (int order = 0; order < kJetCapacity; ++order) {
                    c.jet_into(t, order, J);
                    ASSERT_EQ(J.rows(), order + 1);
                    EXPECT_EQ(Eigen::MatrixXd(J), c.jet(t, order))
                        << "degree " << degree << ", dim " << dim << ", t " << t << ", order " << order;
                }
                for (int order = 1; order < kJetCapacity; ++order) {
                    c.derivatives_into(t, order, J);
                    ASSERT_EQ(J.rows(), order);
                    EXPECT_EQ(Eigen::MatrixXd(J), c.jet(t, order).bottomRows(order))
                        << "degree " << degree << ", dim " << dim << ", t " << t << ", order " << order;
                }
            }
            EXPECT_THROW(c.derivatives_into(c.t_max() + 1.0, 1, J), InvalidInput);
        }
}

// At a knot the jet is A2.3's, bit for bit, now read from the table of knot jets: the ends and the
// joins (both sides: jet and jet_from_left), every order up to the degree and one above, degrees
// 1 to 7, uniform and not, clamped ends.
TEST(BSpline, JetsAtKnotsAreTheA23ValuesBitForBit) {
    for (int p = 1; p <= 7; ++p)
        for (bool uniform : {true, false}) {
            BSplineCurve free = random_curve(p, p + 6, static_cast<unsigned>(40 + p), uniform);
            std::vector<double> knots = free.knots();
            for (int i = 0; i <= p; ++i) {  // clamp both ends: p + 1 equal knots
                knots[static_cast<std::size_t>(i)] = knots[static_cast<std::size_t>(p)];
                knots[knots.size() - 1 - static_cast<std::size_t>(i)] =
                    knots[knots.size() - 1 - static_cast<std::size_t>(p)];
            }
            const BSplineCurve c(p, knots, free.control_points());
            const int n = static_cast<int>(c.control_points().rows());
            for (int s = p; s < n; ++s)
                for (int end = 0; end < 2; ++end) {
                    const double t = knots[static_cast<std::size_t>(s + end)];
                    for (int order = 0; order <= p + 1; ++order) {
                        const Eigen::MatrixXd direct = basis_function_derivatives(p, knots, s, t, order) *
                                                       c.control_points().middleRows(s - p, p + 1);
                        const Eigen::MatrixXd ours = end == 0 ? c.jet(t, order) : c.jet_from_left(t, order);
                        ASSERT_EQ(ours.rows(), order + 1);
                        for (int k = 0; k <= std::min(order, p); ++k)
                            for (int e = 0; e < 2; ++e)
                                ASSERT_EQ(ours(k, e), direct(k, e)) << "degree " << p << " span " << s << " end " << end
                                                                    << " order " << order << " row " << k;
                    }
                }
            // A clamped end gives its control point, to rounding (A2.3 forms 1 as r·(1/r)).
            EXPECT_LE((c.jet(c.t_min(), 0).row(0) - c.control_points().row(0)).norm(), 4e-16);
            EXPECT_LE((c.jet(c.t_max(), 0).row(0) - c.control_points().row(n - 1)).norm(), 4e-16);
        }
}

// Off the knots a jet comes from each span's Taylor coefficients c_k = D_k / k! at the span's middle,
// D = (A2.3's basis derivatives there) · (the span's control points). At the middle itself (h = 0)
// Horner leaves k! · c_k: the table's D, bit for bit, equals the product formed from
// basis_function_derivatives' MatrixXd (the table forms it from the stack array, degree ≤ 7).
TEST(BSpline, TaylorTableIsTheA23ProductAtEachSpanMiddleBitForBit) {
    for (int p = 1; p <= 9; ++p)
        for (int dim : {2, 3}) {
            const BSplineCurve planar = random_curve(p, p + 12, static_cast<unsigned>(70 + p), false);
            Eigen::MatrixXd control(planar.control_points().rows(), dim);
            control.leftCols(2) = planar.control_points();
            if (dim == 3) control.col(2) = planar.control_points().col(0).array() * 0.7 - 0.1;
            const BSplineCurve c(p, planar.knots(), control);
            const std::vector<double>& U = c.knots();
            for (int s = p; s < static_cast<int>(control.rows()); ++s) {
                const double middle = 0.5 * (U[static_cast<std::size_t>(s)] + U[static_cast<std::size_t>(s) + 1]);
                const Eigen::MatrixXd D =
                    basis_function_derivatives(p, U, s, middle, p) * control.middleRows(s - p, p + 1);
                const Eigen::MatrixXd jet = c.jet(middle, p);
                double factorial = 1.0;
                for (int k = 0; k <= p; ++k) {
                    if (k > 0) factorial *= k;
                    for (int e = 0; e < dim; ++e)
                        ASSERT_EQ(jet(k, e), factorial * (D(k, e) / factorial))
                            << "degree " << p << " dimension " << dim << " span " << s << " row " << k;
                }
            }
        }
}

// The tables are built block by block (1024 spans each) as spans are first evaluated: on a curve of
// three blocks, asked span by span in a scattered order and from two threads at once, every jet at
// a span's middle and at its knots is the one A2.3 gives there, bit for bit, as when the whole table
// is built first (the same product, tested above on one block).
TEST(BSpline, TablesBuiltBlockByBlockAreTheWholeTablesBitForBit) {
    for (int p : {2, 3}) {
        const BSplineCurve built_whole = random_curve(p, 2600, static_cast<unsigned>(90 + p), false);
        const std::vector<double>& U = built_whole.knots();
        const int n = static_cast<int>(built_whole.control_points().rows());
        for (int s = p; s < n; ++s)
            (void)built_whole.jet(0.5 * (U[static_cast<std::size_t>(s)] + U[static_cast<std::size_t>(s) + 1]),
                                  p);  // every block, in order
        const BSplineCurve scattered = random_curve(p, 2600, static_cast<unsigned>(90 + p), false);
        std::vector<int> spans;
        for (int k = 0; k < n - p; ++k)
            spans.push_back(p + (k * 997 + n - p - 1) % (n - p));  // every span, from the last on, 997 apart (a prime)
        const auto same_jets = [&](int s) {
            const double middle = 0.5 * (U[static_cast<std::size_t>(s)] + U[static_cast<std::size_t>(s) + 1]);
            const Eigen::MatrixXd D =
                basis_function_derivatives(p, U, s, middle, p) * scattered.control_points().middleRows(s - p, p + 1);
            const Eigen::MatrixXd jet = scattered.jet(middle, p),
                                  at_start = scattered.jet(U[static_cast<std::size_t>(s)], p),
                                  at_end = scattered.jet_from_left(U[static_cast<std::size_t>(s) + 1], p);
            const Eigen::MatrixXd start_direct =
                basis_function_derivatives(p, U, s, U[static_cast<std::size_t>(s)], p) *
                scattered.control_points().middleRows(s - p, p + 1);
            const Eigen::MatrixXd end_direct =
                basis_function_derivatives(p, U, s, U[static_cast<std::size_t>(s) + 1], p) *
                scattered.control_points().middleRows(s - p, p + 1);
            double factorial = 1.0;
            for (int k = 0; k <= p; ++k) {
                if (k > 0) factorial *= k;
                for (int e = 0; e < 2; ++e)
                    if (jet(k, e) != factorial * (D(k, e) / factorial) || at_start(k, e) != start_direct(k, e) ||
                        at_end(k, e) != end_direct(k, e) || jet(k, e) != built_whole.jet(middle, p)(k, e))
                        return false;
            }
            return true;
        };
        for (int s : spans) EXPECT_TRUE(same_jets(s)) << "degree " << p << " span " << s;
        const BSplineCurve fresh = scattered;  // a copy builds its own tables: two threads ask for the same blocks
        std::vector<char> ok(static_cast<std::size_t>(n), 0);
        const auto ask = [&](int from, int step) {
            for (int s = from; s >= p && s < n; s += step) {
                const double middle = 0.5 * (U[static_cast<std::size_t>(s)] + U[static_cast<std::size_t>(s) + 1]);
                ok[static_cast<std::size_t>(s)] =
                    fresh.jet(middle, p) == built_whole.jet(middle, p) &&
                    fresh.jet(U[static_cast<std::size_t>(s)], p) == built_whole.jet(U[static_cast<std::size_t>(s)], p);
            }
        };
        std::thread forward(ask, p, 2),
            backward(ask, n - 1 - (n - 1 - (p + 1)) % 2, -2);  // the spans p, p + 2, … and p + 1, p + 3, …
        forward.join(), backward.join();
        EXPECT_EQ(std::count(ok.begin() + p, ok.end(), 1), n - p) << "degree " << p;
    }
}
