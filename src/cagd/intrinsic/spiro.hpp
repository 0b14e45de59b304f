#pragma once
/// @file
/// Spiro: the interpolating spline whose curvature is a cubic polynomial of arc length on every span
/// and which is G4 at every point (R. Levien, From Spiral to Spline: Optimal Techniques in
/// Interactive Curve Design, PhD thesis, UC Berkeley, 2009, ch. 8; the 'o' points of libspiro).
/// It is the degree-4 member of the curvature-profile family (curvature_profile_design.hpp): ψ a
/// quartic B-spline in arc length with a simple knot at every interior point. Open ends take
/// κ' = κ'' = 0 (libspiro's '{' and '}' ends); a closed curve is G4 where it closes.
///
/// Two formulations of the same equations, each the other's check:
///   chordwise (Levien's, solve_spiro_chordwise): per span i, four coefficients k_i of the curvature
///     of a unit-length spiral, κ_n(u) = k0 + k1 u + k2 u²/2 + k3 u³/6, u ∈ [−1/2, 1/2], and
///     θ_n(u) = ∫_0^u κ_n. The spiral's chord Z = ∫ e^{iθ_n} du is scaled and turned onto the span's
///     chord c_i e^{iφ_i}, so the span interpolates its points by construction: arc length
///     ℓ_i = c_i/|Z|, ψ = φ_i − arg Z + θ_n. The equations are G4 at each point (ψ, κ = κ_n/ℓ,
///     κ' = κ_n'/ℓ², κ'' = κ_n''/ℓ³ equal on both sides; the angles modulo 2π, as libspiro; the
///     curvatures scaled by the mean chord) and the ends' κ_n' = κ_n'' = 0. Newton from k = 0 (every
///     span straight), as libspiro starts, with the exact Jacobian (∂Z/∂k from the integrals'
///     Bernstein weights) and sparse LU; after each step k0 is reduced to [−2π, 2π], as Levien's
///     iteration does.
///   arc length (curvature_profile eq 2–6, solve_curvature_profile): the chordwise solution becomes
///     the unknowns u = (ℓ_0.., de Boor ordinates of ψ) through blossoms (each ordinate is the
///     blossom of a neighbouring span's polynomial at its knots) and Newton polishes it to
///     ‖f‖∞ ≤ 1e−11, its rows dimensionless (positions relative to their chord; not 1e−12: the
///     rounding floor of the interpolation rows grows with the winding of ψ, and Spiro's loops
///     wind it far). The arc-length Newton from the
///     C2 interpolant is not tried where the chordwise one fails: on 10^4 random walks it rescued
///     1 % of the sets, found other solutions than the chordwise one, and cost twelve times as long.
/// The chordwise unknowns are libspiro's ks, so the two libraries can be compared number by number
/// (tests/methods/spiro_against_libspiro.cpp).
///
/// Outcomes (returned): ok, or no_convergence when the chordwise Newton does not converge (Spiro has
/// no solution for some points and libspiro fails on them too, e.g. a tight zigzag; on long point
/// lists one region without a solution fails the whole), or when the polish does not.
/// Preconditions (InvalidInput): planar, finite points, no two consecutive equal (closed: last ≠
/// first); open ≥ 2 points, closed ≥ 3.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/core/points.hpp"
#include "cagd/intrinsic/curvature_profile_design.hpp"

namespace cagd::intrinsic {

/// The design problem of Spiro: the degree-4 layout, free spans, κ' = κ'' = 0 at open ends, G4 closure.
CurvatureProfileProblem spiro_problem(const PointList& points, bool closed);

/// Levien's chordwise solution: per span, k_i = (k0, k1, k2, k3), its arc length and its ψ.
struct SpiroChordwiseSolution {
    Outcome outcome;                        ///< ok, or no_convergence with the residual and the iteration
    std::vector<std::array<double, 4>> ks;  ///< libspiro's ks, one row per span
    std::vector<double> arc_lengths;        ///< ℓ_i = c_i / |Z_i|
    std::vector<double> start_angles;       ///< ψ at the start of each span (unwrapped along the curve)
    int iterations = 0;                     ///< Newton iterations taken
    double residual = 0.0;                  ///< ‖f‖∞ of the last iterate (dimensionless)
    int turns = 0;                          ///< closed: the turning number of the solution, (ψ(L) − ψ(0))/2π
};
/// Levien's chordwise equations at given ks: f (4 per span; open: κ_n' and κ_n'' at the start, the
/// G4 rows of each interior point, κ_n' and κ_n'' at the end) and its exact sparse Jacobian ∂f/∂k.
struct SpiroChordwiseSystem {
    Eigen::VectorXd f;                     ///< the residuals
    Eigen::SparseMatrix<double> jacobian;  ///< ∂f/∂k, k ordered span by span
};
/// f and J at ks (one row per span). InvalidInput when a spiral's chord vanishes.
SpiroChordwiseSystem spiro_chordwise_system(const PointList& points, bool closed,
                                            const std::vector<std::array<double, 4>>& ks);

/// Newton on Levien's chordwise equations from k = 0 (see above).
SpiroChordwiseSolution solve_spiro_chordwise(const PointList& points, bool closed, int max_iterations = 60);

/// The unknowns u of spiro_problem (lengths, then de Boor ordinates) of a chordwise solution.
Eigen::VectorXd spiro_unknowns(const CurvatureProfileProblem& problem, const SpiroChordwiseSolution& chordwise);

/// Spiro through the points: the chordwise solution polished by the arc-length Newton.
struct SpiroSolution {
    CurvatureProfileProblem problem;    ///< spiro_problem(points, closed)
    CurvatureProfileSolution solution;  ///< the arc-length solution (its curve when ok; else the outcome)
    SpiroChordwiseSolution chordwise;   ///< the chordwise Newton, converged or not
};
/// The solve described above.
SpiroSolution solve_spiro(const PointList& points, bool closed);
/// Continuation (a drag's next frame, the locality footprint's moved point): the arc-length Newton
/// started from `start`, the unknowns of an earlier solution on nearby open points of the same number,
/// and given up as soon as a step leaves more than `required_contraction` of the residual before it
/// (NewtonOptions::required_contraction). Where it is given up, for a closed curve (whose turning
/// number the chordwise solution decides) and for a start of another size: solve_spiro. When the
/// start serves, `chordwise` is not run (iterations 0). The result meets solve_spiro's tolerance, on
/// the solution branch of the start.
SpiroSolution solve_spiro_from(const PointList& points, bool closed, const Eigen::VectorXd& start,
                               double required_contraction);

}  // namespace cagd::intrinsic
