// The spiro method against libspiro, the C library FontForge and Inkscape use (Debian libspiro-dev,
// GPL). libspiro is linked into this test program only: never into the library or the command.
//
// libspiro's run_spiro returns, per segment, ks[0..3]: the curvature of the segment scaled to unit
// arc length, κ_n(u) = ks0 + ks1 u + ks2 u²/2 + ks3 u³/6 for u ∈ [−1/2, 1/2]. For a segment of arc
// length ℓ with midpoint s_m that is ks_d = ℓ^(d+1) κ^(d)(s_m), which the spiro method gives from
// its tangent angle ψ (κ^(d) = ψ^(d+1)). Both sides are dimensionless and similarity-invariant.
#include <gtest/gtest.h>

#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

extern "C" {
#include <bezctx.h>
#include <spiro.h>
}

#include "cagd/intrinsic/intrinsic_curve.hpp"
#include "cagd/intrinsic/spiro.hpp"
#include "cagd/methods/method_registry.hpp"

using namespace cagd;

namespace {

struct SpiroCase {
    const char* name;
    PointList points;
    bool closed;
};

PointList rows(std::initializer_list<std::pair<double, double>> xy) {
    PointList p(static_cast<Eigen::Index>(xy.size()), 2);
    Eigen::Index i = 0;
    for (const auto& [x, y] : xy) p(i, 0) = x, p(i, 1) = y, ++i;
    return p;
}

std::vector<SpiroCase> cases() {
    std::vector<SpiroCase> out;
    out.push_back({"open wave", rows({{0, 0}, {1, 0.3}, {2, 0.2}, {3, 0.5}, {4.2, 0.3}, {5, 0.6}}), false});
    // Spiro draws a loop here: the last span turns by 5.7 rad. Both libraries find it.
    out.push_back({"open S with a loop", rows({{0, 0}, {2, 1}, {3, 3}, {2, 5}, {4, 6}}), false});
    out.push_back({"three points", rows({{0, 0}, {1, 1}, {2, 0}}), false});
    PointList ellipse(9, 2);
    for (int i = 0; i < 9; ++i)
        ellipse(i, 0) = 3 * std::cos(2 * std::numbers::pi * i / 9),
                   ellipse(i, 1) = 1.5 * std::sin(2 * std::numbers::pi * i / 9);
    out.push_back({"closed ellipse", ellipse, true});
    out.push_back({"closed blob", rows({{0, 0}, {4, -1}, {7, 1}, {6, 5}, {2, 6}, {-1, 3}}), true});
    // libspiro's own test shape (its tests' "path0" letter outline, open).
    out.push_back({"open hook",
                   rows({{334, 117},
                         {305, 176},
                         {212, 142},
                         {159, 171},
                         {224, 237},
                         {347, 335},
                         {202, 467},
                         {81, 429},
                         {114, 368},
                         {201, 402}}),
                   false});
    return out;
}

// ks of every segment as libspiro computes them.
std::vector<std::array<double, 4>> libspiro_ks(const SpiroCase& c) {
    const int n = static_cast<int>(c.points.rows());
    std::vector<spiro_cp> cp(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) cp[static_cast<std::size_t>(i)] = {c.points(i, 0), c.points(i, 1), 'o'};
    if (!c.closed) cp.front().ty = '{', cp.back().ty = '}';
    spiro_seg* s = run_spiro(cp.data(), n);
    EXPECT_NE(s, nullptr) << c.name;
    std::vector<std::array<double, 4>> out;
    if (!s) return out;
    const int segments = c.closed ? n : n - 1;
    for (int j = 0; j < segments; ++j) out.push_back({s[j].ks[0], s[j].ks[1], s[j].ks[2], s[j].ks[3]});
    free_spiro(s);
    return out;
}

}  // namespace

