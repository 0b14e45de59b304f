#include "cagd/intrinsic/curvature_profile_design.hpp"

#if CAGD_WITH_CERES
#include <ceres/ceres.h>
#endif

#include <algorithm>
#include <string>

#include "cagd/core/errors.hpp"
#include "cagd/core/optional_dependencies.hpp"
#include "cagd/intrinsic/detail/design_system.hpp"

namespace cagd::intrinsic {

#if CAGD_WITH_CERES
namespace {

struct DesignResidual {
    const CurvatureProfileProblem* problem;
    int unknowns;
    bool operator()(double const* const* parameters, double* residuals) const {
        const Eigen::Map<const Eigen::VectorXd> u(parameters[0], unknowns);
        for (int i = 0; i < problem->layout.independent_lengths(); ++i)
            if (!(u(i) > 0)) return false;
        const Eigen::VectorXd f = design_system(*problem, u, false).f;
        std::copy(f.data(), f.data() + f.size(), residuals);
        return f.allFinite();
    }
};

}  // namespace

namespace {

// The Levenberg–Marquardt cross-check. Its Jacobian is a central difference (error ~ε^(2/3) ≈
// 4e-11 relative), so it is accepted at ‖f‖∞ ≤ kLmAcceptance, three digits above Newton's
// exact-Jacobian tolerance (NewtonOptions::tolerance, 1e-12): what it checks is the span lengths,
// to 1e-8 (fig2, fig3). Its own stopping rules are set below any reachable value so that only the
// iteration limit (LM takes tens of iterations here) or a stall ends it.
constexpr double kLmAcceptance = 1e-9;
constexpr int kLmIterations = 500;
constexpr double kLmFunctionTolerance = 1e-20, kLmGradientTolerance = 1e-20, kLmParameterTolerance = 1e-15;
// Span lengths are kept above this fraction of the data scale (a zero length is a degenerate span).
constexpr double kLmShortestSpan = 1e-6;

}  // namespace
#endif

CurvatureProfileSolution solve_curvature_profile_levenberg_marquardt(const CurvatureProfileProblem& P,
                                                                     const Eigen::VectorXd& start) {
    const std::string who = "intrinsic::solve_curvature_profile_levenberg_marquardt";
    require_valid_problem(P, who);
    require_built_with(OptionalDependency::ceres, who);
#if CAGD_WITH_CERES
    CurvatureProfileSolution sol = detail::sized_solution(P, start, who);
    sol.u = start;
    auto* cost =
        new ceres::DynamicNumericDiffCostFunction<DesignResidual, ceres::CENTRAL>(new DesignResidual{&P, sol.unknowns});
    cost->AddParameterBlock(sol.unknowns);
    cost->SetNumResiduals(sol.equations);
    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, sol.u.data());
    const double scale = detail::data_scale(P);
    for (int i = 0; i < P.layout.independent_lengths(); ++i)
        problem.SetParameterLowerBound(sol.u.data(), i, kLmShortestSpan * scale);
    ceres::Solver::Options opt;
    opt.minimizer_type = ceres::TRUST_REGION;
    opt.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    opt.linear_solver_type = ceres::DENSE_QR;
    opt.max_num_iterations = kLmIterations;
    opt.function_tolerance = kLmFunctionTolerance;
    opt.gradient_tolerance = kLmGradientTolerance;
    opt.parameter_tolerance = kLmParameterTolerance;
    opt.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(opt, &problem, &summary);
    const Eigen::VectorXd f = design_system(P, sol.u, false).f;
    const double res = f.lpNorm<Eigen::Infinity>();
    sol.history.push_back({static_cast<int>(summary.iterations.size()), res, 0.0, 1.0, -1});
    if (res <= kLmAcceptance) {
        detail::finish_ok(P, sol);
        return sol;
    }
    sol.outcome = {summary.termination_type == ceres::CONVERGENCE ? Status::no_solution : Status::no_convergence,
                   "Ceres Levenberg–Marquardt (" + summary.message + ") ended with ‖f‖∞ = " + full_precision(res) +
                       ", worst equation " + detail::worst_equation(P, f)};
    return sol;
#else
    (void)start;
    return {};
#endif
}

}  // namespace cagd::intrinsic
