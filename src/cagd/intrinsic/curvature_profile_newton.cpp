#include "cagd/intrinsic/curvature_profile_design.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/intrinsic/detail/design_system.hpp"
#include "cagd/numeric/banded_or_sparse_lu.hpp"
#include "cagd/numeric/sparse_lu.hpp"

namespace cagd::intrinsic {

namespace detail {

std::string worst_equation(const CurvatureProfileProblem& P, const Eigen::VectorXd& f) {
    Eigen::Index i = 0;
    f.cwiseAbs().maxCoeff(&i);
    return design_equation_labels(P)[static_cast<std::size_t>(i)] + " (|f| = " + full_precision(std::abs(f(i))) + ")";
}

CurvatureProfileSolution sized_solution(const CurvatureProfileProblem& P, const Eigen::VectorXd& start,
                                        const std::string& who) {
    CurvatureProfileSolution sol;
    sol.unknowns = design_unknowns(P);
    sol.equations = design_equations(P);
    if (start.size() != sol.unknowns)
        fail_input(who, "start vector needs " + std::to_string(sol.unknowns) + " entries (eq 2), got " +
                            std::to_string(start.size()));
    return sol;
}

void finish_ok(const CurvatureProfileProblem& P, CurvatureProfileSolution& sol) {
    sol.curve.emplace(P.points.row(0).transpose(), TangentAngleSpline::from_unknowns(P.layout, sol.u));
}

}  // namespace detail

using detail::DesignWorkspace;
using detail::finish_ok;
using detail::worst_equation;

namespace {

// Newton's safeguards. The Moore–Penrose step treats singular values below kRankThreshold · σ_max
// as zero: the Jacobian's entries are O(1) in the data scale and exact, so 1e-10 separates true
// rank deficiency (σ ~ ε) from conditioning. A step shorter than kStalledStep · (1 + ‖u‖∞) is the
// rounding of u: Newton has settled. A step may shrink a span length to kKeptLengthFraction of
// itself at most (halving λ until it does), so lengths stay positive.
constexpr double kRankThreshold = 1e-10;
constexpr double kStalledStep = 1e-13;
constexpr double kKeptLengthFraction = 0.2;
// A settled iterate (its step below kStalledStep · (1 + ‖u‖∞), the stall radius r) whose residual is
// at most kReachMultiple · ‖J‖∞ · r could be left by a root within r of it (to first order
// |f(u)| ≤ ‖J‖∞ |u − u*|): the residual a root can leave at the resolution of u, which a square
// regular system's Newton step (f = J δ, |f|∞ ≤ ‖J‖∞ |δ|∞) always meets when it settles. The
// multiple allows for the rounding of the step's solve.
constexpr double kReachMultiple = 2.0;
// A step below the stall radius is still taken when it multiplies the residual by at most this.
constexpr double kSettledContraction = 0.5;

}  // namespace

std::vector<double> CurvatureProfileSolution::segment_lengths() const {
    std::vector<double> out;
    if (!curve) return out;
    return curve->tangent_angle().segment_lengths();
}

CurvatureProfileSolution solve_curvature_profile(const CurvatureProfileProblem& P, const Eigen::VectorXd& start,
                                                 const NewtonOptions& options) {
    const std::string who = "intrinsic::solve_curvature_profile";
    require_valid_problem(P, who);
    if (options.max_iterations < 1 || !(options.tolerance > 0))
        fail_input(who, "needs max_iterations ≥ 1 and tolerance > 0");
    if (!(options.required_contraction >= 0 && options.required_contraction < 1))
        fail_input(who, "needs 0 ≤ required_contraction < 1, got " + full_precision(options.required_contraction));
    CurvatureProfileSolution sol = detail::sized_solution(P, start, who);
    const int l = P.layout.independent_lengths();
    for (int i = 0; i < l; ++i)
        if (!(start(i) > 0) || !std::isfinite(start(i)))
            fail_input(who, "start length S_" + std::to_string(i) + " = " + full_precision(start(i)) +
                                " (finite and > 0 required)");
    if (options.step != NewtonStep::pseudo_inverse && sol.equations != sol.unknowns)
        fail_input(who, std::string("the ") + (options.step == NewtonStep::sparse_lu ? "sparse" : "banded") +
                            " LU step needs a square system; this one has " + std::to_string(sol.equations) +
                            " equations and " + std::to_string(sol.unknowns) + " unknowns (use the pseudo-inverse)");
    const double tol = options.tolerance;  // the equations are dimensionless (design_system)
    // The banded step says which LU it took once the band is known (below).
    const char* method = options.step == NewtonStep::pseudo_inverse ? "Newton with the Moore–Penrose step"
                         : options.step == NewtonStep::banded_lu    ? "Newton with banded LU"
                                                                    : "Newton with sparse LU";
    sol.u = start;
    // The Jacobian's sparsity pattern depends on the layout only, so its symbolic analysis (the
    // column ordering, a tenth of a sparse step's cost) is done once and redone only if the
    // pattern ever differs; the numeric factorisation is the same either way.
    numeric::BandedOrSparseLu lu;  // banded_lu: the band of the analysed pattern, when narrow
    std::vector<int> analysed_outer, analysed_inner;
    DesignWorkspace workspace;
    DesignSystem sys, trial;
    double previous_residual = std::numeric_limits<double>::infinity();
    for (int it = 0;; ++it) {
        // A diverging iterate winds ψ by hundreds of turns between neighbouring ordinates; the
        // integrals of such a segment cost O(turning) and mean nothing: stop it as unconverged.
        const Eigen::VectorXd ordinates = sol.u.tail(P.layout.ordinates());
        const double turning = ordinates.size() > 1
                                   ? (ordinates.tail(ordinates.size() - 1) - ordinates.head(ordinates.size() - 1))
                                         .lpNorm<Eigen::Infinity>()
                                   : 0.0;
        if (!(turning <= kMaxOrdinateTurning)) {
            sol.outcome = {Status::no_convergence,
                           std::string(method) + " diverged at iteration " + std::to_string(it) +
                               ": neighbouring tangent-angle ordinates differ by " + full_precision(turning) +
                               " rad (limit " + full_precision(kMaxOrdinateTurning) + ")"};
            return sol;
        }
        design_system_into(P, sol.u, true, workspace, sys);
        const double res = sys.f.lpNorm<Eigen::Infinity>();
        if (!std::isfinite(res)) {
            sol.outcome = {Status::no_convergence,
                           std::string(method) + ": the residual became non-finite at iteration " + std::to_string(it)};
            return sol;
        }
        if (res <= tol) {
            sol.history.push_back({it, res, 0.0, 1.0, sol.rank});
            finish_ok(P, sol);
            return sol;
        }
        if (options.required_contraction > 0 && it > 0 && !(res <= options.required_contraction * previous_residual)) {
            sol.history.push_back({it, res, 0.0, 1.0, sol.rank});
            sol.outcome = {Status::no_convergence,
                           std::string(method) + " from the given start does not contract: ‖f‖∞ = " +
                               full_precision(res) + " after " + full_precision(previous_residual) +
                               " (required: at most " + full_precision(options.required_contraction) + " of it)"};
            return sol;
        }
        previous_residual = res;
        if (it == options.max_iterations) {
            sol.history.push_back({it, res, 0.0, 1.0, sol.rank});
            sol.outcome = {Status::no_convergence,
                           std::string(method) + " from the given start did not reach ‖f‖∞ ≤ " + full_precision(tol) +
                               " in " + std::to_string(options.max_iterations) +
                               " iterations: ‖f‖∞ = " + full_precision(res) + ", worst equation " +
                               worst_equation(P, sys.f) + "; " + std::to_string(sol.equations) + " equations, " +
                               std::to_string(sol.unknowns) + " unknowns, rank " + std::to_string(sol.rank)};
            return sol;
        }
        Eigen::VectorXd delta;
        if (options.step == NewtonStep::pseudo_inverse) {
            // The threshold before the decomposition: the Z factor is built for the rank the
            // threshold gives at compute time, and solve() applies it for the rank it gives then.
            // Set afterwards, a lower rank would make solve() apply Z reflectors never computed.
            Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
            cod.setThreshold(kRankThreshold);
            cod.compute(Eigen::MatrixXd(sys.jacobian));
            sol.rank = static_cast<int>(cod.rank());
            delta = cod.solve(sys.f);
        } else {
            const Eigen::SparseMatrix<double>& J = sys.jacobian;
            const std::span<const int> outer(J.outerIndexPtr(), static_cast<std::size_t>(J.outerSize()) + 1),
                inner(J.innerIndexPtr(), static_cast<std::size_t>(J.nonZeros()));
            if (!J.isCompressed() ||
                !std::equal(outer.begin(), outer.end(), analysed_outer.begin(), analysed_outer.end()) ||
                !std::equal(inner.begin(), inner.end(), analysed_inner.begin(), analysed_inner.end())) {
                if (options.step == NewtonStep::banded_lu && numeric::BandedLu::available()) {
                    DesignBandOrdering order = design_band_ordering(P);
                    lu.analyze(J, std::move(order.rows), std::move(order.columns), kMaxBandStorageRows);
                } else {
                    lu.analyze(J, {}, {}, 0);
                }
                method = lu.banded() ? "Newton with banded LU" : "Newton with sparse LU";
                analysed_outer.assign(outer.begin(), outer.end());
                analysed_inner.assign(inner.begin(), inner.end());
            }
            if (!lu.factorize(J)) {
                sol.outcome = {Status::no_convergence, std::string(method) +
                                                           ": the Jacobian is singular at iteration " +
                                                           std::to_string(it) + " (use the pseudo-inverse step)"};
                return sol;
            }
            delta = lu.solve(sys.f);
        }
        if (!delta.allFinite()) {
            sol.outcome = {Status::no_convergence,
                           std::string(method) + ": non-finite step at iteration " + std::to_string(it)};
            return sol;
        }
        double lambda = 1.0;
        for (int i = 0; i < l; ++i)
            while (sol.u(i) - lambda * delta(i) < kKeptLengthFraction * sol.u(i)) lambda *= 0.5;
        const double step = lambda * delta.lpNorm<Eigen::Infinity>();
        sol.history.push_back({it, res, step, lambda, sol.rank});
        if (step <= kStalledStep * (1.0 + sol.u.lpNorm<Eigen::Infinity>())) {
            // A step at u's resolution that still halves the residual is taken (a curvature row
            // turns a difference of neighbouring ordinates into f: its last quadratic step is short).
            design_system_into(P, sol.u - lambda * delta, false, workspace, trial);
            if (trial.f.lpNorm<Eigen::Infinity>() <= kSettledContraction * res) {
                sol.u -= lambda * delta;
                continue;
            }
            // Settled above the tolerance. With a regular Jacobian and a residual a root at the step's
            // resolution could leave: converged as far as double precision goes. Otherwise inconsistent
            // conditions only with evidence — a rank below the unknowns, or more equations than unknowns
            // (a least-squares point); a regular square system settled above that is the solver's failure.
            const double radius = kStalledStep * (1.0 + sol.u.lpNorm<Eigen::Infinity>());
            const double reach = kReachMultiple *
                                 (sys.jacobian.cwiseAbs() * Eigen::VectorXd::Ones(sys.jacobian.cols())).maxCoeff() *
                                 radius;
            const bool full_rank = options.step != NewtonStep::pseudo_inverse || sol.rank == sol.unknowns;
            if (full_rank && res <= reach) {
                sol.history.back().step = 0.0;  // the final record: the step was not taken
                sol.history.back().damping = 1.0;
                finish_ok(P, sol);
                return sol;
            }
            const std::string found =
                "‖f‖∞ = " + full_precision(res) + " above the tolerance " + full_precision(tol) + " and " +
                full_precision(res / reach) + " times what a root within the step's resolution " +
                full_precision(radius) + " could leave (worst equation " + worst_equation(P, sys.f) + "; " +
                std::to_string(sol.equations) + " equations, " + std::to_string(sol.unknowns) + " unknowns, " +
                (sol.rank < 0 ? std::string("a regular LU") : "rank " + std::to_string(sol.rank)) + ")";
            if (!full_rank || sol.equations > sol.unknowns)
                sol.outcome = {Status::no_solution, std::string(method) + " settled on a least-squares point: " +
                                                        found + ": the conditions are inconsistent for these points"};
            else
                sol.outcome = {Status::no_convergence,
                               std::string(method) + " settled with a regular Jacobian: " + found +
                                   ": the solver failed, which does not show that no curve exists"};
            return sol;
        }
        sol.u -= lambda * delta;
    }
}

CurvatureProfileSolution solve_curvature_profile(const CurvatureProfileProblem& P, const NewtonOptions& options) {
    return solve_curvature_profile(P, c2_start(P), options);
}

CurvatureProfileProblem clothoid_spline_with_end_angles(const PointList& points, double start_angle, double end_angle) {
    const char* who = "intrinsic::clothoid_spline_with_end_angles";
    if (points.rows() < 2) fail_input(who, "needs at least 2 points, got " + std::to_string(points.rows()));
    if (!std::isfinite(start_angle) || !std::isfinite(end_angle))
        fail_input(who, "end angles " + full_precision(start_angle) + ", " + full_precision(end_angle) +
                            " (finite radians required)");
    const std::vector<SegmentShape> free(static_cast<std::size_t>(points.rows() - 1), SegmentShape::free);
    const KnotLayout layout = span_layout(free);
    CurvatureProfileProblem problem{points, layout, segment_shapes(layout, free), {}, false, 0};
    problem.conditions.push_back({.kind = DesignCondition::Kind::tangent_angle, .index = 0, .value = start_angle});
    problem.conditions.push_back(
        {.kind = DesignCondition::Kind::tangent_angle, .index = layout.segments(), .value = end_angle});
    require_valid_problem(problem, who);
    return problem;
}

void add_natural_open_ends(CurvatureProfileProblem& problem) {
    if (problem.closed || problem.shapes.empty()) return;
    if (problem.shapes.front() == SegmentShape::free)
        problem.conditions.push_back({DesignCondition::Kind::curvature, 0, 0.0, false});
    if (problem.shapes.back() == SegmentShape::free)
        problem.conditions.push_back({DesignCondition::Kind::curvature, problem.layout.segments(), 0.0, true});
}

CurvatureProfileSolution solve_curvature_profile_auto(const CurvatureProfileProblem& problem,
                                                      const NewtonOptions& options) {
    return solve_curvature_profile_auto(problem, c2_start(problem), options);
}

CurvatureProfileSolution solve_curvature_profile_auto(const CurvatureProfileProblem& problem,
                                                      const Eigen::VectorXd& start, const NewtonOptions& options) {
    // The Moore–Penrose step forms the Jacobian densely: n² doubles and O(n³) work per iteration
    // Above 2000 unknowns the sparse-LU outcome is the answer.
    constexpr int kDenseFallbackUnknowns = 2000;
    // Above this the LU step goes first: from about 60 unknowns on, a sparse or banded LU solve
    // costs less than the dense one.
    constexpr int kLuStepAboveUnknowns = 64;
    const int m = design_equations(problem), n = design_unknowns(problem);
    if (m == n && n > kLuStepAboveUnknowns) {
        NewtonOptions lu = options;
        lu.step = NewtonStep::banded_lu;
        CurvatureProfileSolution sol = solve_curvature_profile(problem, start, lu);
        if ((sol.outcome.ok() && sol.curve) || n > kDenseFallbackUnknowns) return sol;
    }
    NewtonOptions dense = options;
    dense.step = NewtonStep::pseudo_inverse;
    return solve_curvature_profile(problem, start, dense);
}

}  // namespace cagd::intrinsic
