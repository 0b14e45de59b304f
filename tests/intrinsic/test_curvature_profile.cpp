// curvature_profile: knot-difference lists, the tangent-angle B-spline, the design equations and
// their Jacobian, Newton with the Moore–Penrose step, outcomes and bad input.
#include <gtest/gtest.h>

#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>

#include "../support/messages.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/random_walk.hpp"
#include "cagd/intrinsic/design_verification.hpp"
#include "cagd/intrinsic/spiro.hpp"
#include "cagd/numeric/banded_lu.hpp"

using namespace cagd;
using namespace cagd::intrinsic;

namespace {

const char* kFig3List =
    "{0, 5.000, 0, 4.018, 0, 3.000, 0, 1.571, 0, 5.000, 0, 5.123, 0, 6.282, 0, 2.500, 0, 1.571, 0, {2.053, 1.806}, "
    "3.430, 2.000, 0}";

PointList fig3_points() {
    PointList p(13, 2);
    p << 9, 1, 4, 1, 1, 3, 1, 6, 2, 7, 7, 7, 10, 3.5, 14, 3.5, 14, 6, 15, 7, 17, 4.2, 20, 3, 22, 3;
    return p;
}

CurvatureProfileProblem fig3_problem() {
    const KnotLayout layout = parse_knot_difference_list(kFig3List, 2).layout;
    return {fig3_points(),
            layout,
            segment_shapes(layout, parse_span_shapes("line,free,line,arc,line,free,arc,line,arc,free,free,line")),
            {},
            false,
            0};
}

CurvatureProfileProblem closed_problem(int degree) {
    PointList p(6, 2);
    p << 0, 0, 4, -1, 7, 1, 6, 5, 2, 6, -1, 3;
    std::vector<int> mult(7, degree - 1), index{0, 1, 2, 3, 4, 5};
    mult.front() = mult.back() = degree;
    const KnotLayout layout(degree, std::vector<int>(6, 1), mult, index);
    return {p,  layout, std::vector<SegmentShape>(6, degree == 3 ? SegmentShape::linear_curvature : SegmentShape::free),
            {}, true,   0};
}

// Spiro's layout (degree 4, simple knots) on the same points: open with κ' = κ'' = 0 at both ends,
// or closed G4.
CurvatureProfileProblem spiro_problem(bool closed) {
    CurvatureProfileProblem P = closed_problem(4);
    P.shapes.assign(6, SegmentShape::free);
    P.layout = KnotLayout(4, std::vector<int>(6, 1), {4, 1, 1, 1, 1, 1, 4}, {0, 1, 2, 3, 4, 5});
    if (closed) {
        P.closing_continuity = 4;
        return P;
    }
    P.closed = false;
    P.points.conservativeResize(7, 2);
    P.points.row(6) << -2, 0.5;
    using K = DesignCondition::Kind;
    for (int order : {1, 2})
        P.conditions.push_back({K::curvature_derivative, 0, 0.0, false, order}),
            P.conditions.push_back({K::curvature_derivative, 6, 0.0, true, order});
    return P;
}

}  // namespace

TEST(KnotDifferenceList, Figure1ExampleStructureAndRoundTrip) {
    const std::string fig1 = "{0, 0, {S0, S0}, 0, S1, {S2, 0, S3}, 0, 0}";
    const KnotDifferenceList l = parse_knot_difference_list(fig1, 3);
    EXPECT_EQ(l.layout.spans(), 3);
    EXPECT_EQ(l.layout.segments(), 5);
    EXPECT_EQ(l.layout.independent_lengths(), 4);  // S0 shared by span 0's two segments
    const std::vector<int> mult{3, 1, 2, 1, 2, 3};
    for (int g = 0; g <= 5; ++g)
        EXPECT_EQ(l.layout.multiplicity(g), mult[static_cast<std::size_t>(g)]) << "breakpoint " << g;
    EXPECT_EQ(l.layout.ordinates(), 12 - 3 + 1);
    EXPECT_EQ(format_knot_difference_list(l.layout), fig1);
    const std::vector<double> lengths{1.25, 1.25, 2.5, 0.75, 3.0};
    const std::string numeric = format_knot_difference_list(l.layout, lengths, 3);
    EXPECT_EQ(numeric, "{0, 0, {1.250, 1.250}, 0, 2.500, {0.750, 0, 3.000}, 0, 0}");
    const KnotDifferenceList back = parse_knot_difference_list(numeric, 3);
    for (int g = 0; g <= 5; ++g) EXPECT_EQ(back.layout.multiplicity(g), l.layout.multiplicity(g));
    EXPECT_EQ(back.layout.independent_lengths(), 5);  // numbers never share a length
    ASSERT_TRUE(back.values[2].has_value());
    EXPECT_DOUBLE_EQ(*back.values[2], 2.5);
}

TEST(KnotDifferenceList, Figure3PrintedListRoundTripsAtDegreeTwo) {
    const KnotDifferenceList l = parse_knot_difference_list(kFig3List, 2);
    EXPECT_EQ(l.layout.spans(), 12);
    EXPECT_EQ(l.layout.segments(), 13);
    EXPECT_EQ(l.layout.ordinates(), 24);
    EXPECT_EQ(l.layout.geometric_continuity(9), 1);   // join ⑨–⑩: one zero = double knot
    EXPECT_EQ(l.layout.geometric_continuity(10), 2);  // inside ⑩: simple knot
    std::vector<double> values;
    for (int j = 0; j < 13; ++j) values.push_back(*l.values[static_cast<std::size_t>(l.layout.length_index(j))]);
    EXPECT_EQ(format_knot_difference_list(l.layout, values, 3), kFig3List);
    // As degree 3 the same text is malformed (ends need two zeros).
    EXPECT_THROW(parse_knot_difference_list(kFig3List, 3), InvalidInput);
    // Elevation raises every multiplicity by one.
    EXPECT_EQ(format_knot_difference_list(l.layout.elevated()).substr(0, 16), "{0, 0, S0, 0, 0,");
}

TEST(KnotDifferenceList, MalformedListsThrow) {
    for (const char* bad : {"", "{}", "{0, 5, 0", "{0, 5, 0} x", "{0, {1, {2}}, 0}", "{0, -1, 0}", "{0, 1, …, 0}",
                            "{0, 1, ..., 0}", "{0, 1, 0, 0, 2, 0}", "{0, {0, 1}, 0}", "{0, {1, 0}, 0}", "{0, 0, 0}",
                            "{1, 2, 0}", "{0, 1, 2}", "{0, 1e999, 0}", "{0, 1; 2, 0}"})
        EXPECT_THROW(parse_knot_difference_list(bad, 2), InvalidInput) << bad;
    EXPECT_THROW(parse_knot_difference_list("{0, 1, 0}", 4), InvalidInput);
    EXPECT_THROW(KnotLayout(2, {1, 1}, {2, 3, 2}, {0, 1}), InvalidInput);  // interior multiplicity > p
    EXPECT_THROW(KnotLayout(2, {1, 1}, {2, 1, 2}, {1, 0}), InvalidInput);  // indices not in order of first use
    const KnotLayout ok(2, {1}, {2, 2}, {0});
    EXPECT_THROW(format_knot_difference_list(ok, {0.0001}, 2), InvalidInput);  // would print as 0
}

