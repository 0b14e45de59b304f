// hosaka sections 2–3: exact rational polynomials, the generalised Hermite basis (eq 1–14), Hosaka
// curves and splines (eq 15–24).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/rational_polynomial.hpp"
#include "cagd/spline/hermite_spline.hpp"
#include "cagd/spline/hosaka_basis.hpp"
#include "cagd/spline/hosaka_spline.hpp"

using namespace cagd;

namespace {

cagd::PointList uneven_points() {
    cagd::PointList p(6, 2);
    p << 0, 0, 1, 0.8, 1.15, 0.95, 3.0, 1.2, 3.2, 0.9, 5.0, 0.0;
    return p;
}

}  // namespace

TEST(HosakaBasis, CardinalEndDerivativesHoldExactlyForHigherM) {
    // m = 6, 7 (beyond the experiment's m ≤ 5): p_i^(k)(0) = δ_ik, q_i^(k)(1) = δ_ik, the others 0.
    for (int m : {6, 7})
        for (int i = 0; i <= m; ++i) {
            const RationalPolynomial p = spline::hosaka_p(m, i), q = spline::hosaka_q(m, i);
            EXPECT_EQ(p.degree(), 2 * m + 1);
            for (int k = 0; k <= m; ++k) {
                EXPECT_EQ(p.derivative(k)(0), i == k ? 1 : 0) << "m " << m << " i " << i << " k " << k;
                EXPECT_EQ(q.derivative(k)(1), i == k ? 1 : 0);
                EXPECT_EQ(p.derivative(k)(1), 0);
                EXPECT_EQ(q.derivative(k)(0), 0);
            }
        }
}

TEST(HosakaBasis, DoubleEvaluationMatchesTheExactBasisAndInterpolatesAQuintic) {
    const spline::HosakaBasis b(2);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        const double t = u(rng);
        for (int i = 0; i <= 2; ++i)
            for (int k = 0; k <= 5; ++k) {
                EXPECT_NEAR(b.p(i, t, k), spline::hosaka_p(2, i).derivative(k).value(t), 1e-10);
                EXPECT_NEAR(b.q(i, t, k), spline::hosaka_q(2, i).derivative(k).value(t), 1e-10);
            }
    }
    // eq (1) with m = 2 reproduces the quintic φ(t) = 1 + 2t − t³ + 0.5 t⁵ from its end data.
    const auto phi = [](double t, int k) {
        switch (k) {
            case 0: return 1 + 2 * t - t * t * t + 0.5 * std::pow(t, 5);
            case 1: return 2 - 3 * t * t + 2.5 * std::pow(t, 4);
            default: return -6 * t + 10 * t * t * t;
        }
    };
    for (double t : {0.1, 0.37, 0.8}) {
        double v = 0;
        for (int i = 0; i <= 2; ++i) v += phi(0, i) * b.p(i, t) + phi(1, i) * b.q(i, t);
        EXPECT_NEAR(v, phi(t, 0), 1e-14);
    }
    EXPECT_EQ(b.p(0, 0.3, 6), 0.0) << "derivatives above 2m+1 vanish";
}

TEST(HosakaBasis, BadIndicesAreRejected) {
    EXPECT_THROW(spline::hosaka_p(-1, 0), InvalidInput);
    EXPECT_THROW(spline::hosaka_q(2, 3), InvalidInput);
    EXPECT_THROW(spline::HosakaBasis(-2), InvalidInput);
    const spline::HosakaBasis b(1);
    EXPECT_THROW(b.p(2, 0.5), InvalidInput);
    EXPECT_THROW(b.q(0, 0.5, -1), InvalidInput);
}

TEST(HosakaSpline, ChordScaleIsTheChordLengthCubicSplineAndUnitScaleTheUniformOne) {
    const cagd::PointList p = uneven_points();
    for (bool closed : {false, true}) {
        spline::HosakaSplineOptions o;
        o.closed = closed;
        const auto chord = spline::hosaka_c2_spline(p, o);
        EXPECT_LT(analysis::max_distance_same_parameter(
                      chord.curve, spline::cubic_spline_interpolant(p, spline::ParameterSpacing::chord_length, closed)),
                  1e-12);
        o.scale = spline::HosakaScale::unit;
        const auto unit = spline::hosaka_c2_spline(p, o);
        EXPECT_LT(analysis::max_distance_same_parameter(
                      unit.curve, spline::cubic_spline_interpolant(p, spline::ParameterSpacing::uniform, closed)),
                  1e-12);
    }
}

