#pragma once
/// @file
/// Composite interpolants designed through their curvature profile (curvature_profile, sections
/// 2–4, eq 2–6): Kuroda, Higashi, Saito, Watanabe.
///
/// Unknowns (eq 2): u = (S_0..S_{l−1}, B_0..B_q) — the independent segment lengths and the de Boor
/// ordinates of the tangent angle ψ(s) (tangent_angle_spline.hpp).
/// Equations f(u) = 0 (eq 3–5), in this order:
///   interpolation (eq 3), 2n rows: span i, Σ_{segments j of span i} Δw_j ∫_0^1 (cos ψ_j, sin ψ_j) dt
///     − (Δx_i, Δy_i) (open: n + 1 points; closed: n points and the closing span P_{n−1} → P_0);
///   shapes (eq 4, "reduce the degree of a segment"), on the Bézier ordinates b_{j,r} of ψ_j:
///     line   κ ≡ 0        b_r − b_0 = 0, r = 1..p                        (p rows)
///     arc    κ constant   b_{r+1} − 2b_r + b_{r−1} = 0, r = 1..p−1        (p − 1 rows)
///     linear_curvature    b_3 − 3b_2 + 3b_1 − b_0 = 0 (p = 3: a clothoid segment)     (1 row)
///   conditions (eq 4): tangent angle ψ(w_g) = θ; curvature κ(w_g) = c (one-sided where κ may jump);
///     curvature radius: κ(w_g) = 1/R; a segment length Δw_j = d (fixes a free split of a span);
///     beyond the paper, a curvature derivative κ^(d)(w_g) = c, 1 ≤ d ≤ p − 2 (Spiro's open ends),
///     the row times h^(d+1), h the chord of the segment's span, so that it is dimensionless;
///   closed curves (section 5): ψ(L) − ψ(0) = 2π·turns and κ(L) = κ(0); with closing_continuity
///     G > 2 also κ^(d)(L) = κ^(d)(0) for d = 1..G − 2 (Spiro closes G4: d = 1, 2), times h^(d+1)
///     with h the mean of the first and last chords.
/// Every row is dimensionless, so that one tolerance means the same in each: an interpolation row
/// is divided by its span's chord |P_{i+1} − P_i|, a segment-length row by its span's chord, a
/// curvature (or radius) row multiplied by its span's chord (closed: the mean of the first and last),
/// angle and shape rows are in radians. The factors are data, not unknowns: J is scaled with f, and
/// a square system's Newton step is unchanged by them.
/// The paper's ψ has degree 2 or 3. Degree 4 (κ cubic in arc length, simple knots: G4) is Levien's
/// Spiro (R. Levien, From Spiral to Spline: Optimal Techniques in Interactive Curve Design, PhD
/// thesis, UC Berkeley, 2009, ch. 8), which the same unknowns, integrals and Newton iteration solve.
/// With m + 1 equations and N = l + q + 1 unknowns, Newton's method (eq 6) u ← u − J⁺ f(u); the
/// paper uses J⁻¹ and, when m < l + q, the Moore–Penrose inverse J⁺: we always take J⁺ (Eigen's
/// CompleteOrthogonalDecomposition, rank threshold 1e−10 relative), which equals J⁻¹ for a regular
/// square J, gives the minimum-norm step for fewer equations, and is also what a square but
/// rank-deficient system needs (Fig. 3's is: a redundant equation and a free direction). NewtonStep::
/// sparse_lu solves square systems with Eigen's SparseLU instead (O(n) per iteration); NewtonStep::
/// banded_lu with LAPACK's banded LU (numeric/banded_lu.hpp) on the band that ordering rows and
/// unknowns by their place along the curve gives (open curves of degree 2: 4 sub- and 4
/// superdiagonals), and with
/// SparseLU where that band is wide (a closed curve's closing rows join its ends) or the build has no
/// LAPACK. Both are partial-pivoting LUs of the same J: the steps agree to rounding.
/// Starting values (section 4): the chord-length parametric cubic C2 interpolant — span arc lengths
/// split evenly among a span's segments, and each B_i the C2 curve's tangent angle at its Greville
/// abscissa (unwrapped).
///
/// Jacobian: analytic in the integrals (∂/∂b_{j,r} of Δw_j ∫cos ψ_j = −Δw_j ∫ sin ψ_j B^p_r, and
/// ∂/∂Δw_j = ∫ cos ψ_j), chained with the exact derivatives of the Bézier ordinates with respect to
/// the de Boor ordinates and the local knots (the blossoming recurrence differentiated in forward mode
/// with ceres::Jet). Sparse: a row touches only the ≤ 2p − 1 segments around it. Tested against central
/// differences.
/// Positivity: a step that would shrink a length below a fifth of its value is halved until it does
/// not (recorded as the damping of the iteration); the paper's iteration is the undamped one.
///
/// Outcomes (returned, never thrown): ok when ‖f‖∞ ≤ tolerance (f dimensionless, above), or when the
/// iteration settles (its step below r = 1e−13·(1 + ‖u‖∞), the resolution of u, and no longer
/// halving ‖f‖∞ when tried) with a regular Jacobian and ‖f‖∞ ≤ 2‖J‖∞·r, the residual a root within
/// r could leave: the rows' rounding level, which a tolerance below it cannot beat; the history's
/// last record has that residual. no_solution only with
/// evidence: settled on a least-squares point above that level with a rank-deficient Jacobian or
/// more equations than unknowns — the conditions are inconsistent (e.g. an arc span no arc with
/// the given tangents joins). A square regular system settled above it is no_convergence, the
/// solver's failure, not evidence that no curve exists. no_convergence also when max_iterations
/// pass, or when an iterate diverges: neighbouring de Boor
/// ordinates B_i, B_{i+1} more than kMaxOrdinateTurning = 1000 rad apart (160 turns; the integrals
/// of eq 3 would cost O(turning) per segment; found by fuzzing, on a closed 6-point hairpin). The
/// message says what was tried, the residual, the rank, and the worst equation.
/// Sources, one concept each: the problem and its checks (curvature_profile_problem.cpp), the
/// system f and its Jacobian (curvature_profile_system.cpp), Newton (curvature_profile_newton.cpp),
/// the Ceres cross-check (curvature_profile_levenberg_marquardt.cpp), the windowed continuation
/// (curvature_profile_continuation.cpp); their shared internals in detail/design_system.hpp.
/// Preconditions (InvalidInput): ≥ 2 points (closed: ≥ 3), finite, no coincident consecutive
/// points (closed: last ≠ first); the layout's span count n matches the points; one shape per
/// segment; linear_curvature only for p = 3; conditions name existing breakpoints and finite values
/// (radius ≠ 0, length > 0); start vector of the right size with positive lengths.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <optional>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/core/points.hpp"
#include "cagd/intrinsic/intrinsic_curve.hpp"
#include "cagd/intrinsic/knot_difference_list.hpp"

