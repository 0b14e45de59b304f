#pragma once
/// @file
/// The minimum pseudo-energy J(θ0, θ1) = min_{r0,r1>0} J(θ0, θ1, r0, r1) and its minimisers
/// r0(θ0, θ1), r1(θ0, θ1) (pseudo_energy eq 8), with the segment length L(θ0, θ1) and the signed
/// area S(θ0, θ1) at the minimiser (section 5), the segment type (eq 14), and
/// J(θ) = min_{θ1} J(θ, θ1) with its minimiser θ1(θ) (eq 11).
///
/// Variables. Both minimisers work in ρ_i = log r_i, so r_i > 0 holds by construction.
/// J → ∞ as r_i → 0 (a cusp forms at the end, E grows like log(1/r_i)) and J grows like a
/// positive quadratic in (r0, r1) as r → ∞ (section 2), so a minimum exists for every direction
/// pair the collinear nodes below excepted. It need not be unique, and J has further local
/// minima, some within 0.1 % of the global one, so both paths start from a scan of
/// (ρ0, ρ1) ∈ [log r_lo, log r_hi]² and descend from several seeds: the scan's discrete local
/// minima and the three lowest grid points away from them (a narrow diagonal valley need not show
/// as a discrete minimum), those within a factor 2 of the lowest.
///
/// Reference path (what the paper did, section 4.1): Romberg integration (rel 1e-13) and the
/// nonlinear conjugate-gradient method (Ceres GradientProblemSolver, Polak–Ribière) from the best
/// `starts` scan seeds and from the fast path's minimum and runner-up (a random-sample check found
/// a direction pair where only the fast path's seeding reached the global minimum, 0.02 % below
/// the reference scan's best); the lowest converged minimum is the answer. It also reports how many
/// distinct local minima it found and the runner-up, so the global choice is visible.
/// Independent check: `minimize_pseudo_energy_nlopt` (NLopt L-BFGS, Romberg values and
/// gradients) from the same scan minima.
/// Fast path: fixed 20-point Gauss–Legendre on the graded pieces, a coarse scan (8-point rule),
/// and damped Newton (analytic gradient, Hessian by central differences of it) from the best scan
/// minima. Both paths descend only from scan minima within a factor 2 of the lowest one.
///
/// Undefined nodes (section 4.1): when θ0, θ1 ∈ {0, ±π} both tangents are parallel to the chord
/// and the segment lies on the x axis. For (0, 0) the straight segment has J = 0 and r0, r1 are
/// not determined; for (±π, 0), (0, ±π), (±π, ±π) x'(t) changes sign on [0, 1] for every r0, r1,
/// so every admissible segment has a cusp and no minimum exists. These return type x and
/// outcome no_solution (J = 0 for (0, 0), J = +∞ otherwise; r0 = r1 = 0 meaning "undefined").
///
/// The descents are unconstrained in ρ: the scan box only seeds them (its edge points count as
/// seeds too), and a minimum outside the box — r0 → 0 as (θ0, θ1) → (±π, 0) — is still reached.
/// Failure modes: a minimiser that ends at r < 1e-8 or r > 1e8 returns no_solution ("minimiser
/// runs off to the boundary"); a descent that does not converge returns no_convergence.
#include <functional>
#include <numbers>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/fairness/hermite_segment.hpp"

