// S-/B2-spline interpolants (sb2_locality): defining equations first.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/locality/locality_spline.hpp"

using namespace cagd;
using namespace cagd::locality;

namespace {

PointList random_points(int n, unsigned seed, int dim = 2) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> step(0.5, 1.5), wiggle(-1.0, 1.0);
    PointList p(n, dim);
    for (int i = 0; i < n; ++i) {
        p(i, 0) = i == 0 ? 0.0 : p(i - 1, 0) + step(rng);
        for (int k = 1; k < dim; ++k) p(i, k) = wiggle(rng);
    }
    return p;
}

const SplineForm kForms[] = {SplineForm::b2_spline, SplineForm::s_spline};

}  // namespace

TEST(Locality, PrintedBasisPolynomialsAreTheBSplineBasis) {
    // eq (4): e(t/2) = t³/2 − t² + 2/3 ; eq (8): ê(t) = −3/2 t⁴ + 4t³ − 3t² + 1/2,
    // f̂(t) = 5/2 t⁴ − 5t³ + 3/2 t² + t + 1/4, 0 ≤ t ≤ 1.
    for (int k = 0; k <= 16; ++k) {
        const double t = k / 16.0;
        EXPECT_NEAR(basis_e(t / 2), t * t * t / 2 - t * t + 2.0 / 3.0, 1e-15);
        EXPECT_NEAR(basis_e(t / 2 - 1), t * t * t / 6, 1e-15);
        EXPECT_NEAR(basis_e_hat(t), -1.5 * std::pow(t, 4) + 4 * t * t * t - 3 * t * t + 0.5, 1e-15);
        EXPECT_NEAR(basis_f_hat(t), 2.5 * std::pow(t, 4) - 5 * t * t * t + 1.5 * t * t + t + 0.25, 1e-15);
        EXPECT_NEAR(basis_f_hat(t + 1), std::pow(1 - t, 4) / 4, 1e-15);
    }
}

TEST(Locality, KnotRelationsAreEq3AndEq7) {
    EXPECT_NEAR(knot_relation(SplineForm::b2_spline).side, 1.0 / 6.0, 1e-15);
    EXPECT_NEAR(knot_relation(SplineForm::b2_spline).centre, 4.0 / 6.0, 1e-15);
    EXPECT_NEAR(knot_relation(SplineForm::s_spline).side, 1.0 / 4.0, 1e-15);
    EXPECT_NEAR(knot_relation(SplineForm::s_spline).centre, 2.0 / 4.0, 1e-15);
}

TEST(Locality, InterpolatesEveryPointForEveryFormEndAndM) {
    const PointList p = random_points(9, 11);
    for (SplineForm f : kForms)
        for (int m : {0, 1, 2, 5, 30})
            for (EndKind e : {EndKind::natural, EndKind::bessel})
                for (bool closed : {false, true}) {
                    Options o;
                    o.form = f;
                    o.m = {{m, m}};
                    o.start.kind = o.end.kind = e;
                    o.closed = closed;
                    const auto s = interpolate(p, o);
                    for (Eigen::Index i = 0; i < p.rows(); ++i)
                        EXPECT_LT((s.curve.point(double(i)) - p.row(i).transpose()).norm(), 1e-13)
                            << "r(" << i << ") = p_" << i << ", m = " << m;
                    if (closed) {
                        EXPECT_LT((s.curve.point(double(p.rows())) - p.row(0).transpose()).norm(), 1e-13);
                    }
                }
}

TEST(Locality, CurveIsC2AtTheNodesAndClosedCurvesCloseC2) {
    const PointList p = random_points(7, 12);
    for (SplineForm f : kForms) {
        Options o;
        o.form = f;
        o.closed = true;
        const auto c = interpolate(p, o).curve;
        const double h = 1e-6;
        for (int i = 1; i < 7; ++i) {
            const Eigen::MatrixXd a = c.jet(i - h, 2), b = c.jet(i + h, 2);
            EXPECT_LT((a.row(2) - b.row(2)).norm(), 1e-4) << "r'' continuous at u = " << i;
        }
        EXPECT_LT((c.jet(0.0, 2) - c.jet(7.0, 2)).norm(), 1e-11) << "closed: r, r', r'' equal at both ends";
    }
}