namespace cagd::intrinsic {

/// The shape of a segment of ψ: free, a line (κ ≡ 0), an arc (κ constant) or a clothoid (κ linear, degree 3).
enum class SegmentShape { free, line, arc, linear_curvature };
/// "free", "line", "arc" or "clothoid".
const char* to_string(SegmentShape shape);

/// One prescribed condition of eq (4): tangent angle, curvature or its radius at a breakpoint, or a segment's length.
struct DesignCondition {
    /// What is prescribed: ψ, κ or R = 1/κ at a breakpoint, or a segment's length.
    enum class Kind { tangent_angle, curvature, curvature_radius, segment_length, curvature_derivative };
    Kind kind;               ///< what is prescribed
    int index;               ///< breakpoint g in 0..k (segment j in 0..k−1 for segment_length)
    double value;            ///< θ (radians), κ, R, Δw_j, or κ^(d)
    bool from_left = false;  ///< curvature and its derivatives: the segment ending at w_g (else the one starting there)
    int order = 1;           ///< curvature_derivative: d in 1..p − 2
};

/// The design problem: points, the knot layout of ψ, the segments' shapes and the conditions.
struct CurvatureProfileProblem {
    PointList points;                         ///< open: n + 1 rows; closed: n rows (the closing span added)
    KnotLayout layout;                        ///< n spans
    std::vector<SegmentShape> shapes;         ///< one per segment
    std::vector<DesignCondition> conditions;  ///< the prescribed conditions (eq 4)
    bool closed = false;                      ///< a closed curve (section 5)
    int turns = 0;               ///< closed: ψ(L) − ψ(0) = 2π·turns; 0 = the sign of the polygon's signed area
    int closing_continuity = 2;  ///< closed: G order where the curve closes, 2..p (rows: ψ, κ, κ', …)
};

/// "line,free,arc,…" (one shape per span; also "clothoid" = linear_curvature) → shapes.
std::vector<SegmentShape> parse_span_shapes(const std::string& text);
/// One shape per segment: each span's segments take the span's shape.
std::vector<SegmentShape> segment_shapes(const KnotLayout& layout, const std::vector<SegmentShape>& span_shapes);
/// The layout `cagd interpolate --method curvature-profile` uses: degree 2 (κ piecewise linear, as
/// Figs. 2–3), one segment per span, a double knot (G1: κ may jump) where a line or an arc meets
/// another span and a simple knot (G2) between free spans.
KnotLayout span_layout(const std::vector<SegmentShape>& span_shapes);

/// Throws InvalidInput (naming `who`) unless the problem meets the preconditions above.
void require_valid_problem(const CurvatureProfileProblem& problem, const std::string& who);

/// turns if set, else +1 for a counter-clockwise polygon (signed area ≥ 0) and −1 otherwise.
int closing_turns(const CurvatureProfileProblem& problem);

int design_unknowns(const CurvatureProfileProblem& problem);   ///< N = l + q + 1
int design_equations(const CurvatureProfileProblem& problem);  ///< m + 1
/// One label per equation ("interpolation x, span 3", "line, segment 2, b2 − b0", …).
std::vector<std::string> design_equation_labels(const CurvatureProfileProblem& problem);

/// f(u) and its sparse Jacobian.
struct DesignSystem {
    Eigen::VectorXd f;                     ///< f(u), m + 1 values, in the order above
    Eigen::SparseMatrix<double> jacobian;  ///< empty unless asked for
};
/// f(u) (and J(u) with `with_jacobian`) at the unknowns u.
DesignSystem design_system(const CurvatureProfileProblem& problem, const Eigen::VectorXd& u, bool with_jacobian = true);

/// The starting vector from the parametric cubic C2 interpolant.
Eigen::VectorXd c2_start(const CurvatureProfileProblem& problem);

/// An iterate whose neighbouring de Boor ordinates differ by more than this (radians) has diverged.
inline constexpr double kMaxOrdinateTurning = 1000.0;
/// The Newton step: J⁺ f (Moore–Penrose), or the LU solve of a square system: sparse (Eigen's
/// SparseLU), or banded (LAPACK) where the layout's band is narrow and sparse otherwise.
enum class NewtonStep { pseudo_inverse, sparse_lu, banded_lu };
/// Band storage rows (2kl + ku + 1) up to which NewtonStep::banded_lu factorises banded: every open
/// layout of degree ≤ 4 needs far fewer (degree 2: 13); a wider band is a closed curve's, whose
/// closing rows span all unknowns, and goes to SparseLU.
inline constexpr int kMaxBandStorageRows = 48;
/// The orderings that make J banded: row r of J at position rows[r], unknown c at columns[c]
/// (equations and unknowns sorted by their place along the curve: the segments they involve).
struct DesignBandOrdering {
    std::vector<int> rows;     ///< a permutation of the equations
    std::vector<int> columns;  ///< a permutation of the unknowns
};
/// The orderings above (numeric::BandedLu takes them).
DesignBandOrdering design_band_ordering(const CurvatureProfileProblem& problem);
/// Options of the Newton iteration.
struct NewtonOptions {
    NewtonStep step = NewtonStep::pseudo_inverse;  ///< the step
    int max_iterations = 50;                       ///< iterations before no_convergence
    double tolerance = 1e-12;                      ///< ‖f‖∞ ≤ tolerance (f dimensionless) is converged
    /// Give up (no_convergence) as soon as a step leaves ‖f‖∞ above this fraction of the residual
    /// before it; 0 = never. For starts from a nearby solution (continuation), from which Newton
    /// either converges quadratically or wanders: a start outside that basin is abandoned after a
    /// step or two instead of max_iterations (10^5 points with one point moved by a chord: 50
    /// wandering iterations, 13 s, against 5 from the design's own start, 3 s).
    double required_contraction = 0.0;
};
/// One Newton iteration, as the history records it.
struct NewtonRecord {
    int iteration;    ///< 0 = the start
    double residual;  ///< ‖f(u)‖∞ before the step
    double step;      ///< ‖Δu‖∞ taken (0 for the final record)
    double damping;   ///< 1 = the full Newton step
    int rank;         ///< of J (−1 for the sparse step)
};
/// The result of the design: the outcome, the unknowns, the history and the curve when ok.
struct CurvatureProfileSolution {
    Outcome outcome;                      ///< ok, no_solution or no_convergence (see above), with a message
    Eigen::VectorXd u;                    ///< the last iterate
    std::vector<NewtonRecord> history;    ///< one record per iteration
    int equations = 0;                    ///< m + 1
    int unknowns = 0;                     ///< N
    int rank = -1;                        ///< of the last Jacobian (−1: sparse LU steps)
    std::optional<IntrinsicCurve> curve;  ///< present when outcome.ok()