// The lengths print as printf's "%.*f" prints them (format_knot_difference_list writes them with
// std::to_chars where the standard library has it), rounding ties included.
TEST(KnotDifferenceList, LengthsPrintAsPrintfFixed) {
    const KnotLayout one(2, {1}, {2, 2}, {0});
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> mantissa(1.0, 10.0);
    std::uniform_int_distribution<int> exponent(-4, 12), digits(0, 17);
    std::vector<std::pair<double, int>> cases{{0.125, 2}, {0.375, 2}, {2.5, 0},     {3.5, 0},
                                              {1e22, 3},  {0.1, 17},  {123456.0, 0}};
    for (int i = 0; i < 2000; ++i) cases.emplace_back(mantissa(rng) * std::pow(10.0, exponent(rng)), digits(rng));
    for (const auto& [v, decimals] : cases) {
        char want[400];
        std::snprintf(want, sizeof want, "%.*f", decimals, v);
        if (std::strtod(want, nullptr) == 0.0) {
            EXPECT_THROW(format_knot_difference_list(one, {v}, decimals), InvalidInput)
                << v << " with " << decimals << " decimals prints as " << want;
            continue;
        }
        EXPECT_EQ(format_knot_difference_list(one, {v}, decimals), std::string("{0, ") + want + ", 0}")
            << full_precision(v) << " with " << decimals << " decimals";
    }
}

TEST(TangentAngleSpline, BezierFormMatchesDeBoorEvaluation) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> len(0.3, 2.0), ord(-2.0, 2.0);
    for (int p = 2; p <= 3; ++p) {
        const KnotLayout layout(p, {2, 1, 2}, {p, 1, p, p - 1, p == 3 ? 2 : 1, p}, {0, 1, 2, 3, 4});
        std::vector<double> lengths;
        for (int j = 0; j < 5; ++j) lengths.push_back(len(rng));
        Eigen::VectorXd c(layout.ordinates());
        for (int i = 0; i < c.size(); ++i) c(i) = ord(rng);
        const TangentAngleSpline psi(layout, lengths, c);
        for (int j = 0; j < 5; ++j)
            for (double t : {0.0, 0.3, 0.71, 1.0}) {
                const double s =
                    psi.breakpoints()[static_cast<std::size_t>(j)] + t * lengths[static_cast<std::size_t>(j)];
                double bez = 0.0;
                for (int r = 0; r <= p; ++r)
                    bez += psi.bezier()(j, r) * std::tgamma(p + 1) / (std::tgamma(r + 1) * std::tgamma(p - r + 1)) *
                           std::pow(t, r) * std::pow(1 - t, p - r);
                EXPECT_NEAR(bez, psi.jet_in_segment(j, s, 0)(0), 1e-13) << "p=" << p << " segment " << j << " t=" << t;
            }
        // Clamped ends interpolate the end ordinates; Greville abscissae start at 0 and end at L.
        EXPECT_NEAR(psi.jet(0.0, 0)(0), c(0), 1e-14);
        EXPECT_NEAR(psi.jet(psi.length(), 0)(0), c(c.size() - 1), 1e-14);
        EXPECT_NEAR(psi.greville_abscissae().back(), psi.length(), 1e-14);
    }
}

TEST(TangentAngleSpline, DirectionIntegralsMatchAdaptiveGaussKronrod) {
    using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
    for (const Eigen::Vector4d& b :
         {Eigen::Vector4d(0, 5, -3, 8), Eigen::Vector4d(1, 1, 1, 1), Eigen::Vector4d(-20, 3, 30, -2)}) {
        auto psi = [&](double t) {
            return b(0) * std::pow(1 - t, 3) + 3 * b(1) * t * (1 - t) * (1 - t) + 3 * b(2) * t * t * (1 - t) +
                   b(3) * t * t * t;
        };
        for (double tau : {1.0, 0.37}) {
            const Eigen::Vector2d I = direction_integrals(b, tau);
            EXPECT_NEAR(
                I(0), GK::integrate([&](double t) { return std::cos(psi(t)) + 2.0; }, 0.0, tau, 15, 1e-15) - 2.0 * tau,
                1e-14)
                << b.transpose();
            EXPECT_NEAR(
                I(1), GK::integrate([&](double t) { return std::sin(psi(t)) + 2.0; }, 0.0, tau, 15, 1e-15) - 2.0 * tau,
                1e-14)
                << b.transpose();
        }
    }
    EXPECT_THROW(direction_integrals(Eigen::Vector4d(0, 1, 2, 3), 1.5), InvalidInput);
}

// Degree 4 (the Spiro layout): the same rule against the same adaptive reference, with ordinates
// that turn by up to 40 rad over the segment.
TEST(TangentAngleSpline, QuarticDirectionIntegralsMatchAdaptiveGaussKronrod) {
    using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
    using Vector5d = Eigen::Matrix<double, 5, 1>;
    for (const Vector5d& b : {Vector5d(0, 5, -3, 8, 1), Vector5d(2, 2, 2, 2, 2), Vector5d(-20, 3, 30, -2, 10),
                              Vector5d(0, 0.1, 0.3, 0.2, -0.1)}) {
        auto psi = [&](double t) {
            const double u = 1 - t;
            return b(0) * u * u * u * u + 4 * b(1) * t * u * u * u + 6 * b(2) * t * t * u * u +
                   4 * b(3) * t * t * t * u + b(4) * t * t * t * t;
        };
        for (double tau : {1.0, 0.37}) {
            const Eigen::Vector2d I = direction_integrals(b, tau);
            EXPECT_NEAR(
                I(0), GK::integrate([&](double t) { return std::cos(psi(t)) + 2.0; }, 0.0, tau, 15, 1e-15) - 2.0 * tau,
                1e-14)
                << b.transpose();
            EXPECT_NEAR(
                I(1), GK::integrate([&](double t) { return std::sin(psi(t)) + 2.0; }, 0.0, tau, 15, 1e-15) - 2.0 * tau,
                1e-14)
                << b.transpose();
        }
    }
    EXPECT_THROW(direction_integrals(Eigen::Matrix<double, 6, 1>::Zero(), 1.0), InvalidInput);
}