TEST(Locality, MZeroIsMethodIAndLargeMIsTheCubicInterpolant) {
    const PointList p = random_points(12, 13);
    for (SplineForm f : kForms) {
        Options a, b;
        a.form = b.form = f;
        a.m = {{0, 0}};
        b.rule = ExtraPointRule::method_I;
        EXPECT_LT(analysis::max_distance_same_parameter(interpolate(p, a).curve, interpolate(p, b).curve), 1e-15);
        a.m = {{60, 60}};
        EXPECT_LT(analysis::max_distance_same_parameter(interpolate(p, a).curve, cubic_bspline_interpolant(p, false)),
                  1e-13);
        a.closed = true;
        EXPECT_LT(analysis::max_distance_same_parameter(interpolate(p, a).curve, cubic_bspline_interpolant(p, true)),
                  1e-13);
    }
}

TEST(Locality, EndConditionsKeepTheirPromises) {
    const PointList p = random_points(8, 14);
    for (SplineForm f : kForms)
        for (int m : {0, 1, 3}) {
            Options o;
            o.form = f;
            o.m = {{m, m}};
            const auto natural = interpolate(p, o).curve;
            EXPECT_NEAR(analysis::curvature(natural, 0.0), 0.0, 1e-12) << "natural end: κ = 0";
            EXPECT_NEAR(analysis::curvature(natural, 7.0), 0.0, 1e-12);
            o.start.kind = o.end.kind = EndKind::tangent;
            o.start.tangent = Eigen::Vector2d(1.0, 2.0);
            o.end.tangent = Eigen::Vector2d(1.0, -1.0);
            const auto tangent = interpolate(p, o).curve;
            const Eigen::RowVectorXd d0 = tangent.jet(0.0, 1).row(1), d1 = tangent.jet(7.0, 1).row(1);
            EXPECT_NEAR(d0(0) * 2.0 - d0(1) * 1.0, 0.0, 1e-12 * d0.norm()) << "r'(0) ∥ (1, 2)";
            EXPECT_NEAR(d1(0) * -1.0 - d1(1) * 1.0, 0.0, 1e-12 * d1.norm()) << "r'(end) ∥ (1, −1)";
            o.start.kind = o.end.kind = EndKind::bessel;
            const auto bessel = interpolate(p, o).curve;
            const Eigen::VectorXd tb = bessel_tangent(p);
            const Eigen::RowVectorXd db = bessel.jet(0.0, 1).row(1);
            EXPECT_NEAR(db(0) * tb(1) - db(1) * tb(0), 0.0, 1e-12 * db.norm() * tb.norm());
        }
}

TEST(Locality, TruncationWeightsClosedFormEqualsStencil) {
    for (int m = 1; m <= 12; ++m) {
        const auto s = truncation_weights_by_stencil(m);
        EXPECT_LT((s.weights - truncation_weights(m)).norm(), 1e-15) << "eq (13), m = " << m;
        EXPECT_LT(s.largest_other, 1e-15);
    }
}

TEST(Locality, Eq14ExtraPointsOfTheBlendingFunction) {
    // p_i = δ_{i0}: d_{2i+1} = d_{−2i−1} = (1−α)/(1−α^{m+1}) α^i / 2, i = 0..m; zero beyond.
    const int m = 3, half = m + 3;
    PointList p = PointList::Zero(2 * half + 1, 2);  // x = i, y = δ_{i0}
    for (int i = 0; i <= 2 * half; ++i) p(i, 0) = i - half;
    p(half, 1) = 1.0;
    Options o;
    o.m = {{m, m}};
    const auto s = interpolate(p, o);
    const double a = alpha(), K = (1 - a) / (1 - std::pow(a, m + 1));
    for (int i = 0; i <= m + 1; ++i) {
        const double expect = i <= m ? K * std::pow(a, i) / 2 : 0.0;
        EXPECT_NEAR(s.extra_points(half + i + 1, 1), expect, 4e-16) << "d_{2i+1}, i = " << i;
        EXPECT_NEAR(s.extra_points(half - i - 1 + 1, 1), expect, 4e-16) << "d_{-2i-1}, i = " << i;
    }
}