    std::vector<double> segment_lengths() const;  ///< Δw_j of the final iterate
};

/// Newton (eq 6) from the given start.
CurvatureProfileSolution solve_curvature_profile(const CurvatureProfileProblem& problem, const Eigen::VectorXd& start,
                                                 const NewtonOptions& options = {});
/// Newton (eq 6) from c2_start.
CurvatureProfileSolution solve_curvature_profile(const CurvatureProfileProblem& problem,
                                                 const NewtonOptions& options = {});

/// The clothoid-spline defaults shared by `cagd interpolate` and compare/: natural ends (κ = 0 at an
/// open end whose segment is free; lines and arcs already fix their curvature), appended to
/// problem.conditions; and the solve that picks the step — the banded LU step (sparse LU where the
/// band is wide) for square systems of more than 64 unknowns (O(n) per iteration), the
/// Moore–Penrose step otherwise or when the LU iteration
/// fails (a singular or unconverged iteration) on at most 2000 unknowns. Above 2000 unknowns a failed
/// LU iteration is returned as it is: the dense step would need n² doubles.
void add_natural_open_ends(CurvatureProfileProblem& problem);
/// The G1 Hermite problem with clothoids (two points: one clothoid arc, ψ quadratic in arc length)
/// and, through more points, the clothoid spline (every span free on span_layout: degree 2, G2
/// joins) whose ends take the tangent angles θ_0 = `start_angle` at the first point and θ_1 =
/// `end_angle` at the last (radians, from +x) instead of natural ends. Square: 2n interpolation
/// rows and two angle rows in 2n + 2 unknowns. InvalidInput for fewer than 2 points or a
/// non-finite angle (then as require_valid_problem).
CurvatureProfileProblem clothoid_spline_with_end_angles(const PointList& points, double start_angle, double end_angle);

/// The solve of the defaults above (the step chosen by size; the other options as given).
CurvatureProfileSolution solve_curvature_profile_auto(const CurvatureProfileProblem& problem,
                                                      const NewtonOptions& options = {});
/// The same from the given start.
CurvatureProfileSolution solve_curvature_profile_auto(const CurvatureProfileProblem& problem,
                                                      const Eigen::VectorXd& start, const NewtonOptions& options = {});

/// Spans on either side of the unsatisfied ones that continuation_start solves with them: an
/// interpolating spline's response to a moved point decays by a factor of about 0.27 per span (the
/// C2 cubic's 2 − √3; at most 1/2 for any chords), so 64 spans take it below 1e−19 of the move.
inline constexpr int kContinuationWindowSpans = 64;
/// A start for Newton from the solution `start` of nearby points (a drag's next frame, the locality
/// footprint's one moved point). Where the problem is an open curve of free spans on span_layout,
/// its conditions at the two ends only, and `start` leaves only the interpolation rows (eq 3) of the
/// spans i0..i1 above options.tolerance: the window of those spans widened by
/// kContinuationWindowSpans on each side (clipped to the curve; at most a quarter of it) is solved
/// alone — its ends held at start's tangent angles there, or at the curve's own end conditions —
/// and its lengths and de Boor ordinates are set into `start` (those whose knots lie inside the
/// window). Outside the window start already solves every row, and across its ends the change is
/// below rounding, so Newton from the result typically stops at its first evaluation (10^5 points,
/// one moved by a chord: 1 evaluation of f and J where start itself took 8). Otherwise, or when the
/// window's own solve fails, `start` unchanged. Newton decides either way; this only picks where
/// it begins. O(window) plus one evaluation of f (no Jacobian) on the whole.
Eigen::VectorXd continuation_start(const CurvatureProfileProblem& problem, const Eigen::VectorXd& start,
                                   const NewtonOptions& options = {});

/// The second solver: Ceres Levenberg–Marquardt on the same f, with its own central-difference
/// Jacobian (DynamicNumericDiffCostFunction) and lengths bounded below — independent of ours.
CurvatureProfileSolution solve_curvature_profile_levenberg_marquardt(const CurvatureProfileProblem& problem,
                                                                     const Eigen::VectorXd& start);

}  // namespace cagd::intrinsic