namespace cagd::fairness {

/// The minimum of J = L²E over r0, r1 > 0 at (θ0, θ1) and what it found on the way (eq 8).
struct PseudoEnergyMinimum {
    double theta0 = 0.0;                ///< θ0
    double theta1 = 0.0;                ///< θ1
    double pseudo_energy = 0.0;         ///< J(θ0, θ1)
    double r0 = 0.0;                    ///< r0 at the minimum
    double r1 = 0.0;                    ///< r1 at the minimum
    double length = 0.0;                ///< L(θ0, θ1)
    double area = 0.0;                  ///< S(θ0, θ1)
    double strain_energy = 0.0;         ///< E at the minimiser
    SegmentType type = SegmentType::x;  ///< the segment type at the minimum (eq 14)
    double gradient_norm = 0.0;         ///< |∇_ρ J| at the answer
    double error_estimate = 0.0;        ///< quadrature error bound on J (reference path)
    int local_minima = 0;               ///< distinct local minima the descents reached (reference: the census)
    double runner_up = 0.0;             ///< lowest J among the other local minima (+∞ if none)
    double runner_up_r0 = 0.0;          ///< r0 of the runner-up
    double runner_up_r1 = 0.0;          ///< r1 of the runner-up
    long evaluations = 0;               ///< energy evaluations (all starts)
    Outcome outcome;                    ///< ok; no_solution at an undefined node; no_convergence
};

/// The box of (r0, r1) scanned for starting points, log-spaced.
struct ScanBox {
    double r_lo = 1e-2;  ///< smallest r
    double r_hi = 1e2;   ///< largest r
    int n = 41;          ///< scan points per axis, log-spaced
};

/// Options of the reference minimiser (Romberg energies, Ceres conjugate gradients).
struct ReferenceMinimizerOptions {
    ScanBox box{};                   ///< the scan for starting points
    int starts = 6;                  ///< descents from the lowest scan seeds
    double romberg_rel_tol = 1e-13;  ///< Romberg's relative tolerance per integral
    /// The census of local minima: a finer scan with the fast energy over a wider box, a Newton
    /// descent from every seed, and a reference descent from each distinct minimum it reaches, so
    /// that `local_minima` and the runner-up count minima in narrow valleys the coarse scan misses
    /// (at (−70°, 30°) a third minimum at r0 = 0.14, 1.4e-3 above J relative; at (60°, −60°) a
    /// pair at r ≈ (3.0, 0.029)). It covers r ∈ [1e-3, 1e3]²; n = 0 turns it off.
    ScanBox census{1e-3, 1e3, 121};
};

/// Options of the fast minimiser (Gauss–Legendre energies, Newton).
struct FastMinimizerOptions {
    ScanBox box{1e-2, 1e2, 21};  ///< the scan for starting points
    int starts = 6;              ///< descents from the lowest scan seeds
};

/// True for the undefined nodes (θ0, θ1 ∈ {0, ±π} to 1e-12).
bool is_undefined_node(double theta0, double theta1);

/// Reference path. Throws InvalidInput for angles outside [−π, π] or non-finite.
PseudoEnergyMinimum minimize_pseudo_energy_reference(double theta0, double theta1,
                                                     const ReferenceMinimizerOptions& opt = {});
/// Independent second minimiser (NLopt LD_LBFGS on the Romberg energy, no polish) from the same
/// scan minima (up to 4); the lowest result.
PseudoEnergyMinimum minimize_pseudo_energy_nlopt(double theta0, double theta1, const ScanBox& box = {});
/// A local minimum of J(θ0, θ1; r0, r1) over (r0, r1).
struct LocalMinimum {
    double pseudo_energy = 0.0;  ///< J
    double r0 = 0.0;             ///< r0
    double r1 = 0.0;             ///< r1
};
/// The census of the local minima of J(θ0, θ1; ·) over the box (ReferenceMinimizerOptions::census,
/// whose count and runner-up the reference minimiser reports): the grid lines' one-dimensional
/// minima refined onto the valley floors, Newton descents (fast energy) from the floors' minima,
/// minima merged as the same when closer than 1e-4 in log r, or than 1e-2 with J equal to 1e-9.
/// Lowest J first; empty at an undefined node. Throws InvalidInput for bad angles or box.
std::vector<LocalMinimum> local_minima_census(double theta0, double theta1, const ScanBox& box = {1e-3, 1e3, 121});
/// An independent census of the same minima (to validate local_minima_census): NLopt's
/// derivative-free BOBYQA on the fast J from `starts` points drawn log-uniformly in the box
/// (seeded: the same answer every run), each result confirmed by J not decreasing at eight
/// neighbours 1e-3 away in log r; two results are the same minimum when within 1e-2 in log r with
/// no barrier between them (J on the segment joining them never above the higher end by more than
/// 1e-9 relative). Lowest J first; empty at an undefined node.
/// The box is that of the census (ReferenceMinimizerOptions::census): minima on its boundary are
/// not counted.
std::vector<LocalMinimum> local_minima_multistart(double theta0, double theta1, int starts = 300,
                                                  const ScanBox& box = {1e-3, 1e3, 0}, unsigned seed = 1);

/// Fast path. `warm` adds starting points (r0, r1), e.g. a neighbouring node's minimiser. Its
/// `local_minima` and runner-up come from its coarse scan (a lower bound on the count).
PseudoEnergyMinimum minimize_pseudo_energy(double theta0, double theta1, const FastMinimizerOptions& opt = {},
                                           const std::vector<Eigen::Vector2d>& warm = {});

/// The largest tangent magnitude measure_segment accepts: the strain integrand squares the
/// curvature numerator P'' × P' (of order r²), so r⁴ must stay well inside double range (1e308).
inline constexpr double kMaxSegmentMagnitude = 1e60;

/// Evaluate the measures of the segment (θ0, θ1, r0, r1) into a PseudoEnergyMinimum record (fast
/// quadrature); used to report a given (r0, r1). Throws InvalidInput for angles outside [−π, π]
/// and unless 0 < r0, r1 ≤ kMaxSegmentMagnitude; a measure that is not finite all the same gives
/// the outcome not_representable (never a NaN in an ok record).
PseudoEnergyMinimum measure_segment(double theta0, double theta1, double r0, double r1);

/// J(θ) = min_{θ1 ∈ [−π, π]} J(θ, θ1) and θ1(θ) (eq 11): a scan of θ1 with step `scan_step`
/// (radians) over the fast J(θ, θ1), then Brent's method (Boost.Math) on the best bracket.
struct AngleMinimum {
    double theta = 0.0;          ///< θ
    double theta1 = 0.0;         ///< θ1(θ), the minimiser
    double pseudo_energy = 0.0;  ///< J(θ)
    Outcome outcome;             ///< ok, or why there is no minimum
};
/// The default scan: kEndAngleScanSteps steps of 2° from −π to π (181 angles).
constexpr int kEndAngleScanSteps = 180;
/// J(θ) and θ1(θ) at one θ (see above), with the fast J.
AngleMinimum minimize_over_end_angle(double theta, double scan_step = 2 * std::numbers::pi / kEndAngleScanSteps);
/// The same scan and Brent refinement on a given J(θ, ·) (e.g. an interpolated table); j_of returns
/// +∞ where J is undefined.
AngleMinimum minimize_over_end_angle(double theta, const std::function<double(double)>& j_of, double scan_step);
/// The second half of both: given J at the scan angles t (increasing, J = +∞ where undefined), Brent's
/// method on j_of over the bracket around the smallest; the scan's best point is kept when Brent's
/// is not lower. Lets a caller take the scan from values it already has (a table's nodes).
AngleMinimum refine_end_angle_scan(double theta, const std::vector<double>& t, const std::vector<double>& v,
                                   const std::function<double(double)>& j_of);
/// The J that the end-angle scan uses for one fast minimum: its J, +∞ where it failed, and at the
/// undefined nodes 0 (straight, θ = θ1 = 0) or +∞.
double end_angle_energy(const PseudoEnergyMinimum& m);
/// The same for the fast minimum at (θ, θ1), minimised here.
double end_angle_energy(double theta, double theta1);

}  // namespace cagd::fairness