TEST(HosakaSpline, JoinsSatisfyEq18WithTheErratumAndEndsHaveZeroCurvature) {
    const cagd::PointList p = uneven_points();
    const auto s = spline::hosaka_c2_spline(p);
    for (int j = 0; j + 1 < s.curve.segments(); ++j) {
        const Eigen::MatrixXd right = s.curve.jet(j + 1, 2);
        const double kj = s.k[static_cast<std::size_t>(j)];
        EXPECT_NEAR(kj, (p.row(j + 1) - p.row(j)).norm() / (p.row(j + 2) - p.row(j + 1)).norm(), 1e-15) << "eq (19)";
        EXPECT_NEAR((s.curve.jet(j + 0.999999999999, 2).row(1) - kj * right.row(1)).norm(), 0.0, 1e-9)
            << "R_i'(1) = k_i R_{i+1}'(0)";
        EXPECT_NEAR((s.C.row(j) - kj * right.row(1)).norm(), 0.0, 1e-12);
        // Second derivatives from the segment's own end data (exact end values of the basis).
        const Eigen::RowVectorXd r2_end = -6 * (p.row(j + 1) - p.row(j)) + 2 * s.B.row(j) + 4 * s.C.row(j);
        const Eigen::RowVectorXd r2_start = 6 * (p.row(j + 2) - p.row(j + 1)) - 4 * s.B.row(j + 1) - 2 * s.C.row(j + 1);
        EXPECT_NEAR((r2_end - kj * kj * r2_start).norm(), 0.0, 1e-11) << "R_i''(1) = k_i² R_{i+1}''(0)";
    }
    EXPECT_NEAR(s.curve.jet(0, 2).row(2).norm(), 0.0, 1e-12) << "natural start";
    EXPECT_NEAR(s.curve.jet(s.curve.segments(), 2).row(2).norm(), 0.0, 1e-12) << "natural end";
}

TEST(HosakaSpline, TangentEndsSpaceCurvesAndBadInput) {
    cagd::PointList p(4, 3);
    p << 0, 0, 0, 1, 1, 0, 2, 1, 1, 3, 0, 2;
    spline::HosakaSplineOptions o;
    o.end = spline::HosakaEnd::tangent;
    o.start_tangent = Eigen::Vector3d(1, 0, 0);
    o.end_tangent = Eigen::Vector3d(0, 0, 1);
    const auto s = spline::hosaka_c2_spline(p, o);
    EXPECT_NEAR((s.curve.jet(0, 1).row(1) - Eigen::RowVector3d(1, 0, 0)).norm(), 0.0, 1e-13);
    EXPECT_NEAR((s.curve.jet(3, 1).row(1) - Eigen::RowVector3d(0, 0, 1)).norm(), 0.0, 1e-13);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR((s.curve.point(i).transpose() - p.row(i)).norm(), 0.0, 1e-14);
    cagd::PointList two(2, 2);
    two << 0, 0, 1, 1;
    EXPECT_NEAR(spline::hosaka_c2_spline(two).curve.point(0.5).y(), 0.5, 1e-15) << "two points: the chord";
    cagd::PointList dup(3, 2);
    dup << 0, 0, 1, 1, 1, 1;
    EXPECT_THROW(spline::hosaka_c2_spline(dup), InvalidInput) << "zero-length chord: k undefined";
    EXPECT_THROW(spline::hosaka_c2_spline(two.topRows(1)), InvalidInput);
    o.end_tangent = Eigen::Vector2d(0, 1);
    EXPECT_THROW(spline::hosaka_c2_spline(p, o), InvalidInput) << "tangent of the wrong dimension";
    spline::HosakaSplineOptions closed;
    closed.closed = true;
    EXPECT_THROW(spline::hosaka_c2_spline(two, closed), InvalidInput) << "closed needs 3 points";
}