// Segment by segment, ours against libspiro's, raw and after one Newton step of our chordwise
// equations from libspiro's ks. libspiro stops its Newton when the squared step is below 1e-12, so
// its ks carry its residual (up to 1e-8 in our equations) times the system's conditioning; the one
// step removes exactly that, and what remains is the agreement of the two solutions.
TEST(SpiroAgainstLibspiro, CurvatureCoefficientsAgreeSegmentBySegment) {
    double worst_raw = 0.0, worst_polished = 0.0;
    for (const SpiroCase& c : cases()) {
        std::vector<std::array<double, 4>> theirs = libspiro_ks(c);
        ASSERT_FALSE(theirs.empty()) << c.name;
        const intrinsic::SpiroChordwiseSystem sys = intrinsic::spiro_chordwise_system(c.points, c.closed, theirs);
        Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(sys.jacobian);
        ASSERT_EQ(lu.info(), Eigen::Success) << c.name;
        const Eigen::VectorXd step = lu.solve(sys.f);
        std::vector<std::array<double, 4>> polished = theirs;
        for (std::size_t j = 0; j < polished.size(); ++j)
            for (std::size_t d = 0; d < 4; ++d) polished[j][d] -= step(static_cast<Eigen::Index>(4 * j + d));
        const methods::InterpolationResult r = methods::interpolate("spiro", c.points, c.closed);
        ASSERT_TRUE(r.outcome.ok()) << c.name << ": " << r.outcome.message;
        const auto* curve = dynamic_cast<const intrinsic::IntrinsicCurve*>(r.interpolant->curve.get());
        ASSERT_NE(curve, nullptr);
        const intrinsic::TangentAngleSpline& psi = curve->tangent_angle();
        ASSERT_EQ(static_cast<std::size_t>(psi.segments()), theirs.size()) << c.name;
        for (int j = 0; j < psi.segments(); ++j) {
            const double l = psi.segment_lengths()[static_cast<std::size_t>(j)],
                         mid = psi.breakpoints()[static_cast<std::size_t>(j)] + 0.5 * l;
            const Eigen::VectorXd jet = psi.jet_in_segment(j, mid, 4);
            for (int d = 0; d < 4; ++d) {
                const double ours = std::pow(l, d + 1) * jet(d + 1);
                const double raw = std::abs(ours - theirs[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)]);
                const double after =
                    std::abs(ours - polished[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)]);
                worst_raw = std::max(worst_raw, raw);
                worst_polished = std::max(worst_polished, after);
                EXPECT_LE(raw, 1e-6) << c.name << ", segment " << j << ", ks[" << d << "]: ours " << ours
                                     << ", libspiro "
                                     << theirs[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)];
                EXPECT_LE(after, 1e-9) << c.name << ", segment " << j << ", ks[" << d
                                       << "] after one Newton step from libspiro's: ours " << ours << ", libspiro's "
                                       << polished[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)];
            }
        }
    }
    std::printf("largest |ks difference| against libspiro: %.3g as it returns them, %.3g after one Newton step\n",
                worst_raw, worst_polished);
}

// libspiro's own solution satisfies our chordwise equations (intrinsic::spiro_chordwise_system),
// to libspiro's convergence tolerance.
TEST(SpiroAgainstLibspiro, LibspiroSolvesOurChordwiseEquations) {
    for (const SpiroCase& c : cases()) {
        const std::vector<std::array<double, 4>> theirs = libspiro_ks(c);
        ASSERT_FALSE(theirs.empty()) << c.name;
        const intrinsic::SpiroChordwiseSystem sys = intrinsic::spiro_chordwise_system(c.points, c.closed, theirs);
        EXPECT_LE(sys.f.lpNorm<Eigen::Infinity>(), 1e-7) << c.name;
    }
}

// Where Spiro has no solution, both libraries say so: libspiro returns no path, and the method
// returns no_convergence rather than a curve.
TEST(SpiroAgainstLibspiro, BothFailOnATightZigzag) {
    const SpiroCase zigzag{"tight zigzag", rows({{0, 0}, {1, 0.6}, {2, 0.2}, {3, 0.9}, {4.2, 0.3}, {5, 1.1}}), false};
    std::vector<spiro_cp> cp;
    for (int i = 0; i < zigzag.points.rows(); ++i) cp.push_back({zigzag.points(i, 0), zigzag.points(i, 1), 'o'});
    cp.front().ty = '{', cp.back().ty = '}';
    spiro_seg* s = run_spiro(cp.data(), static_cast<int>(cp.size()));
    EXPECT_EQ(s, nullptr) << "libspiro solved the zigzag";
    if (s) free_spiro(s);
    const methods::InterpolationResult r = methods::interpolate("spiro", zigzag.points, false);
    EXPECT_FALSE(r.outcome.ok());
    EXPECT_EQ(r.outcome.status, Status::no_convergence);
    EXPECT_FALSE(r.interpolant.has_value());
}