// The rule's pieces turn by up to 3 rad: segments whose steepest derivative ordinate is just below
// 3 (one piece) and 6 (two pieces), for every degree, alternating ordinates (the worst case of the
// header's bound), against 30-point Gauss on 64 subintervals (each turning < 0.1 rad: exact to
// rounding) to a few units of rounding.
TEST(TangentAngleSpline, PiecesOfThreeRadiansIntegrateToRounding) {
    using Fine = boost::math::quadrature::gauss<double, 30>;
    for (int p = 2; p <= 4; ++p)
        for (double turning : {2.999, 5.999})
            for (double offset : {0.0, 0.7, -2.1}) {
                Eigen::VectorXd b(p + 1);
                for (int r = 0; r <= p; ++r) b(r) = offset + (r % 2 == 0 ? 0.0 : turning / p);  // |p Δb| = turning
                auto psi = [&](double t) {
                    double v = 0.0;
                    for (int r = 0; r <= p; ++r)
                        v += b(r) * std::tgamma(p + 1) / (std::tgamma(r + 1) * std::tgamma(p - r + 1)) *
                             std::pow(t, r) * std::pow(1 - t, p - r);
                    return v;
                };
                double c = 0.0, s = 0.0;
                for (int m = 0; m < 64; ++m) {
                    c += Fine::integrate([&](double t) { return std::cos(psi(t)); }, m / 64.0, (m + 1) / 64.0);
                    s += Fine::integrate([&](double t) { return std::sin(psi(t)); }, m / 64.0, (m + 1) / 64.0);
                }
                const Eigen::Vector2d I = direction_integrals(b, 1.0);
                EXPECT_NEAR(I(0), c, 1e-15) << "p = " << p << ", turning " << turning << ", offset " << offset;
                EXPECT_NEAR(I(1), s, 1e-15) << "p = " << p << ", turning " << turning << ", offset " << offset;
            }
}

TEST(IntrinsicCurve, JetMatchesFiniteDifferencesOfPosition) {
    const CurvatureProfileProblem P = closed_problem(3);
    const IntrinsicCurve c(Eigen::Vector2d(1, 2), TangentAngleSpline::from_unknowns(P.layout, c2_start(P)));
    const double h = 1e-4;
    for (double s : {0.5, 3.3, 9.1}) {
        const Eigen::MatrixXd j = c.jet(s, 2);
        const Eigen::RowVector2d d1 = (c.jet(s + h, 0).row(0) - c.jet(s - h, 0).row(0)) / (2 * h);
        const Eigen::RowVector2d d2 = (c.jet(s + h, 0).row(0) - 2 * j.row(0) + c.jet(s - h, 0).row(0)) / (h * h);
        EXPECT_NEAR((d1 - j.row(1)).norm(), 0.0, 1e-8) << "r' = (cos ψ, sin ψ) at s = " << s;
        EXPECT_NEAR((d2 - j.row(2)).norm(), 0.0, 1e-5) << "r'' = κ n at s = " << s;
        EXPECT_NEAR(j.row(1).norm(), 1.0, 1e-15) << "arc-length parametrisation";
    }
}

TEST(IntrinsicCurve, DerivativesAreTheJetWithoutItsPosition) {
    const CurvatureProfileProblem P = closed_problem(3);
    const IntrinsicCurve c(Eigen::Vector2d(1, 2), TangentAngleSpline::from_unknowns(P.layout, c2_start(P)));
    for (double s : {0.0, 0.5, 3.3, 9.1, c.length()})
        for (int order = 1; order <= 4; ++order) {
            const Eigen::MatrixXd d = c.derivatives(s, order), j = c.jet(s, order);
            ASSERT_EQ(d.rows(), order);
            EXPECT_EQ(d, j.bottomRows(order)) << "s = " << s << ", order " << order;
        }
    EXPECT_THROW(c.derivatives(1.0, 0), InvalidInput);
    EXPECT_THROW(c.derivatives(-0.1, 1), InvalidInput);
    // The default (a curve that does not override it) slices the jet.
    const Curve& base = c;
    EXPECT_EQ(base.Curve::derivatives(2.0, 3), c.jet(2.0, 3).bottomRows(3));
}

// Positions at a segment's ends come from the stored points, not a fresh quadrature; they must be
// what the quadrature gives, bit for bit: r_j + d_j ∫_0^τ (cos ψ, sin ψ) dt at τ = 0 and τ = 1.
TEST(IntrinsicCurve, PositionsAtTheJoinsAreTheQuadratureBitForBit) {
    const CurvatureProfileProblem P = closed_problem(3);
    const IntrinsicCurve c(Eigen::Vector2d(-0.0, 2), TangentAngleSpline::from_unknowns(P.layout, c2_start(P)));
    const TangentAngleSpline& psi = c.tangent_angle();
    JetMatrix J;
    for (int j = 0; j < psi.segments(); ++j) {
        const double w = psi.breakpoints()[static_cast<std::size_t>(j)],
                     d = psi.segment_lengths()[static_cast<std::size_t>(j)];
        const Eigen::RowVector2d start = c.breakpoint_points().row(j),
                                 quadrature_start =
                                     start + d * direction_integrals(psi.bezier().row(j).transpose(), 0.0).transpose();
        c.jet_into(w, 1, J);  // s = w_j: segment j at τ = 0
        EXPECT_EQ(J(0, 0), quadrature_start(0)) << "segment " << j;
        EXPECT_EQ(J(0, 1), quadrature_start(1)) << "segment " << j;
        EXPECT_EQ(std::signbit(J(0, 0)), std::signbit(quadrature_start(0)))
            << "segment " << j << ": r_j + (+0) is +0 for r_j = −0";
        EXPECT_EQ(c.jet(w, 0).row(0), J.row(0)) << "segment " << j;
        const Eigen::RowVector2d quadrature_end =
            start + d * direction_integrals(psi.bezier().row(j).transpose(), 1.0).transpose();
        if (j + 1 == psi.segments()) {
            c.jet_into(c.length(), 0, J);  // the last segment at τ = (L − w)/d (1 unless it rounds below)
            const double tau = std::min(1.0, std::max(0.0, (c.length() - w) / d));
            EXPECT_EQ(J.row(0), start + d * direction_integrals(psi.bezier().row(j).transpose(), tau).transpose());
        }
        EXPECT_EQ(c.breakpoint_points().row(j + 1), quadrature_end) << "segment " << j;
    }
}

TEST(TangentAngleSpline, LocalKnotsAreTheFarinKnotsShiftedToTheSegmentStart) {
    const CurvatureProfileProblem P = fig3_problem();
    const TangentAngleSpline psi = TangentAngleSpline::from_unknowns(P.layout, c2_start(P));
    const std::vector<double> v = psi.farin_knots();
    const int p = psi.degree();
    for (int j = 0; j < psi.segments(); ++j) {
        const std::vector<double> local = psi.local_farin_knots(j);
        ASSERT_EQ(local.size(), static_cast<std::size_t>(2 * p));
        const int k0 = P.layout.last_knot_of_breakpoint(j) - p + 1;
        for (int m = 0; m < 2 * p; ++m)
            EXPECT_NEAR(local[static_cast<std::size_t>(m)],
                        v[static_cast<std::size_t>(k0 + m)] - psi.breakpoints()[static_cast<std::size_t>(j)], 1e-13)
                << j << " " << m;
    }
}

