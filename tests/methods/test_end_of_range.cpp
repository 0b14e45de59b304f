// Every configuration of the registry at 10, 10^3 and 10^5 points: the curve is defined on the whole
// of its stated parameter range [t_min, t_max], its first and last node parameters are that range's
// ends, and there it passes through the first and last point (closed: through the first point
// again), in u and in the method's parameter τ (MethodParameterCurve, what Python returns). The
// points: walks of unit steps in uniformly random directions (near-hairpins included), and walks
// whose chords vary 10^6-fold (log-uniform in [1e-3, 1e3]), open and closed. The iterative methods
// (Newton: the curvature profile, Spiro) take walks whose steps turn by at most ±1.2 rad instead,
// where their curves exist: on hairpins they end in no_convergence, after up to 50 Newton steps
// (111 s at 10^3 points for the curvature profile), which tests no end of any range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "cagd/core/curve.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"

namespace {

using cagd::PointList;

// n points of a walk from the origin; each step turns by an angle uniform in [−max_turn, max_turn]
// (π: a uniformly random direction) and has length 1 (chord_decades = 0) or 10^x with x uniform in
// [−chord_decades, chord_decades].
PointList end_of_range_walk(long n, unsigned seed, double chord_decades, double max_turn) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> turn(-max_turn, max_turn), decade(-chord_decades, chord_decades);
    PointList p(n, 2);
    p.row(0) << 0.0, 0.0;
    double heading = 0.0;
    for (long i = 1; i < n; ++i) {
        heading += turn(rng);
        const double l = chord_decades > 0.0 ? std::pow(10.0, decade(rng)) : 1.0;
        p.row(i) << p(i - 1, 0) + l * std::cos(heading), p(i - 1, 1) + l * std::sin(heading);
    }
    return p;
}

// The curve at both ends of its range, against the first and last point. Positions agree to
// kEndPositionTolerance of the points' extent: the direct methods interpolate to rounding, the
// iterative ones (curvature profile, Spiro) to their Newton tolerance, summed along the curve.
constexpr double kEndPositionTolerance = 1e-8;
// The largest turn per step of the iterative methods' walks (see the file comment).
constexpr double kIterativeMaxTurn = 1.2;

void expect_ends_interpolate(const cagd::methods::Configuration& c, const PointList& p, bool closed,
                             const std::string& what) {
    SCOPED_TRACE(c.name + (closed ? " closed, " : " open, ") + what + ", n = " + std::to_string(p.rows()));
    cagd::methods::InterpolationResult r;
    ASSERT_NO_THROW(r = cagd::methods::interpolate(c, p, closed));
    if (!r.outcome.ok()) {
        // A numerical outcome (these walks have near-hairpins, where the iterative methods may find
        // no curve) says why; whether it may happen at all is RandomPointSetsKeepEveryClaim's question.
        EXPECT_FALSE(r.outcome.message.empty());
        return;
    }
    const std::vector<double>& u = r.interpolant->node_parameters;
    ASSERT_EQ(static_cast<long>(u.size()), p.rows() + (closed ? 1 : 0));
    EXPECT_EQ(u.front(), r.interpolant->curve->t_min()) << "the first node is the range's start";
    EXPECT_EQ(u.back(), r.interpolant->curve->t_max()) << "the last node is the range's end";
    const double extent = (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm();
    // The curve in u, and in the method's parameter τ (what Python's interpolate returns).
    std::optional<cagd::methods::MethodParameterCurve> wrapped;
    ASSERT_NO_THROW(wrapped.emplace(*r.interpolant));
    const cagd::methods::MethodParameterCurve& in_tau = *wrapped;
    for (const cagd::Curve* curve :
         {static_cast<const cagd::Curve*>(r.interpolant->curve.get()), static_cast<const cagd::Curve*>(&in_tau)}) {
        const Eigen::RowVectorXd last = closed ? p.row(0) : p.row(p.rows() - 1);
        for (const auto& [t, point] :
             {std::pair{curve->t_min(), Eigen::RowVectorXd(p.row(0))}, std::pair{curve->t_max(), last}}) {
            const std::string at = (curve == &in_tau ? "tau = " : "u = ") + cagd::full_precision(t);
            Eigen::MatrixXd jet;
            ASSERT_NO_THROW(jet = curve->jet(t, 2)) << at;
            EXPECT_TRUE(jet.allFinite()) << at;
            EXPECT_LE((jet.row(0) - point).norm(), kEndPositionTolerance * extent) << at;
        }
    }
}

void check_every_configuration_at(long n) {
    for (const cagd::methods::Configuration& c : cagd::methods::configurations()) {
        const long count = c.claims.max_points > 0 ? std::min<long>(n, c.claims.max_points) : n;
        const bool iterative = c.method->iterative;
        const double turn = iterative ? kIterativeMaxTurn : std::numbers::pi;
        for (bool closed : {false, true}) {
            if (closed && !c.claims.supports_closed) continue;
            for (unsigned seed : {1u, 2u})
                expect_ends_interpolate(c, end_of_range_walk(count, seed, 0.0, turn), closed,
                                        "unit steps, seed " + std::to_string(seed));
            // Chords 10^6-fold: at 10^5 points the iterative methods end in no_convergence (seconds each).
            if (!(iterative && n >= 100000))
                expect_ends_interpolate(c, end_of_range_walk(count, 3u, 3.0, turn), closed, "chords 1e-3..1e3");
        }
    }
}

TEST(EveryMethodEndOfRange, TenPoints) { check_every_configuration_at(10); }
TEST(EveryMethodEndOfRange, ThousandPoints) { check_every_configuration_at(1000); }
TEST(EveryMethodEndOfRange, HundredThousandPoints) { check_every_configuration_at(100000); }

}  // namespace