TEST(HosakaExplicit, InterpolatesIsC2WithNaturalEndsAndRejectsBadAbscissae) {
    const std::vector<double> x{0, 0.4, 1.5, 2.2, 4.0};
    Eigen::MatrixXd y(5, 1);
    y << 1, -0.5, 0.25, 2, 0;
    const auto s = spline::hosaka_explicit_spline(x, y);
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(s.evaluate(x[static_cast<std::size_t>(i)])(0), y(i, 0), 1e-14);
    for (int i = 1; i < 4; ++i)
        for (int k : {1, 2})
            EXPECT_NEAR(s.evaluate_in(i - 1, 1.0, k)(0), s.evaluate_in(i, 0.0, k)(0), 1e-12)
                << "C" << k << " at x_" << i;
    EXPECT_NEAR(s.evaluate(0.0, 2)(0), 0.0, 1e-12);
    EXPECT_NEAR(s.evaluate(4.0, 2)(0), 0.0, 1e-12);
    // A straight line is reproduced and has zero energy.
    Eigen::MatrixXd line(5, 1);
    for (int i = 0; i < 5; ++i) line(i, 0) = 2 * x[static_cast<std::size_t>(i)] - 1;
    EXPECT_NEAR(spline::hosaka_explicit_spline(x, line).bending_energy(), 0.0, 1e-24);
    EXPECT_THROW(spline::hosaka_explicit_spline({0, 1, 1, 2, 3}, y), InvalidInput) << "repeated abscissa";
    EXPECT_THROW(spline::hosaka_explicit_spline({0, 2, 1, 3, 4}, y), InvalidInput) << "unsorted";
    EXPECT_THROW(spline::hosaka_explicit_spline({0, 1, 2}, y), InvalidInput) << "row count";
    EXPECT_THROW(s.evaluate(4.5), InvalidInput);
}

TEST(HosakaSpline, OrderMSplineIsContinuousTo2mAndReducesToEq20ForM1) {
    const cagd::PointList p = uneven_points();
    EXPECT_LT(analysis::max_distance_same_parameter(spline::hosaka_spline(p, 1).curve.value(),
                                                    spline::hosaka_c2_spline(p).curve),
              1e-12);
    spline::HosakaSplineOptions closed;
    closed.closed = true;
    EXPECT_LT(analysis::max_distance_same_parameter(
                  spline::hosaka_spline(p, 1, spline::HosakaScale::chord, true).curve.value(),
                  spline::hosaka_c2_spline(p, closed).curve),
              1e-12);
    const spline::HosakaCurve c = spline::hosaka_spline(p, 2, spline::HosakaScale::unit).curve.value();
    for (int s = 1; s < c.segments(); ++s)
        for (int k = 1; k <= 4; ++k) {  // unit scale: τ = u, so t-derivatives must match directly
            const spline::HosakaBasis b(2);
            Eigen::RowVectorXd left = Eigen::RowVectorXd::Zero(2);
            for (int i = 0; i <= 2; ++i)
                left += b.p(i, 1.0, k) * c.start_derivatives(s - 1).row(i) +
                        b.q(i, 1.0, k) * c.end_derivatives(s - 1).row(i);
            const Eigen::RowVectorXd right = c.jet(s, k).row(k);
            EXPECT_NEAR((left - right).norm(), 0.0, 1e-9 * (1 + right.norm())) << "order " << k << " at join " << s;
        }
    EXPECT_THROW(spline::hosaka_spline(p, 0), InvalidInput);
}

TEST(HosakaSpline, TangentEndsForAnyOrder) {
    PointList p(5, 2);
    p << 0, 0, 1, 0.8, 1.2, 2.0, 3.0, 1.5, 3.5, 0.2;
    spline::HosakaSplineOptions o;
    o.end = spline::HosakaEnd::tangent;
    o.start_tangent = Eigen::Vector2d(0.5, 1.0);
    o.end_tangent = Eigen::Vector2d(1.0, -2.0);
    // m = 1: the clamped spline of eq (20).
    EXPECT_LT(analysis::max_distance_same_parameter(spline::hosaka_spline(p, 1, o).curve.value(),
                                                    spline::hosaka_c2_spline(p, o).curve),
              1e-12);
    const spline::HosakaCurve c = spline::hosaka_spline(p, 2, o).curve.value();
    const int last = c.segments() - 1;
    EXPECT_LT((c.segment_jet(0, 0.0, 1).row(1).transpose() - o.start_tangent).norm(), 1e-12);
    EXPECT_LT((c.segment_jet(last, 1.0, 1).row(1).transpose() - o.end_tangent).norm(), 1e-12);
    EXPECT_LT(c.segment_jet(0, 0.0, 3).row(3).norm(),
              1e-9 * c.segment_jet(0, 0.5, 3).row(3).norm() + 1e-9);  // order m+1 = 3 vanishes
    EXPECT_GT(c.segment_jet(0, 0.0, 4).row(4).norm(), 1e-3);          // order 2m does not
    // Differs from the natural m = 2 spline, and bad tangents are rejected.
    EXPECT_GT(analysis::max_distance_same_parameter(c, spline::hosaka_spline(p, 2).curve.value()), 1e-3);
    o.end_tangent = Eigen::Vector3d(1, 0, 0);
    EXPECT_THROW(spline::hosaka_spline(p, 2, o), InvalidInput);
}