TEST(CurvatureProfileDesign, LongOpenSplineConvergesToTheTolerance) {
    // 6·10^4 points of a random walk (arc length 3.6·10^4): with absolute knots the knot differences
    // lost ε·w each and Newton settled at ‖f‖∞ = 2.8e-12 > 1e-12 ("no solution"; checked by
    // putting the absolute knots back).
    const PointList p = cagd::random_walk(60000, 1, 0.2, 1.0, 1.2);
    const std::vector<SegmentShape> free(static_cast<std::size_t>(p.rows() - 1), SegmentShape::free);
    const KnotLayout layout = span_layout(free);
    CurvatureProfileProblem problem{p, layout, segment_shapes(layout, free), {}, false, 0};
    add_natural_open_ends(problem);
    const CurvatureProfileSolution sol = solve_curvature_profile_auto(problem);
    ASSERT_TRUE(sol.outcome.ok()) << sol.outcome.message;
    EXPECT_LE(sol.history.back().residual, 1e-12 * 1.0);  // data_scale = max(1, longest chord) = 1
    EXPECT_LE(sol.history.size(), 8u);
}

// Continuation from the solution of nearby points: with one point of 2000 moved by a chord, the
// window around it is solved alone and set into the old solution, and Newton from there stops at
// its first evaluation, on the solution the design's own start reaches (to Newton's tolerance).
// The start changes only in the window's lengths and ordinates; where it does not apply, or the
// points did not move, the start comes back unchanged.
TEST(CurvatureProfileDesign, ContinuationStartSolvesTheWindowAroundAMovedPoint) {
    const auto problem_of = [](const PointList& p, bool closed) {
        const std::vector<SegmentShape> free(static_cast<std::size_t>(p.rows() - (closed ? 0 : 1)), SegmentShape::free);
        const KnotLayout layout = span_layout(free);
        CurvatureProfileProblem problem{p, layout, segment_shapes(layout, free), {}, closed, 0};
        add_natural_open_ends(problem);
        return problem;
    };
    const PointList p = cagd::random_walk(2000, 3, 0.2, 1.0, 1.2);
    const CurvatureProfileProblem before = problem_of(p, false);
    const CurvatureProfileSolution first = solve_curvature_profile_auto(before);
    ASSERT_TRUE(first.outcome.ok()) << first.outcome.message;
    EXPECT_EQ(continuation_start(before, first.u), first.u) << "nothing moved";
    const NewtonOptions continuation{.required_contraction = 0.5};
    for (const int moved : {1000, 3, 1996}) {  // the middle, and windows clipped at either end
        PointList q = p;
        q(moved, 1) += 1.0;
        const CurvatureProfileProblem after = problem_of(q, false);
        const Eigen::VectorXd start = continuation_start(after, first.u, continuation);
        // The window: spans moved − 1 and moved (the moved point's rows) widened by 64 on each side.
        const int n = 1999, a = std::max(0, moved - 1 - kContinuationWindowSpans),
                  b = std::min(n, moved + 1 + kContinuationWindowSpans);
        for (int j = 0; j < n; ++j)
            if (j < a || j >= b) {
                ASSERT_EQ(start(j), first.u(j)) << "length " << j << " outside the window [" << a << ", " << b << ")";
            }
        for (int i = 0; i < n + 2; ++i)
            if (i < a || i > b + 1) {
                ASSERT_EQ(start(n + i), first.u(n + i)) << "ordinate " << i << " outside the window";
            }
        EXPECT_GT((start - first.u).lpNorm<Eigen::Infinity>(), 1e-3) << "the window was re-solved";
        const CurvatureProfileSolution near = solve_curvature_profile_auto(after, start, continuation),
                                       cold = solve_curvature_profile_auto(after);
        ASSERT_TRUE(near.outcome.ok() && cold.outcome.ok()) << near.outcome.message << " / " << cold.outcome.message;
        EXPECT_EQ(near.history.size(), 1u) << "converged at the first evaluation, moved point " << moved;
        EXPECT_LE((near.u - cold.u).lpNorm<Eigen::Infinity>(), 1e-10) << "moved point " << moved;
        // From the old solution itself Newton does not contract (the case this start is for).
        EXPECT_FALSE(solve_curvature_profile_auto(after, first.u, continuation).outcome.ok())
            << "moved point " << moved;
    }
    // Not applicable: points moved far apart (a window over a quarter of the curve), a closed curve,
    // too few spans, a start of another size.
    PointList spread = p;
    spread(200, 1) += 1.0, spread(1800, 1) += 1.0;
    EXPECT_EQ(continuation_start(problem_of(spread, false), first.u), first.u);
    const PointList ring = p.topRows(400);
    const CurvatureProfileProblem closed = problem_of(ring, true);
    const Eigen::VectorXd closed_start = c2_start(closed);
    EXPECT_EQ(continuation_start(closed, closed_start), closed_start);
    const CurvatureProfileProblem short_open = problem_of(p.topRows(200), false);
    const Eigen::VectorXd short_start = c2_start(short_open);
    EXPECT_EQ(continuation_start(short_open, short_start), short_start);
    EXPECT_EQ(continuation_start(before, first.u.head(10)), first.u.head(10));
}

// The defaults' solve takes the Moore–Penrose step up to 64 unknowns (32 open points) and the LU
// step above (rank −1 in the solution), and both reach the same curve.
TEST(CurvatureProfileDesign, AutoTakesTheLuStepAbove64Unknowns) {
    for (const int points : {32, 33, 100}) {
        const PointList p = cagd::random_walk(points, 7, 0.2, 1.0, 1.2);
        const std::vector<SegmentShape> free(static_cast<std::size_t>(p.rows() - 1), SegmentShape::free);
        const KnotLayout layout = span_layout(free);
        CurvatureProfileProblem problem{p, layout, segment_shapes(layout, free), {}, false, 0};
        add_natural_open_ends(problem);
        const CurvatureProfileSolution automatic = solve_curvature_profile_auto(problem),
                                       dense = solve_curvature_profile(problem);
        ASSERT_TRUE(automatic.outcome.ok() && dense.outcome.ok()) << points;
        EXPECT_EQ(automatic.unknowns, 2 * points);
        if (automatic.unknowns > 64)
            EXPECT_EQ(automatic.rank, -1) << points << " points: an LU step";
        else
            EXPECT_EQ(automatic.rank, automatic.unknowns) << points << " points: the Moore–Penrose step, full rank";
        EXPECT_LE((automatic.u - dense.u).lpNorm<Eigen::Infinity>(), 1e-10) << points;
    }
}

TEST(IntrinsicCurve, ProfileSamplesShowOneSidedCurvatureAtJoins) {
    const CurvatureProfileProblem P = fig3_problem();
    const CurvatureProfileSolution sol = solve_curvature_profile(P);
    ASSERT_TRUE(sol.outcome.ok()) << sol.outcome.message;
    const std::vector<ProfileSample> q = curvature_profile_samples(*sol.curve, 4);
    ASSERT_EQ(q.size(), 13u * 5u);
    // Span ③ is a line (κ = 0) and ④ the clockwise quarter circle (κ = −1): both sides of their join.
    EXPECT_EQ(q[14].segment, 2);
    EXPECT_NEAR(q[14].kappa, 0.0, 1e-12);
    EXPECT_EQ(q[15].segment, 3);
    EXPECT_NEAR(q[15].kappa, -1.0, 1e-12);
    EXPECT_DOUBLE_EQ(q[14].s, q[15].s);
    EXPECT_NEAR(q[14].x, 1.0, 1e-12);
    EXPECT_NEAR(q[14].y, 6.0, 1e-12);
    EXPECT_THROW(curvature_profile_samples(*sol.curve, 0), InvalidInput);
}

