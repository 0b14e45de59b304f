#pragma once
/// @file
/// Differential and integral measures of any Curve (docs/design.md: computed once, here).
///
///   curvature κ(t) and signed curvature: from frenet_jet (analysis/frenet_jet.hpp, the one kernel)
///   arc length L = ∫ |r'(t)| dt,  enclosed (signed) area A = ½ ∮ (x y' − y x') dt,
///   bending energy E = ∫ κ² ds = ∫ κ² |r'| dt.
/// Integrals are taken piece by piece between Curve::breakpoints() with a 20-point
/// Gauss–Legendre rule split into `pieces` sub-intervals (fast path), or with Romberg to
/// rel 1e-13 (reference path, `romberg_arc_length`). For polynomial curves the area
/// integrand is a polynomial and the rule is exact to rounding for degree ≤ 19.
/// Preconditions: |r'(t)| > 0 where curvature is asked (InvalidInput names t otherwise); curves of
/// dimension 1–3 (the integrands evaluate into a fixed-capacity JetMatrix, core/curve.hpp; a
/// higher dimension throws InvalidInput).
#include <string>

#include "cagd/core/curve.hpp"
#include "cagd/core/points.hpp"
#include "cagd/numeric/romberg.hpp"

namespace cagd::analysis {

/// Curvature κ(t) ≥ 0 (dimension 2 or 3).
double curvature(const Curve& c, double t);
double signed_curvature(const Curve& c, double t);  ///< planar curves only
/// The curvature vector κN = (r'' − (r''·T) T)/|r'|², T = r'/|r'|, from rows 1 and 2 of a jet (any
/// dimension, any parameter: it is geometric). Compare one-sided jets at a join to measure G2.
Eigen::VectorXd curvature_vector(const Eigen::MatrixXd& jet);
/// Arc length over the whole curve (Gauss–Legendre, `pieces` sub-intervals per piece).
double arc_length(const Curve& c, int pieces = 4);
/// Arc length over [a, b] ⊆ [t_min, t_max].
double arc_length(const Curve& c, double a, double b, int pieces = 4);
/// The reference arc length: Romberg to rel_tol on every piece.
numeric::RombergResult romberg_arc_length(const Curve& c, double rel_tol = 1e-13);
/// Adaptive Gauss–Kronrod (Boost.Math, 31 points, depth ≤ 15) per piece: robust where the speed
/// nearly vanishes (near-cusps), where Romberg's uniform refinement needs millions of evaluations.
double adaptive_arc_length(const Curve& c, double rel_tol = 1e-10);
double enclosed_area(const Curve& c);  ///< planar; signed, CCW positive
/// The signed area enclosed by the curve and the straight chord from its end back to its start
/// (= enclosed_area for a closed curve).
double area_closed_by_chord(const Curve& c);

/// Arc length for a user's curve (`cagd analyze --in`): adaptive Gauss–Kronrod (31 points, Boost)
/// per piece to rel 1e-12, with Boost's error estimate summed over the pieces. Milliseconds where
/// Romberg to 1e-13 takes seconds per piece (and on some pieces stalls at rounding, unconverged).
struct ArcLength {
    double value = 0.0;           ///< the arc length
    double error_estimate = 0.0;  ///< its error estimate
};
/// Arc length by the reference path with its error estimate.
ArcLength accurate_arc_length(const Curve& c);
/// Bending energy ∫ κ² ds over the whole curve.
double bending_energy(const Curve& c, int pieces = 4);
/// The same on [a, b] inside one polynomial piece (no breakpoint strictly inside, not checked):
/// O(pieces) evaluations and no breakpoint search, for loops over the pieces of long curves.
double piece_arc_length(const Curve& c, double a, double b, int pieces);
/// ∫ κ² ds over [a, b] inside one polynomial piece, `pieces` sub-intervals.
double piece_bending_energy(const Curve& c, double a, double b, int pieces);
/// Both from one derivative evaluation per quadrature node: {piece_arc_length, piece_bending_energy}
/// bit for bit.
std::pair<double, double> piece_length_and_bending_energy(const Curve& c, double a, double b, int pieces);
/// Bending energy over [a, b] ⊆ [t_min, t_max].
double bending_energy(const Curve& c, double a, double b, int pieces = 4);

/// max_t |a(t) − b(t)| over `samples_per_piece` uniform samples between the breakpoints of
/// both curves, on the common parameter interval. The curves must share the parameter.
double max_distance_same_parameter(const Curve& a, const Curve& b, int samples_per_piece = 64);
/// The same restricted to [t0, t1].
double max_distance_same_parameter(const Curve& a, const Curve& b, double t0, double t1, int samples = 257);

/// Planar: (a(t) − b(t)) · n_b(t), n_b the unit left normal of b at t (positive = a lies to the
/// left of b). Precondition: b'(t) ≠ 0.
double normal_offset(const Curve& a, const Curve& b, double t);

/// The tangent's total turn of a closed planar curve over [t_min, t_max], in turns: the signed
/// angles between the tangents r′ at `samples_per_piece` + 1 uniform samples of every piece, summed,
/// divided by 2π (each step must turn by less than π, which 64 samples a piece ensure for every
/// registry method on any data). For a closed G1 curve it is its turning number, an integer.
/// Precondition: a planar curve with r′ ≠ 0 at the samples (InvalidInput names t).
double tangent_turns(const Curve& c, int samples_per_piece = 64);
/// The turning number of the closed polygon through `points` (planar, consecutive points distinct):
/// its exterior angles, each in (−π, π], summed and divided by 2π.
int polygon_turning_number(const PointList& points);
/// How much longer than its polygon's perimeter a closed curve may be before it is flagged (a fair
/// interpolant is at most a few per cent longer).
inline constexpr double kLoopingLengthFactor = 1.5;
/// A closed planar curve through `points`, of arc length `length`, is flagged when its turning
/// number differs from its polygon's (it loops where the polygon does not), or its length exceeds
/// kLoopingLengthFactor times the polygon's perimeter. Returns the reason in one line ("turning
/// number 1 against the polygon's 0; length 1.62 × the polygon's perimeter …"), or "" when the
/// curve is not flagged.
std::string closed_curve_anomaly(const Curve& c, const PointList& points, double length);

}  // namespace cagd::analysis