TEST(SpiroAgainstLibspiro, KnotTangentAnglesAgree) {
    for (const SpiroCase& c : cases()) {
        const int n = static_cast<int>(c.points.rows());
        std::vector<spiro_cp> cp(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) cp[static_cast<std::size_t>(i)] = {c.points(i, 0), c.points(i, 1), 'o'};
        if (!c.closed) cp.front().ty = '{', cp.back().ty = '}';
        spiro_seg* s = run_spiro(cp.data(), n);
        ASSERT_NE(s, nullptr);
        const methods::InterpolationResult r = methods::interpolate("spiro", c.points, c.closed);
        ASSERT_TRUE(r.outcome.ok()) << r.outcome.message;
        const Curve& curve = *r.interpolant->curve;
        const int segments = c.closed ? n : n - 1;
        for (int i = 0; i < segments; ++i) {
            const double u = r.interpolant->node_parameters[static_cast<std::size_t>(i)];
            const Eigen::MatrixXd jet = curve.jet(u, 1);
            const double ours = std::atan2(jet(1, 1), jet(1, 0)), theirs = get_knot_th(s, i);
            EXPECT_LE(std::abs(std::remainder(ours - theirs, 2 * std::numbers::pi)), 1e-9) << c.name << ", point " << i;
        }
        free_spiro(s);
    }
}

// Seeded random polygons (points around a circle, radius and angle jittered; open and closed).
// Wherever both libraries return a curve it is the same curve: libspiro's ks, refined by up to three
// Newton steps of our chordwise equations, agree with ours to 1e-9. Newton's basin differs a little
// between the two (libspiro differentiates numerically, we exactly):
// the counts of sets each solves are printed, and the method must solve at least 180 of the 200.
TEST(SpiroAgainstLibspiro, SeededPolygons) {
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<double> jitter(-0.35, 0.35);
    int both = 0, only_ours = 0, only_theirs = 0, neither = 0;
    double worst = 0.0;
    for (int trial = 0; trial < 200; ++trial) {
        const int n = 4 + trial % 9;
        const bool closed = trial % 2 == 1;
        PointList p(n, 2);
        for (int i = 0; i < n; ++i) {
            const double a = (closed ? 2 * std::numbers::pi : 1.5 * std::numbers::pi) * (i + 0.5 * jitter(rng)) / n,
                         r = 1.0 + jitter(rng);
            p(i, 0) = r * std::cos(a), p(i, 1) = r * std::sin(a);
        }
        const SpiroCase c{"seeded", p, closed};
        std::vector<spiro_cp> cp;
        for (int i = 0; i < n; ++i) cp.push_back({p(i, 0), p(i, 1), 'o'});
        if (!closed) cp.front().ty = '{', cp.back().ty = '}';
        spiro_seg* s = run_spiro(cp.data(), n);
        const methods::InterpolationResult r = methods::interpolate("spiro", p, closed);
        if (!s) {
            ++(r.outcome.ok() ? only_ours : neither);
            continue;
        }
        free_spiro(s);
        if (!r.outcome.ok()) {
            ++only_theirs;
            std::printf("trial %d: libspiro converges, the method does not: %s\n", trial, r.outcome.message.c_str());
            continue;
        }
        ++both;
        std::vector<std::array<double, 4>> theirs = libspiro_ks(c);
        for (int step = 0; step < 3; ++step) {
            const intrinsic::SpiroChordwiseSystem sys = intrinsic::spiro_chordwise_system(p, closed, theirs);
            Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(sys.jacobian);
            const Eigen::VectorXd delta = lu.solve(sys.f);
            for (std::size_t j = 0; j < theirs.size(); ++j)
                for (std::size_t d = 0; d < 4; ++d) theirs[j][d] -= delta(static_cast<Eigen::Index>(4 * j + d));
        }
        const auto& psi = dynamic_cast<const intrinsic::IntrinsicCurve&>(*r.interpolant->curve).tangent_angle();
        for (int j = 0; j < psi.segments(); ++j) {
            const double l = psi.segment_lengths()[static_cast<std::size_t>(j)];
            const Eigen::VectorXd jet =
                psi.jet_in_segment(j, psi.breakpoints()[static_cast<std::size_t>(j)] + 0.5 * l, 4);
            for (int d = 0; d < 4; ++d) {
                const double diff = std::abs(std::pow(l, d + 1) * jet(d + 1) -
                                             theirs[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)]);
                worst = std::max(worst, diff);
                EXPECT_LE(diff, 1e-9) << "trial " << trial << ", segment " << j << ", ks[" << d << "]";
            }
        }
    }
    std::printf(
        "200 seeded polygons: both solve %d, only the method %d, only libspiro %d, neither %d; largest |ks difference| "
        "%.3g\n",
        both, only_ours, only_theirs, neither, worst);
    EXPECT_GE(both + only_ours, 180);
}