// segment_offset_bound covers the distance between two curves at equal fractions of a segment,
// at fractions denser than any comparison samples: here the figure-3 design against the same
// design with one tangent-angle ordinate and one length perturbed (from 1e-12 to 1e-2); a curve
// against itself is bounded by the rounding margin alone; other segment counts or degrees throw.
TEST(IntrinsicCurve, SegmentOffsetBoundCoversEveryFraction) {
    const CurvatureProfileProblem P = fig3_problem();
    const CurvatureProfileSolution sol = solve_curvature_profile(P);
    ASSERT_TRUE(sol.outcome.ok()) << sol.outcome.message;
    const IntrinsicCurve& a = *sol.curve;
    const int segments = a.tangent_angle().segments(), l = P.layout.independent_lengths();
    for (double size : {1e-12, 1e-6, 1e-2})
        for (int which = 0; which < 3; ++which) {
            Eigen::VectorXd u = sol.u;
            u(l + (which == 0 ? 0 : P.layout.ordinates() / 2)) += size;  // an ordinate
            if (which == 2) u(l / 2) *= 1.0 + size;                      // and a length
            const IntrinsicCurve b(P.points.row(0).transpose(), TangentAngleSpline::from_unknowns(P.layout, u));
            for (int j = 0; j < segments; ++j) {
                const double bound = a.segment_offset_bound(b, j);
                const double wa = a.breakpoints()[static_cast<std::size_t>(j)],
                             da = a.tangent_angle().segment_lengths()[static_cast<std::size_t>(j)];
                const double wb = b.breakpoints()[static_cast<std::size_t>(j)],
                             db = b.tangent_angle().segment_lengths()[static_cast<std::size_t>(j)];
                for (int q = 0; q <= 64; ++q) {
                    const double f = q / 64.0;
                    const double distance =
                        (a.jet(f == 1.0 ? wa + da : wa + f * da, 0) - b.jet(f == 1.0 ? wb + db : wb + f * db, 0))
                            .norm();
                    ASSERT_LE(distance, bound)
                        << "perturbation " << size << " (" << which << "), segment " << j << ", fraction " << f;
                }
            }
        }
    for (int j = 0; j < segments; ++j) {
        const double scale = a.breakpoint_points().row(j).cwiseAbs().maxCoeff() +
                             2.0 * a.tangent_angle().segment_lengths()[static_cast<std::size_t>(j)] *
                                 (1.0 + a.tangent_angle().bezier().row(j).cwiseAbs().maxCoeff());
        EXPECT_LE(a.segment_offset_bound(a, j), 3e-13 * scale)
            << "segment " << j << ": a curve does not move from itself";
    }
    EXPECT_THROW(a.segment_offset_bound(a, segments), InvalidInput);
    EXPECT_THROW(a.segment_offset_bound(a, -1), InvalidInput);
}

TEST(CurvatureProfileDesign, JacobianMatchesCentralDifferences) {
    CurvatureProfileProblem cubic = closed_problem(3);
    cubic.closed = false;
    cubic.points.conservativeResize(5, 2);
    cubic.layout = KnotLayout(3, {2, 1, 1, 1}, {3, 1, 2, 3, 2, 3}, {0, 0, 1, 2, 3});
    cubic.shapes = {SegmentShape::free, SegmentShape::arc, SegmentShape::linear_curvature, SegmentShape::line,
                    SegmentShape::free};
    using K = DesignCondition::Kind;
    cubic.conditions = {{K::tangent_angle, 0, 0.1, false},
                        {K::curvature, 3, 0.2, true},
                        {K::curvature_radius, 2, 4.0, false},
                        {K::segment_length, 4, 2.0, false}};
    for (const CurvatureProfileProblem& P :
         {fig3_problem(), closed_problem(2), closed_problem(3), cubic, spiro_problem(false), spiro_problem(true)}) {
        Eigen::VectorXd u = c2_start(P);
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> jitter(-0.05, 0.05);
        for (int i = 0; i < u.size(); ++i) u(i) += jitter(rng);
        const Eigen::MatrixXd J(design_system(P, u, true).jacobian);
        ASSERT_EQ(J.rows(), design_equations(P));
        ASSERT_EQ(J.cols(), design_unknowns(P));
        const double h = 1e-6;
        double worst = 0.0;
        for (int k = 0; k < u.size(); ++k) {
            Eigen::VectorXd up = u, um = u;
            up(k) += h, um(k) -= h;
            const Eigen::VectorXd fd = (design_system(P, up, false).f - design_system(P, um, false).f) / (2 * h);
            worst = std::max(worst, (fd - J.col(k)).lpNorm<Eigen::Infinity>());
        }
        EXPECT_LT(worst, 1e-7) << "∂f/∂u against central differences, " << design_equations(P) << " equations";
    }
}

TEST(CurvatureProfileDesign, Figure3ConvergesQuadraticallyToTheForcedArcs) {
    const CurvatureProfileProblem P = fig3_problem();
    const CurvatureProfileSolution sol = solve_curvature_profile(P);
    ASSERT_TRUE(sol.outcome.ok()) << sol.outcome.message;
    EXPECT_EQ(sol.rank, 36);  // 37 × 37, one redundant equation and a free split of span ⑩
    const std::vector<double> L = sol.segment_lengths();
    EXPECT_NEAR(L[3], std::numbers::pi / 2, 1e-11);  // quarter circle radius 1
    EXPECT_NEAR(L[6], 2 * std::numbers::pi, 1e-11);  // semicircle radius 2
    EXPECT_NEAR(L[8], std::numbers::pi / 2, 1e-11);
    EXPECT_NEAR(L[1], 4.01808761111852, 1e-11);  // reference/curvature_profile/fig3_mpmath.py
    EXPECT_NEAR(L[5], 5.12274417009232, 1e-11);
    EXPECT_NEAR(L[11], 3.43018694456654, 1e-11);
    const auto& h = sol.history;
    ASSERT_GE(h.size(), 4u);
    for (std::size_t k = 2; k + 1 < h.size(); ++k)
        EXPECT_LT(h[k + 1].residual, 10.0 * h[k].residual * h[k].residual) << "r_{k+1} ≤ C r_k² at k = " << k;
    const DesignVerification v = verify_design(P, *sol.curve);
    EXPECT_LT(v.interpolation_error, 1e-10);
    EXPECT_LT(v.line_curvature, 1e-10);
    EXPECT_LT(v.arc_curvature_spread, 1e-10);
    EXPECT_GT(v.g1_curvature_jump, 0.5);  // κ really jumps where a line meets an arc
}