TEST(Locality, StraightLinesAndAffineMapsAreReproduced) {
    PointList line(6, 2);
    for (int i = 0; i < 6; ++i) line.row(i) << 2.0 * i + 1.0, -1.0 * i;
    Options o;
    o.m = {{1, 1}};
    const auto c = interpolate(line, o).curve;
    for (double u = 0; u <= 5; u += 0.125) EXPECT_NEAR(c.point(u)(0) + 2 * c.point(u)(1), 1.0, 1e-13);
    const PointList p = random_points(7, 15);
    Eigen::Matrix2d A;
    A << 0.3, -1.2, 0.8, 0.5;
    const Eigen::RowVector2d shift(3.0, -4.0);
    const PointList q = (p * A.transpose()).rowwise() + shift;
    for (SplineForm f : kForms) {
        o.form = f;
        o.m = {{2, 2}};
        const auto cp = interpolate(p, o).curve, cq = interpolate(q, o).curve;
        for (double u = 0; u <= 6; u += 0.1)
            EXPECT_LT((A * cp.point(u) + shift.transpose() - cq.point(u)).norm(), 1e-12);
    }
}

TEST(Locality, MVectorChangesOnlyNearbySpans) {
    const PointList p = random_points(12, 16);
    Options a, b;
    a.m = parse_m_vector("1,1,1,1,1,1,1,1,1,1,1");
    b.m = a.m;
    b.m[5] = {3, 3};  // segment 5 changes: its extra point moves → spans 4, 5, 6 move
    const auto ca = interpolate(p, a).curve, cb = interpolate(p, b).curve;
    for (int s = 0; s < 11; ++s) {
        const double d = analysis::max_distance_same_parameter(ca, cb, s, s + 1, 65);
        if (s >= 4 && s <= 6) {
            EXPECT_GT(d, 1e-6) << "span " << s;
        } else {
            EXPECT_EQ(d, 0.0) << "span " << s;
        }
    }
}

TEST(Locality, ParsesAndFormatsMVectors) {
    const MVector m = parse_m_vector("{1, 2, 0:3, 4}");
    ASSERT_EQ(m.size(), 4u);
    EXPECT_EQ(m[2].left, 0);
    EXPECT_EQ(m[2].right, 3);
    EXPECT_EQ(format_m_vector(m), "1,2,0:3,4");
    EXPECT_EQ(format_m_vector(parse_m_vector(format_m_vector(m))), "1,2,0:3,4");
}