// jet_into and derivatives_into take a row's basis values at once (HosakaBasis::values) and sums scalars; it must give
// jet()'s values bit for bit (the same products and sums in the same order), for m = 1..3, planar
// and space, every order up to the capacity, and values() must be p() and q().
TEST(HosakaSpline, JetIntoIsTheJetBitForBit) {
    for (const int m : {1, 2, 3}) {
        const spline::HosakaBasis b(m);
        std::vector<double> p(static_cast<std::size_t>(m) + 1), q(p.size());
        for (const double t : {0.0, 0.3, 1.0})
            for (int k = 0; k <= 2 * m + 3; ++k) {
                b.values(t, k, p.data(), q.data());
                for (int i = 0; i <= m; ++i) {
                    EXPECT_EQ(p[static_cast<std::size_t>(i)], b.p(i, t, k)) << "m " << m << ", i " << i << ", k " << k;
                    EXPECT_EQ(q[static_cast<std::size_t>(i)], b.q(i, t, k)) << "m " << m << ", i " << i << ", k " << k;
                }
            }
        EXPECT_THROW(b.values(0.5, -1, p.data(), q.data()), InvalidInput);
        for (const int dim : {2, 3}) {
            std::mt19937 rng(static_cast<unsigned>(10 * m + dim));
            std::uniform_real_distribution<double> u(-2.0, 2.0);
            PointList pts(7, dim);
            for (Eigen::Index r = 0; r < pts.rows(); ++r)
                for (int c = 0; c < dim; ++c) pts(r, c) = u(rng) + 3.0 * static_cast<double>(r);
            const spline::HosakaCurve curve = spline::hosaka_spline(pts, m).curve.value();
            JetMatrix J;
            for (int step = 0; step <= 60; ++step) {
                const double x = curve.t_max() * step / 60.0;
                for (int order = 0; order < kJetCapacity; ++order) {
                    curve.jet_into(x, order, J);
                    const Eigen::MatrixXd expected = curve.jet(x, order);
                    ASSERT_EQ(J.rows(), expected.rows());
                    for (Eigen::Index r = 0; r < J.rows(); ++r)
                        for (int c = 0; c < dim; ++c)
                            EXPECT_EQ(J(r, c), expected(r, c)) << "m " << m << ", u " << x << ", row " << r;
                }
                for (int order = 1; order <= kJetCapacity; ++order) {  // derivatives_into: the jet without its position
                    curve.derivatives_into(x, order, J);
                    const Eigen::MatrixXd expected = curve.jet(x, order).bottomRows(order);
                    ASSERT_EQ(J.rows(), expected.rows());
                    for (Eigen::Index r = 0; r < J.rows(); ++r)
                        for (int c = 0; c < dim; ++c)
                            EXPECT_EQ(J(r, c), expected(r, c)) << "m " << m << ", u " << x << ", derivative " << r + 1;
                }
            }
        }
    }
}

// On points validated already (ValidPoints) the C2 spline (m = 1) and the higher ones are the
// PointList constructions bit for bit; validated open, a closed construction checks them itself.
TEST(HosakaSpline, ValidatedPointsGiveTheSameCurves) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    PointList p(60, 2);
    for (Eigen::Index i = 0; i < p.rows(); ++i) p(i, 0) = static_cast<double>(i) + 0.3 * u(rng), p(i, 1) = u(rng);
    for (const bool closed : {false, true}) {
        spline::HosakaSplineOptions o;
        o.closed = closed;
        const ValidPoints valid = validate_points(p, 3, closed, "test");
        const spline::HosakaCurve c2 = spline::hosaka_c2_spline(valid, o).curve,
                                  c2_list = spline::hosaka_c2_spline(p, o).curve;
        const spline::HosakaCurve c3 = spline::hosaka_spline(valid, 3, o).curve.value(),
                                  c3_list = spline::hosaka_spline(p, 3, o).curve.value();
        JetMatrix a, b;
        for (double t = 0.0; t <= c2.t_max(); t += 0.37) {
            c2.jet_into(t, 2, a);
            c2_list.jet_into(t, 2, b);
            EXPECT_TRUE(a == b) << (closed ? "closed" : "open") << " m = 1, u = " << t;
            c3.jet_into(t, 2, a);
            c3_list.jet_into(t, 2, b);
            EXPECT_TRUE(a == b) << (closed ? "closed" : "open") << " m = 3, u = " << t;
        }
    }
    PointList q = p.topRows(6);
    q.row(5) = q.row(0);
    spline::HosakaSplineOptions closed_options;
    closed_options.closed = true;
    EXPECT_THROW((void)spline::hosaka_c2_spline(validate_points(q, 3, false, "test"), closed_options), InvalidInput)
        << "last = first: no closing chord";
    EXPECT_THROW((void)spline::hosaka_spline(validate_points(q, 3, false, "test"), 3, closed_options), InvalidInput)
        << "last = first: no closing chord";
}