TEST(CurvatureProfileDesign, ClosedClothoidSplineSparseAndDenseAgree) {
    const CurvatureProfileProblem P = closed_problem(2);
    NewtonOptions lu;
    lu.step = NewtonStep::sparse_lu;
    const CurvatureProfileSolution a = solve_curvature_profile(P), b = solve_curvature_profile(P, lu);
    ASSERT_TRUE(a.outcome.ok() && b.outcome.ok()) << a.outcome.message << b.outcome.message;
    EXPECT_LT((a.u - b.u).lpNorm<Eigen::Infinity>(), 1e-10);
    const DesignVerification v = verify_design(P, *a.curve);
    EXPECT_LT(std::abs(v.closing_angle), 1e-12);
    EXPECT_LT(std::abs(v.closing_curvature), 1e-12);
    EXPECT_LT(v.g2_curvature_jump, 1e-12);
    EXPECT_LT(v.interpolation_error, 1e-10);
    const TangentAngleSpline& psi = a.curve->tangent_angle();
    EXPECT_NEAR(psi.angle(5, true) - psi.angle(0, false), 2 * std::numbers::pi,
                1e-12);  // counter-clockwise: turns = +1
}

// The banded step: the layout's ordering makes J of an open clothoid spline banded (degree 2:
// 4 sub- and 4 superdiagonals, whatever n), and Newton with it reaches the solution of the sparse and
// dense steps. A closed curve's band is wide (its closing rows join the ends): the step falls back
// to SparseLU and still converges.
TEST(CurvatureProfileDesign, BandedStepAgreesWithSparseAndDense) {
    if (!cagd::numeric::BandedLu::available()) GTEST_SKIP() << "this build has no LAPACK";
    const int n = 150;
    PointList p(n, 2);
    for (int i = 0; i < n; ++i) p.row(i) << 0.5 * i, std::sin(0.5 * i) + 0.1 * std::cos(1.7 * i);
    const std::vector<SegmentShape> spans(static_cast<std::size_t>(n) - 1, SegmentShape::free);
    CurvatureProfileProblem P{p, span_layout(spans), spans, {}, false, 0};
    add_natural_open_ends(P);
    DesignBandOrdering order = design_band_ordering(P);
    const cagd::numeric::BandedLu band(design_system(P, c2_start(P), true).jacobian, std::move(order.rows),
                                       std::move(order.columns));
    EXPECT_LE(band.lower_width(), 4);
    EXPECT_LE(band.upper_width(), 4);
    NewtonOptions banded, sparse, dense;
    banded.step = NewtonStep::banded_lu;
    sparse.step = NewtonStep::sparse_lu;
    const CurvatureProfileSolution a = solve_curvature_profile(P, banded), b = solve_curvature_profile(P, sparse),
                                   c = solve_curvature_profile(P, dense);
    ASSERT_TRUE(a.outcome.ok() && b.outcome.ok() && c.outcome.ok())
        << a.outcome.message << b.outcome.message << c.outcome.message;
    EXPECT_LT((a.u - b.u).lpNorm<Eigen::Infinity>(), 1e-10);
    EXPECT_LT((a.u - c.u).lpNorm<Eigen::Infinity>(), 1e-10);
    EXPECT_EQ(a.history.size(), b.history.size()) << "the same Newton path";

    const CurvatureProfileProblem Q = closed_problem(2);
    DesignBandOrdering closed_order = design_band_ordering(Q);
    const cagd::numeric::BandedLu closed_band(design_system(Q, c2_start(Q), true).jacobian,
                                              std::move(closed_order.rows), std::move(closed_order.columns));
    EXPECT_GT(closed_band.storage_rows(), 2 * 4 + 4 + 1) << "the closing rows widen the band";
    const CurvatureProfileSolution d = solve_curvature_profile(Q, banded), e = solve_curvature_profile(Q, sparse);
    ASSERT_TRUE(d.outcome.ok() && e.outcome.ok()) << d.outcome.message << e.outcome.message;
    EXPECT_LT((d.u - e.u).lpNorm<Eigen::Infinity>(), 1e-10);
    CurvatureProfileProblem overdetermined = P;
    overdetermined.conditions.push_back({DesignCondition::Kind::tangent_angle, 3, 0.5});
    EXPECT_NE(cagd::test::invalid_input_message([&] {
                  solve_curvature_profile(overdetermined, banded);
              }).find("the banded LU step needs a square system"),
              std::string::npos);
}

TEST(CurvatureProfileDesign, DivergingIterationStopsEarly) {
    // Found by fuzz_interpolate: a closed clothoid spline through a hairpin that revisits (2, 1).
    // Newton diverges; it used to spend 50 iterations on ever more winding ψ (3 s at -O2, a
    // libFuzzer timeout under ASan). Now: no_convergence naming the divergence. Newton's path here
    // is chaotic (the start's last bits, e.g. from another tridiagonal solver, decide whether it
    // winds or stalls), so the test takes four such hairpins: all fail without a curve, and the
    // divergence stop must fire on at least one.
    int diverged = 0;
    for (double x4 : {6.0, 7.0, 7.5, 8.0}) {
        PointList p(6, 2);
        p << 0, 0, 2, 1, 1, 0, 2, 1, x4, 0, 9, 2.5;
        const std::vector<SegmentShape> free(6, SegmentShape::free);
        const KnotLayout layout = span_layout(free);
        const CurvatureProfileProblem problem{p, layout, segment_shapes(layout, free), {}, true, 0};
        const CurvatureProfileSolution sol = solve_curvature_profile(problem);
        EXPECT_EQ(sol.outcome.status, Status::no_convergence) << x4;
        EXPECT_FALSE(sol.curve.has_value()) << x4;
        if (sol.outcome.message.find("diverged at iteration") != std::string::npos) ++diverged;
    }
    EXPECT_GE(diverged, 1);
}

