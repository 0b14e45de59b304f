// compare/scorecard: the seeded polygons, each measure on methods whose property is known, the peer
// curves read as interpolants, the summaries and their independence of the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cagd/compare/scorecard.hpp"
#include "cagd/export/bezier_form.hpp"

using namespace cagd;
using namespace cagd::compare;

namespace {

// The turning angle at interior point i of an open polygon.
double turn_at(const PointList& p, long i) {
    const Eigen::Vector2d a = (p.row(i) - p.row(i - 1)).transpose(), b = (p.row(i + 1) - p.row(i)).transpose();
    return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

CurveSubject method(const std::string& name) { return method_subject(methods::find_configuration(name), 1); }

const ScorecardRow& row(const std::vector<ScorecardRow>& rows, const std::string& property,
                        const std::string& quantity) {
    const auto it = std::find_if(rows.begin(), rows.end(), [&](const ScorecardRow& r) {
        return r.property == property && r.quantity == quantity;
    });
    if (it == rows.end()) throw std::runtime_error("no row " + property + " " + quantity);
    return *it;
}

}  // namespace

TEST(Scorecard, PolygonsHaveTheirLargestTurnAndTheSameSeedTheSamePoints) {
    for (unsigned s = 0; s < 200; ++s) {
        const ScorecardPolygon p = scorecard_polygon(s);
        ASSERT_EQ(p.points.rows(), kScorecardPoints);
        EXPECT_GE(p.largest_turn, 30.0 * std::numbers::pi / 180);
        EXPECT_LE(p.largest_turn, 170.0 * std::numbers::pi / 180);
        double largest = 0.0;
        for (long i = 1; i + 1 < p.points.rows(); ++i) largest = std::max(largest, std::abs(turn_at(p.points, i)));
        EXPECT_NEAR(largest, p.largest_turn, 1e-12) << "seed " << s;
        EXPECT_EQ(scorecard_polygon(s).points, p.points);
    }
}

TEST(Scorecard, CoCircularSetsLieOnTheUnitCircleWithThreeToSixtyFourPoints) {
    for (unsigned s = 0; s < 124; ++s)
        for (bool closed : {true, false}) {
            const PointList p = co_circular_points(s, closed);
            EXPECT_EQ(p.rows(), 3 + static_cast<long>(s % 62));
            EXPECT_LT((p.rowwise().norm().array() - 1.0).abs().maxCoeff(), 1e-15) << "seed " << s;
        }
}

TEST(Scorecard, MeasuresShowWhatTheMethodsAreKnownToDo) {
    const ScorecardOptions o{.polygons = 40, .threads = 2};
    // The chordal cubic spline: symmetric and similarity invariant to rounding; every span moves.
    const auto cubic = scorecard_rows(run_scorecard(method("cubic-b"), o));
    EXPECT_LT(row(cubic, "symmetry", "max").estimate.value, 1e-14);
    EXPECT_LT(row(cubic, "similarity", "max").estimate.value, 1e-13);
    EXPECT_EQ(row(cubic, "spans_moved", "median").estimate.value, kScorecardPoints - 1);
    EXPECT_GT(row(cubic, "roundness_closed", "median").estimate.value, 1e-6);  // not a circle
    EXPECT_EQ(row(cubic, "existence", "rate").estimate.value, 0.0);
    // The S-spline with m = 1 moves the 2 (m + 2) = 6 spans around a moved point, none beyond.
    const auto s1 = scorecard_rows(run_scorecard(method("s-spline-m1"), o));
    EXPECT_EQ(row(s1, "spans_moved", "mean").estimate.value, 6.0);
    EXPECT_EQ(row(s1, "zero_influence_spans", "median").estimate.value, kScorecardPoints - 1 - 6);
    // The clothoid spline (curvature linear in arc length on each span): a closed circle through
    // co-circular points, extensional, and its |κ| peaks only at the points.
    const auto clothoid = scorecard_rows(run_scorecard(method("curvature-profile"), o));
    EXPECT_LT(row(clothoid, "roundness_closed", "max").estimate.value, 1e-10);
    EXPECT_LT(row(clothoid, "extensionality", "q95").estimate.value, 1e-9);
    EXPECT_EQ(row(clothoid, "curvature_maxima_inside", "rate").estimate.value, 0.0);
    EXPECT_GT(row(cubic, "curvature_maxima_inside", "rate").estimate.value, 0.0);
}

TEST(Scorecard, FailuresAreBinnedByTheLargestTurningAngle) {
    // A subject that fails exactly on the polygons whose largest turn exceeds 90°.
    const CurveSubject base = method("cubic-b");
    const CurveSubject picky{.name = "picky", .kind = "method", .draw = [&](const std::vector<CurveRequest>& rs) {
                                 std::vector<DrawnCurve> out = base.draw(rs);
                                 for (std::size_t k = 0; k < rs.size(); ++k) {
                                     double largest = 0.0;
                                     if (!rs[k].closed)
                                         for (long i = 1; i + 1 < rs[k].points.rows(); ++i)
                                             largest = std::max(largest, std::abs(turn_at(rs[k].points, i)));
                                     if (largest > std::numbers::pi / 2)
                                         out[k] = {.status = AttemptStatus::no_result, .note = "too sharp"};
                                 }
                                 return out;
                             }};
    const auto rows = scorecard_rows(run_scorecard(picky, {.polygons = 300}));
    EXPECT_EQ(row(rows, "existence_30_50", "rate").estimate.value, 0.0);
    EXPECT_EQ(row(rows, "existence_70_90", "rate").estimate.value, 0.0);
    EXPECT_EQ(row(rows, "existence_110_130", "rate").estimate.value, 1.0);
    EXPECT_EQ(row(rows, "existence_150_170", "rate").estimate.value, 1.0);
    const ScorecardRow& all = row(rows, "existence", "rate");
    EXPECT_EQ(all.sets, 300);
    EXPECT_GT(all.estimate.value, 0.4);
    EXPECT_LT(all.estimate.low, all.estimate.value);
    EXPECT_GT(all.estimate.high, all.estimate.value);
    // Measures are over the polygons with a curve only.
    EXPECT_EQ(row(rows, "symmetry", "median").sets, std::lround(300 * (1.0 - all.estimate.value)));
}

TEST(Scorecard, PeerPiecesBecomeAnInterpolantThroughThePoints) {
    const PointList p = scorecard_polygon(3).points;
    const auto curve = methods::interpolate("cubic-b", p, false);
    exports::CurveDocument d;
    d.form = exports::to_bezier(*curve.interpolant->curve);
    std::string why;
    const auto in = peer_interpolant(d, p, false, why);
    ASSERT_TRUE(in) << why;
    EXPECT_EQ(in->node_parameters, d.form.pieces.breaks);
    // Two pieces per span (each split at its middle): the nodes are every other break.
    exports::BezierPieces split;
    split.degree = 3;
    split.control.resize(2 * d.form.pieces.control.rows(), 2);
    for (int i = 0; i < d.form.pieces.pieces(); ++i) {
        const double a = d.form.pieces.breaks[static_cast<std::size_t>(i)],
                     b = d.form.pieces.breaks[static_cast<std::size_t>(i) + 1];
        const BezierCurve piece = exports::piece_curve(d.form.pieces, i);
        for (int half = 0; half < 2; ++half) {
            const double lo = a + 0.5 * half * (b - a), hi = lo + 0.5 * (b - a);
            if (split.breaks.empty()) split.breaks.push_back(lo);
            split.breaks.push_back(hi);
            const Eigen::MatrixXd l = piece.jet(lo, 1), r = piece.jet_from_left(hi, 1);
            const long first = (2 * i + half) * 4;
            split.control.row(first) = l.row(0);
            split.control.row(first + 1) = l.row(0) + (hi - lo) / 3 * l.row(1);
            split.control.row(first + 2) = r.row(0) - (hi - lo) / 3 * r.row(1);
            split.control.row(first + 3) = r.row(0);
        }
    }
    exports::CurveDocument halves;
    halves.form.pieces = split;
    const auto twice = peer_interpolant(halves, p, false, why);
    ASSERT_TRUE(twice) << why;
    for (std::size_t k = 0; k < twice->node_parameters.size(); ++k)
        EXPECT_EQ(twice->node_parameters[k], split.breaks[2 * k]);
    // One cubic through four points (SISL's free ends drop the interior knots): the nodes lie inside
    // its piece, at the chord lengths.
    exports::CurveDocument one;
    one.form.pieces.degree = 3;
    one.form.pieces.breaks = {0.0, 3 * std::sqrt(2.0)};
    one.form.pieces.control.resize(4, 2);
    one.form.pieces.control << 0, 0, 1, 10.0 / 3, 2, -7.0 / 3, 3, 1;
    PointList four(4, 2);
    four << 0, 0, 1, 1, 2, 0, 3, 1;
    const auto inside = peer_interpolant(one, four, false, why);
    ASSERT_TRUE(inside) << why;
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(inside->node_parameters[static_cast<std::size_t>(i)], i * std::sqrt(2.0), 1e-9);
    // A piece with a loop: it passes 0.034 from the point near t = 0.03 (the nearest sample there)
    // and through it at t = 0.962; the pass is found from the second local minimum.
    exports::CurveDocument loop;
    loop.form.pieces.degree = 3;
    loop.form.pieces.breaks = {0.0, 1.0};
    loop.form.pieces.control.resize(4, 2);
    loop.form.pieces.control << 0, 0, 3, 4, -6, 3, 1, 0;
    const BezierCurve looped = exports::piece_curve(loop.form.pieces, 0);
    PointList three(3, 2);
    three.row(0) = looped.jet(0.0, 0).row(0);
    three.row(1) = looped.jet(0.962, 0).row(0);
    three.row(2) = looped.jet(1.0, 0).row(0);
    const auto through = peer_interpolant(loop, three, false, why);
    ASSERT_TRUE(through) << why;
    EXPECT_NEAR(through->node_parameters[1], 0.962, 1e-9);
    // A curve that misses a point is no interpolant, and says which point.
    PointList moved = p;
    moved(5, 1) += 0.1;
    EXPECT_FALSE(peer_interpolant(d, moved, false, why));
    EXPECT_NE(why.find("point 6"), std::string::npos) << why;
}

TEST(Scorecard, PeersAreScoredThroughTheirAdapters) {
    // The test launcher's echoer draws the polygon itself: symmetric, similar, local (the two spans
    // beside a moved point), straight; its "refuse" configuration fails on every polygon.
    const PeerLauncher launcher{.run = std::string(CAGD_SOURCE_DIR) + "/tests/data/peers/run",
                                .programs = "/nonexistent"};
    PeerConfiguration echo{.peer = "echoer", .configuration = "polygon", .open = true, .closed = false};
    const auto rows = scorecard_rows(run_scorecard(peer_subject(launcher, echo), {.polygons = 20}));
    EXPECT_LT(row(rows, "symmetry", "max").estimate.value, 1e-15);
    EXPECT_EQ(row(rows, "spans_moved", "mean").estimate.value, 2.0);
    EXPECT_EQ(row(rows, "bending", "max").estimate.value, 0.0);
    EXPECT_THROW(row(rows, "roundness_closed", "median"), std::runtime_error);  // draws no closed curves
    echo.configuration = "refuse";
    const auto refused = scorecard_rows(run_scorecard(peer_subject(launcher, echo), {.polygons = 20}));
    EXPECT_EQ(row(refused, "existence", "rate").estimate.value, 1.0);
}

TEST(Scorecard, ResultsDoNotDependOnTheThreads) {
    ScorecardOptions o{.polygons = 30, .threads = 1};
    const std::string one = scorecard_csv(scorecard_rows(run_scorecard(method("spiro"), o)));
    o.threads = 2;
    EXPECT_EQ(scorecard_csv(scorecard_rows(run_scorecard(method("spiro"), o))), one);
    EXPECT_EQ(one.substr(0, one.find('\n')), "subject,kind,property,quantity,sets,value,low,high");
    const std::string md = scorecard_markdown(scorecard_rows(run_scorecard(method("spiro"), o)), 30, {"x: absent"});
    EXPECT_NE(md.find("| spiro |"), std::string::npos);
    EXPECT_NE(md.find("- x: absent"), std::string::npos);
}