TEST(HosakaSpline, SpanLengthsAreTheChordsAndGiveEq19BitForBit) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const int dim : {2, 3}) {
        PointList p(40, dim);
        for (Eigen::Index i = 0; i < p.rows(); ++i)
            for (int c = 0; c < dim; ++c) p(i, c) = (c == 0 ? static_cast<double>(i) : 0.0) + u(rng);
        for (const bool closed : {false, true}) {
            spline::HosakaSplineOptions o;
            o.closed = closed;
            const spline::HosakaSpline s = spline::hosaka_c2_spline(p, o);
            const std::vector<double> chords = chord_lengths(p, closed);
            EXPECT_EQ(s.span_lengths, chords) << dim << "-D, " << (closed ? "closed" : "open");
            const Eigen::Index n = static_cast<Eigen::Index>(chords.size());
            ASSERT_EQ(s.k.size(), static_cast<std::size_t>(closed ? n : n - 1));
            for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(s.k.size()); ++i) {
                // eq (19) with |A_i| formed as a row's norm, as the construction formed it before
                // it kept the lengths: the same bits.
                const Eigen::Index a = (i + 1) % p.rows(), b = (i + 2) % p.rows();
                const double ratio = (p.row(a) - p.row(i)).norm() / (p.row(b) - p.row(a)).norm();
                EXPECT_EQ(s.k[static_cast<std::size_t>(i)], ratio) << dim << "-D, join " << i;
            }
            o.scale = spline::HosakaScale::unit;
            EXPECT_EQ(spline::hosaka_c2_spline(p, o).span_lengths, std::vector<double>(chords.size(), 1.0));
        }
    }
}

// The τ-derivatives are solved in units of the mean chord's power of 2: the same curve, scaled, from
// 1e-150 to 1e150 at every order (at 1e60 and m = 3 the system was "singular": entries 1e60^-5),
// and a numerical outcome, not an exception, where the system is singular in double precision.
TEST(HosakaSpline, TheSameCurveAtEveryScaleAndASingularSystemIsAnOutcome) {
    const PointList p = test::kNewberyGarrett;
    // m = 6 is solved at every scale too, but its system is ill-conditioned: curves at two scales
    // (two λ) differ by up to 8e-4 here, the rounding of a badly conditioned solve; only m ≤ 3 is
    // held to rounding.
    for (int m : {2, 3, 6}) {
        const spline::HosakaCurve unit = spline::hosaka_spline(p, m).curve.value();
        for (double s : {1e-150, 1e-60, 1e60, 1e150}) {
            const spline::HosakaSplineFit f = spline::hosaka_spline(PointList(s * p), m);
            ASSERT_TRUE(f.outcome.ok()) << "m = " << m << ", scale " << s << ": " << f.outcome.message;
            ASSERT_TRUE(f.curve->point(1.5).allFinite());
            if (m == 6) continue;
            for (double u = 0.0; u <= unit.t_max(); u += 0.25)
                EXPECT_LE((f.curve->point(u) / s - unit.point(u)).norm(), 1e-12 * 10)
                    << "m = " << m << ", scale " << s << ", u = " << u;
        }
    }
    PointList wild(12, 2);
    double x = 0.0;
    for (int i = 0; i < 12; ++i) {
        x += std::pow(10.0, i % 2 == 0 ? -6.0 : 6.0);
        wild.row(i) << x, i % 3 == 0 ? 1.0 : -1.0;
    }
    const spline::HosakaSplineFit f = spline::hosaka_spline(wild, 30);
    EXPECT_FALSE(f.outcome.ok());
    EXPECT_FALSE(f.curve.has_value());
    EXPECT_NE(f.outcome.message.find("order m = 30"), std::string::npos) << f.outcome.message;
}