// A square regular system whose Newton settles above the tolerance, at the rounding level of its
// equations, has converged: a root lies within the step's resolution. It used to be reported as "the
// conditions are inconsistent", with a full-rank Jacobian. With dimensionless rows the default 1e-12
// is reached (a 270° arc of the unit circle through 48..192 points: ‖f‖∞ ≈ 1e-15 in 3–4 steps), so a
// tolerance below any reachable residual makes every run settle. The curve is the natural clothoid
// spline through the points: within its O(h²) distance of the circle, and through every point.
TEST(CurvatureProfileDesign, SettlingAtTheRoundingLevelIsConvergence) {
    for (const int n : {48, 96, 192}) {
        PointList p(n, 2);
        for (int i = 0; i < n; ++i) {
            const double a = 1.5 * std::numbers::pi * i / (n - 1);
            p.row(i) << std::cos(a), std::sin(a);
        }
        const std::vector<SegmentShape> free(static_cast<std::size_t>(n - 1), SegmentShape::free);
        const KnotLayout layout = span_layout(free);
        CurvatureProfileProblem problem{p, layout, segment_shapes(layout, free), {}, false, 0};
        add_natural_open_ends(problem);
        for (const NewtonStep step : {NewtonStep::banded_lu, NewtonStep::pseudo_inverse}) {
            NewtonOptions o;
            o.step = step;
            const std::string what = std::to_string(n) + (step == NewtonStep::banded_lu ? " LU" : " Moore–Penrose");
            const CurvatureProfileSolution reached = solve_curvature_profile(problem, o);
            ASSERT_TRUE(reached.outcome.ok()) << what << ": " << reached.outcome.message;
            EXPECT_LE(reached.history.back().residual, o.tolerance) << what << ": the default tolerance is reached";
            o.tolerance = 1e-20;  // below the rounding level of any row
            const CurvatureProfileSolution sol = solve_curvature_profile(problem, o);
            ASSERT_TRUE(sol.outcome.ok()) << what << ": " << sol.outcome.message;
            EXPECT_GT(sol.history.back().residual, o.tolerance) << what << ": settled above the tolerance";
            EXPECT_LE(sol.history.back().residual, 1e-13) << what;
            EXPECT_EQ(sol.history.back().step, 0.0) << what << ": the final record takes no step";
            const IntrinsicCurve& c = *sol.curve;
            double off = 0.0;
            for (int k = 0; k <= 400; ++k) off = std::max(off, std::abs(c.point(c.t_max() * (k / 400.0)).norm() - 1.0));
            EXPECT_LT(off, 20.0 / (n * n)) << what << ": distance from the circle";
            const std::vector<double> w = c.breakpoints();
            for (int i = 0; i < n; ++i)
                EXPECT_LT((c.point(w[static_cast<std::size_t>(i)]) - p.row(i).transpose()).norm(), 1e-12)
                    << what << ", point " << i;
        }
    }
}

TEST(CurvatureProfileDesign, InconsistentArcIsNoSolutionNotAWrongCurve) {
    // Line, arc, line: the circle leaving (1,0) along +x through (2,1) arrives heading +y, not along the
    // final line's +x.
    PointList p(4, 2);
    p << 0, 0, 1, 0, 2, 1, 3, 1;
    const std::vector<SegmentShape> spans = parse_span_shapes("line,arc,line");
    const CurvatureProfileProblem P{p, span_layout(spans), spans, {}, false, 0};
    const CurvatureProfileSolution sol = solve_curvature_profile(P);
    EXPECT_EQ(sol.outcome.status, Status::no_solution);
    EXPECT_FALSE(sol.curve.has_value());
    EXPECT_NE(sol.outcome.message.find("inconsistent"), std::string::npos) << sol.outcome.message;
    NewtonOptions one;
    one.max_iterations = 1;
    const CurvatureProfileSolution early = solve_curvature_profile(fig3_problem(), one);
    EXPECT_EQ(early.outcome.status, Status::no_convergence);
    EXPECT_NE(early.outcome.message.find("worst equation"), std::string::npos) << early.outcome.message;
    // A contraction no Newton step reaches: given up after the first step, saying so.
    NewtonOptions strict;
    strict.required_contraction = 1e-30;
    const CurvatureProfileSolution stopped = solve_curvature_profile(fig3_problem(), strict);
    EXPECT_EQ(stopped.outcome.status, Status::no_convergence);
    EXPECT_EQ(stopped.history.size(), 2u) << "the start and one step";
    EXPECT_NE(stopped.outcome.message.find("does not contract"), std::string::npos) << stopped.outcome.message;
    EXPECT_TRUE(solve_curvature_profile(fig3_problem(), NewtonOptions{.required_contraction = 0.5}).outcome.ok())
        << "Newton's own contraction passes 0.5";
    strict.required_contraction = 1.0;
    const std::string m = cagd::test::invalid_input_message([&] { solve_curvature_profile(fig3_problem(), strict); });
    EXPECT_NE(m.find("required_contraction < 1, got 1"), std::string::npos) << m;
}

TEST(CurvatureProfileDesign, SpanShapesAndDefaultLayout) {
    const std::vector<SegmentShape> s = parse_span_shapes("line, free,arc,free,free,clothoid");
    ASSERT_EQ(s.size(), 6u);
    EXPECT_EQ(s[5], SegmentShape::linear_curvature);
    const KnotLayout L = span_layout(s);
    EXPECT_EQ(L.degree(), 2);
    EXPECT_EQ(format_knot_difference_list(L), "{0, S0, 0, S1, 0, S2, 0, S3, S4, S5, 0}");
    EXPECT_THROW(parse_span_shapes("line,circle"), InvalidInput);
    EXPECT_THROW(parse_span_shapes(""), InvalidInput);
}

TEST(CurvatureProfileDesign, BadInputThrows) {
    CurvatureProfileProblem P = fig3_problem();
    auto expect_bad = [](CurvatureProfileProblem q, const char* what) {
        EXPECT_THROW(solve_curvature_profile(q), InvalidInput) << what;
    };
    {
        CurvatureProfileProblem q = P;
        q.points.conservativeResize(1, 2);
        expect_bad(q, "one point");
    }
    {
        CurvatureProfileProblem q = P;
        q.points.row(4) = q.points.row(3);
        expect_bad(q, "coincident consecutive points");
    }
    {
        CurvatureProfileProblem q = P;
        q.points(2, 1) = std::nan("");
        expect_bad(q, "NaN coordinate");
    }
    {
        CurvatureProfileProblem q = P;
        q.points.conservativeResize(12, 2);
        expect_bad(q, "12 points for a 12-span layout");
    }
    {
        CurvatureProfileProblem q = P;
        q.shapes[1] = SegmentShape::linear_curvature;
        expect_bad(q, "linear curvature on a degree-2 ψ");
    }
    {
        CurvatureProfileProblem q = P;
        q.conditions = {{DesignCondition::Kind::tangent_angle, 14, 0.0, false}};
        expect_bad(q, "breakpoint out of range");
    }
    {
        CurvatureProfileProblem q = P;
        q.conditions = {{DesignCondition::Kind::curvature_radius, 3, 0.0, false}};
        expect_bad(q, "radius 0");
    }
    Eigen::VectorXd start = c2_start(P);
    start(2) = -1.0;
    EXPECT_THROW(solve_curvature_profile(P, start), InvalidInput);
    EXPECT_THROW(solve_curvature_profile(P, Eigen::VectorXd::Ones(5)), InvalidInput);
    NewtonOptions lu;
    lu.step = NewtonStep::sparse_lu;
    CurvatureProfileProblem under = closed_problem(2);
    under.closed = false;
    under.points.conservativeResize(7, 2);
    under.points.row(6) << 1, -2;
    EXPECT_THROW(solve_curvature_profile(under, lu), InvalidInput);  // 12 + 0 equations, 14 unknowns
}