TEST(Locality, BadInputThrowsNamingTheValue) {
    const PointList p = random_points(5, 17);
    Options o;
    const auto expect_message = [&](const PointList& pts, const Options& opt, const std::string& part) {
        try {
            interpolate(pts, opt);
            ADD_FAILURE() << "no exception; expected one mentioning '" << part << "'";
        } catch (const InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    expect_message(p.topRows(1), o, "at least 2 points");
    PointList bad = p;
    bad(2, 1) = NAN;
    expect_message(bad, o, "point 3 (row 2) coordinate y is nan");
    bad(2, 1) = INFINITY;
    expect_message(bad, o, "inf");
    bad = p;
    bad.row(3) = bad.row(2);
    expect_message(bad, o, "point 3 (row 2) and point 4 (row 3) coincide");
    o.m = {{-1, -1}};
    expect_message(p, o, "m = -1");
    o.m = parse_m_vector("1,2,3");
    expect_message(p, o, "m-vector has 3 entries");
    o.m = {{1, 1}};
    o.start.kind = EndKind::tangent;
    o.start.tangent = Eigen::Vector2d::Zero();
    expect_message(p, o, "tangent must be finite and non-zero");
    EXPECT_THROW(parse_m_vector("1,x,2"), InvalidInput);
    EXPECT_THROW(parse_m_vector("1,-2"), InvalidInput);
    EXPECT_THROW(parse_m_vector(""), InvalidInput);
}

TEST(Locality, ExtendedPointsFollowSection33) {
    const PointList p = random_points(5, 18);
    Options o;  // natural: p_{−k} = 2p_0 − p_k, p_{n−1+k} = 2p_{n−1} − p_{n−1−k}
    EXPECT_LT((extended_point(p, o, -2) - (2 * p.row(0) - p.row(2))).norm(), 1e-15);
    EXPECT_LT((extended_point(p, o, 6) - (2 * p.row(4) - p.row(2))).norm(), 1e-15);
    EXPECT_EQ((extended_point(p, o, 3) - p.row(3)).norm(), 0.0);
    o.start.kind = EndKind::tangent;  // mirror ⟂ (1, 0) through p_0: x reflected, y kept
    o.start.tangent = Eigen::Vector2d(1.0, 0.0);
    const Eigen::RowVectorXd v = extended_point(p, o, -1);
    EXPECT_NEAR(v(0), 2 * p(0, 0) - p(1, 0), 1e-15);
    EXPECT_NEAR(v(1), p(1, 1), 1e-15);
    o = Options{};
    o.closed = true;
    EXPECT_EQ((extended_point(p, o, -1) - p.row(4)).norm(), 0.0);
    EXPECT_EQ((extended_point(p, o, 7) - p.row(2)).norm(), 0.0);
}

// Eq (12) with one m for every segment: each extra point is the weighted sum of the extended points
// of section 3.3, the interior ones (summed coordinate by coordinate) and those near the ends alike,
// to the last bit; for m = 0 … 7, both forms, open (natural and Bessel ends) and closed, in 2-D and 3-D.
TEST(Locality, ExtraPointsAreEq12SumsOfTheExtendedPoints) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
    for (const int dim : {2, 3})
        for (const bool closed : {false, true})
            for (const SplineForm form : {SplineForm::s_spline, SplineForm::b2_spline})
                for (const int m : {0, 1, 2, 4, 7})
                    for (const EndKind end : {EndKind::natural, EndKind::bessel}) {
                        if (closed && end != EndKind::natural) continue;
                        PointList p(40, dim);
                        for (Eigen::Index i = 0; i < p.rows(); ++i)
                            for (Eigen::Index c = 0; c < dim; ++c) p(i, c) = coordinate(rng);
                        Options o;
                        o.form = form;
                        o.m = {{m, m}};
                        o.closed = closed;
                        o.start.kind = o.end.kind = end;
                        const LocalitySpline s = interpolate(p, o);
                        const SegmentWeights w = extra_point_weights({m, m});
                        const long N = closed ? 41 : 40;
                        ASSERT_EQ(s.extra_points.rows(), N + 1);
                        for (long i = -1; i <= N - 1; ++i) {
                            Eigen::RowVectorXd d = Eigen::RowVectorXd::Zero(dim);
                            for (Eigen::Index j = 0; j < w.left.size(); ++j)
                                d += w.left(j) * extended_point(p, o, i - j);
                            for (Eigen::Index j = 0; j < w.right.size(); ++j)
                                d += w.right(j) * extended_point(p, o, i + 1 + j);
                            for (Eigen::Index c = 0; c < dim; ++c)
                                ASSERT_EQ(s.extra_points(i + 1, c), d(c))
                                    << "segment " << i << ", m = " << m << (closed ? ", closed" : ", open") << ", dim "
                                    << dim;
                        }
                    }
}

// On points validated already (ValidPoints) the construction is the PointList one bit for bit;
// validated open, a closed construction checks them itself (the closing chord).
TEST(Locality, ValidatedPointsGiveTheSameCurveAndAreCheckedWhereTheProofFallsShort) {
    for (const SplineForm form : kForms)
        for (const bool closed : {false, true}) {
            const PointList p = random_points(200, 9, 3);
            Options o;
            o.form = form;
            o.closed = closed;
            o.m = {{2, 2}};
            const LocalitySpline a = interpolate(validate_points(p, 3, closed, "test"), o), b = interpolate(p, o);
            EXPECT_EQ(a.curve.knots(), b.curve.knots());
            EXPECT_TRUE(a.curve.control_points() == b.curve.control_points()) << (closed ? "closed" : "open");
        }
    PointList q = random_points(6, 4);
    q.row(5) = q.row(0);
    Options o;
    o.closed = true;
    const ValidPoints open = validate_points(q, 3, false, "test");
    EXPECT_THROW((void)interpolate(open, o), InvalidInput) << "last = first: no closing chord";
}