// Spiro (intrinsic/spiro.hpp): the chordwise Jacobian against central differences, and the two
// formulations agreeing on one curve, G4 at every point.
TEST(Spiro, ChordwiseJacobianMatchesCentralDifferences) {
    for (bool closed : {false, true}) {
        const CurvatureProfileProblem P = spiro_problem(false);
        PointList points = closed ? closed_problem(4).points : P.points;
        const int spans = static_cast<int>(points.rows()) - (closed ? 0 : 1);
        std::vector<std::array<double, 4>> ks;
        for (int i = 0; i < spans; ++i) ks.push_back({0.3 * i - 0.5, 0.2, -0.1 * i, 0.05});
        const Eigen::MatrixXd J(spiro_chordwise_system(points, closed, ks).jacobian);
        double worst = 0.0;
        for (int c = 0; c < 4 * spans; ++c) {
            auto up = ks, down = ks;
            up[static_cast<std::size_t>(c / 4)][static_cast<std::size_t>(c % 4)] += 1e-6;
            down[static_cast<std::size_t>(c / 4)][static_cast<std::size_t>(c % 4)] -= 1e-6;
            const Eigen::VectorXd fd =
                (spiro_chordwise_system(points, closed, up).f - spiro_chordwise_system(points, closed, down).f) / 2e-6;
            worst = std::max(worst, (fd - J.col(c)).lpNorm<Eigen::Infinity>());
        }
        EXPECT_LT(worst, 1e-8) << (closed ? "closed" : "open");
    }
    EXPECT_THROW(spiro_chordwise_system(closed_problem(4).points, true, {}), InvalidInput);
}

TEST(Spiro, BothFormulationsGiveOneG4Curve) {
    for (bool closed : {false, true}) {
        const PointList points = closed ? closed_problem(4).points : spiro_problem(false).points;
        const SpiroSolution s = solve_spiro(points, closed);
        ASSERT_TRUE(s.solution.outcome.ok()) << s.solution.outcome.message;
        const TangentAngleSpline& psi = s.solution.curve->tangent_angle();
        // The chordwise arc lengths and curvature coefficients are the arc-length solution's.
        for (int j = 0; j < psi.segments(); ++j) {
            const double l = psi.segment_lengths()[static_cast<std::size_t>(j)];
            EXPECT_NEAR(l, s.chordwise.arc_lengths[static_cast<std::size_t>(j)], 1e-10 * l);
            const Eigen::VectorXd jet =
                psi.jet_in_segment(j, psi.breakpoints()[static_cast<std::size_t>(j)] + 0.5 * l, 4);
            for (int d = 0; d < 4; ++d)
                EXPECT_NEAR(std::pow(l, d + 1) * jet(d + 1),
                            s.chordwise.ks[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)], 1e-9);
        }
        // G4: ψ, κ, κ', κ'' continuous at every interior breakpoint (and across the seam).
        for (int g = 1; g < psi.segments(); ++g) {
            const double w = psi.breakpoints()[static_cast<std::size_t>(g)];
            const Eigen::VectorXd left = psi.jet_in_segment(g - 1, w, 4), right = psi.jet_in_segment(g, w, 4);
            for (int d = 0; d < 4; ++d)
                EXPECT_NEAR(left(d), right(d), 1e-9 * (1 + std::abs(left(d)))) << "ψ^(" << d << ") at breakpoint " << g;
            EXPECT_GT(std::abs(left(4) - right(4)), 1e-6) << "a knot: ψ'''' jumps at breakpoint " << g;
        }
        const Eigen::VectorXd start = psi.jet_in_segment(0, 0.0, 3),
                              end = psi.jet_in_segment(psi.segments() - 1, psi.length(), 3);
        if (closed) {
            EXPECT_NEAR(end(0) - start(0), 2 * std::numbers::pi, 1e-10);
            for (int d = 1; d < 4; ++d) EXPECT_NEAR(end(d), start(d), 1e-9 * (1 + std::abs(start(d))));
        } else {
            for (int d = 2; d < 4; ++d) {
                EXPECT_NEAR(start(d), 0.0, 1e-9) << "κ^(" << d - 1 << ") = 0 at the open start";
                EXPECT_NEAR(end(d), 0.0, 1e-9) << "κ^(" << d - 1 << ") = 0 at the open end";
            }
        }
        // The curve passes through the points.
        for (int i = 0; i < s.problem.layout.spans(); ++i)
            EXPECT_LE(
                (s.solution.curve->point(psi.breakpoints()[static_cast<std::size_t>(i)]) - points.row(i).transpose())
                    .norm(),
                1e-10);
    }
}

TEST(Spiro, BadConditionsThrow) {
    CurvatureProfileProblem open = spiro_problem(false);
    open.conditions.front().order = 3;  // a degree-4 ψ has κ' and κ'' only
    EXPECT_THROW(require_valid_problem(open, "test"), InvalidInput);
    CurvatureProfileProblem closed = spiro_problem(true);
    closed.closing_continuity = 5;
    EXPECT_THROW(require_valid_problem(closed, "test"), InvalidInput);
    closed.closing_continuity = 1;
    EXPECT_THROW(require_valid_problem(closed, "test"), InvalidInput);
    PointList three_d(4, 3);
    three_d.setRandom();
    EXPECT_THROW(solve_spiro(three_d, false), InvalidInput);
    PointList repeated(3, 2);
    repeated << 0, 0, 0, 0, 1, 1;
    EXPECT_THROW(solve_spiro(repeated, false), InvalidInput);
}

// The G1 Hermite problem with clothoids: symmetric end angles −α, α on a unit chord are met by the
// circular arc of turn 2α (radius 1 / (2 sin α), length α / sin α); equal angles 0 by the chord.
TEST(CurvatureProfileDesign, EndAnglesOfASymmetricG1ProblemGiveTheArc) {
    PointList p(2, 2);
    p << 0, 0, 1, 0;
    for (const double alpha : {0.3, 1.0, 2.5}) {
        const CurvatureProfileSolution sol =
            solve_curvature_profile_auto(clothoid_spline_with_end_angles(p, -alpha, alpha));
        ASSERT_TRUE(sol.outcome.ok()) << alpha << ": " << sol.outcome.message;
        const IntrinsicCurve& c = *sol.curve;
        EXPECT_NEAR(c.t_max(), alpha / std::sin(alpha), 1e-11) << "α = " << alpha << ": length α / sin α";
        for (const double s : {0.0, 0.37, 1.0}) {
            const Eigen::MatrixXd d = c.derivatives(s * c.t_max(), 2);
            const double kappa = d(0, 0) * d(1, 1) - d(0, 1) * d(1, 0);  // unit speed
            EXPECT_NEAR(kappa, 2.0 * std::sin(alpha), 1e-9) << "α = " << alpha << ", s = " << s;
        }
    }
    const CurvatureProfileSolution line = solve_curvature_profile_auto(clothoid_spline_with_end_angles(p, 0.0, 0.0));
    ASSERT_TRUE(line.outcome.ok());
    EXPECT_NEAR(line.curve->t_max(), 1.0, 1e-13);
    try {
        clothoid_spline_with_end_angles(p, std::nan(""), 0.0);
        ADD_FAILURE() << "a NaN angle was accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("nan"), std::string::npos) << e.what();
    }
    EXPECT_THROW(clothoid_spline_with_end_angles(p.topRows(1), 0.0, 0.0), InvalidInput);
}
