#include "cagd/smoothing/elastic_space_curve.hpp"

#if CAGD_WITH_CERES
#include <ceres/ceres.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "cagd/core/optional_dependencies.hpp"
#include "cagd/numeric/gauss_legendre.hpp"
#include "cagd/smoothing/elastic_line.hpp"

namespace cagd::smoothing {

namespace {

// Cubic Hermite on [0, 1] scaled to length h: value, first and second x-derivatives.
template <typename T>
void hermite(const T* a, const T* b, int c, double h, double u, T& v, T& d1, T& d2) {
    const double p0 = 1 - 3 * u * u + 2 * u * u * u, q0 = 3 * u * u - 2 * u * u * u, p1 = u - 2 * u * u + u * u * u,
                 q1 = u * u * u - u * u;
    const double p0u = -6 * u + 6 * u * u, q0u = 6 * u - 6 * u * u, p1u = 1 - 4 * u + 3 * u * u,
                 q1u = 3 * u * u - 2 * u;
    const double p0uu = -6 + 12 * u, q0uu = 6 - 12 * u, p1uu = -4 + 6 * u, q1uu = 6 * u - 2;
    // block layout: (y, y', z, z'); c = 0 for y, 2 for z.
    v = a[c] * p0 + b[c] * q0 + h * (a[c + 1] * p1 + b[c + 1] * q1);
    d1 = (a[c] * p0u + b[c] * q0u) / h + a[c + 1] * p1u + b[c + 1] * q1u;
    d2 = (a[c] * p0uu + b[c] * q0uu) / (h * h) + (a[c + 1] * p1uu + b[c + 1] * q1uu) / h;
}

struct BendingResidual {
    double h, u, scale;  // scale = √(Gauss weight · h)
    template <typename T>
    bool operator()(const T* a, const T* b, T* r) const {
        T y, y1, y2, z, z1, z2;
        hermite(a, b, 0, h, u, y, y1, y2);
        hermite(a, b, 2, h, u, z, z1, z2);
        // r' = (1, y1, z1), r'' = (0, y2, z2); r' × r'' = (y1 z2 − z1 y2, −z2, y2).
        const T speed2 = 1.0 + y1 * y1 + z1 * z1;
        const T factor = scale / pow(speed2, 1.25);  // 1 / |r'|^{5/2}
        r[0] = (y1 * z2 - z1 * y2) * factor;
        r[1] = -z2 * factor;
        r[2] = y2 * factor;
        return true;
    }
};

struct SpringResidual {
    double ay, az, weight;  // weight = 1/√λ
    template <typename T>
    bool operator()(const T* k, T* r) const {
        r[0] = (k[0] - ay) * weight;
        r[1] = (k[2] - az) * weight;
        return true;
    }
};

}  // namespace

Eigen::MatrixXd ElasticSpaceCurve::whole_jet(double at, int order, JetSide side) const {
    // The piece that starts at or before x (right), or the one that ends at or after it (left).
    const auto it = side == JetSide::left ? std::lower_bound(knots.begin(), knots.end(), at)
                                          : std::upper_bound(knots.begin(), knots.end(), at);
    const std::size_t i =
        std::min<std::size_t>(static_cast<std::size_t>(std::max<long>(it - knots.begin() - 1, 0)), knots.size() - 2);
    const Eigen::Index k = static_cast<Eigen::Index>(i);
    const double h = knots[i + 1] - knots[i], u = (at - knots[i]) / h;
    const double a[4] = {values(k, 0), slopes(k, 0), values(k, 1), slopes(k, 1)};
    const double b[4] = {values(k + 1, 0), slopes(k + 1, 0), values(k + 1, 1), slopes(k + 1, 1)};
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(order + 1, 3);
    for (int c = 0; c < 2; ++c) {
        double v, d1, d2, v0, d10, d20, v1, d11, d21;
        hermite(a, b, 2 * c, h, u, v, d1, d2);
        out(0, c + 1) = v;
        if (order >= 1) out(1, c + 1) = d1;
        if (order >= 2) out(2, c + 1) = d2;
        if (order >= 3) {  // the third derivative is constant on a cubic piece
            hermite(a, b, 2 * c, h, 0.0, v0, d10, d20);
            hermite(a, b, 2 * c, h, 1.0, v1, d11, d21);
            out(3, c + 1) = (d21 - d20) / h;
        }
    }
    out(0, 0) = at;
    if (order >= 1) out(1, 0) = 1.0;
    return out;
}

ElasticSpaceCurve elastic_space_curve(const std::vector<double>& x, const Eigen::MatrixXd& a,
                                      const std::vector<double>& lambda_in, int subdivisions) {
    const char* who = "cagd::smoothing::elastic_space_curve";
    if (a.cols() != 2) fail_input(who, "needs two value columns (y, z), got " + std::to_string(a.cols()));
    if (subdivisions < 1) fail_input(who, "needs subdivisions >= 1, got " + std::to_string(subdivisions));
    if (x.size() >= 2 && static_cast<long long>(x.size() - 1) * subdivisions > kMaxSpaceCurvePieces)
        fail_input(who, "subdivisions = " + std::to_string(subdivisions) + " gives " +
                            std::to_string(static_cast<long long>(x.size() - 1) * subdivisions) + " pieces for " +
                            std::to_string(x.size()) + " points; at most " + std::to_string(kMaxSpaceCurvePieces) +
                            " pieces");
    const ElasticLine start = elastic_line(x, a, lambda_in);  // validates x, a, λ
    const std::vector<double> lambda = per_point_lambda(lambda_in, x.size(), who);
    for (std::size_t i = 0; i < lambda.size(); ++i)
        if (lambda[i] == 0.0)
            fail_input(
                who, "lambda[" + std::to_string(i) + "] = 0; the space elastic line needs finite springs (lambda > 0)");
    require_built_with(OptionalDependency::ceres, who);
#if CAGD_WITH_CERES

    ElasticSpaceCurve out;
    for (std::size_t i = 0; i + 1 < x.size(); ++i)
        for (int s = 0; s < subdivisions; ++s) out.knots.push_back(x[i] + (x[i + 1] - x[i]) * s / subdivisions);
    out.knots.push_back(x.back());
    const Eigen::Index knots = static_cast<Eigen::Index>(out.knots.size());
    std::vector<std::array<double, 4>> block(out.knots.size());
    for (Eigen::Index k = 0; k < knots; ++k) {
        const double xk = out.knots[static_cast<std::size_t>(k)];
        const Eigen::RowVectorXd v = start.curve.evaluate(xk), d = start.curve.evaluate(xk, 1);
        block[static_cast<std::size_t>(k)] = {v(0), d(0), v(1), d(1)};
    }
    static const numeric::GaussLegendreRule rule(4);
    ceres::Problem problem;
    for (std::size_t k = 0; k + 1 < out.knots.size(); ++k) {
        const double h = out.knots[k + 1] - out.knots[k];
        for (std::size_t q = 0; q < rule.nodes().size(); ++q) {
            const double u = 0.5 * (rule.nodes()[q] + 1.0), w = 0.5 * rule.weights()[q];
            problem.AddResidualBlock(
                new ceres::AutoDiffCostFunction<BendingResidual, 3, 4, 4>(new BendingResidual{h, u, std::sqrt(w * h)}),
                nullptr, block[k].data(), block[k + 1].data());
        }
    }
    for (std::size_t i = 0; i < x.size(); ++i)
        problem.AddResidualBlock(
            new ceres::AutoDiffCostFunction<SpringResidual, 2, 4>(new SpringResidual{
                a(static_cast<Eigen::Index>(i), 0), a(static_cast<Eigen::Index>(i), 1), 1.0 / std::sqrt(lambda[i])}),
            nullptr, block[i * static_cast<std::size_t>(subdivisions)].data());
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    // The energy is quadratic but for the spring directions: Ceres converges in tens of iterations;
    // the tolerances sit at rounding so that the result is the minimiser to double precision.
    constexpr double kFunctionTolerance = 1e-15, kGradientTolerance = 1e-14, kParameterTolerance = 1e-14;
    constexpr int kIterations = 500;
    options.function_tolerance = kFunctionTolerance;
    options.gradient_tolerance = kGradientTolerance;
    options.parameter_tolerance = kParameterTolerance;
    options.max_num_iterations = kIterations;
    options.num_threads = 1;
    options.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    if (summary.termination_type != ceres::CONVERGENCE)
        out.outcome = Outcome{Status::no_convergence, "Ceres did not converge: " + summary.BriefReport()};
    out.energy = summary.final_cost;
    out.values.resize(knots, 2);
    out.slopes.resize(knots, 2);
    for (Eigen::Index k = 0; k < knots; ++k) {
        const auto& b = block[static_cast<std::size_t>(k)];
        out.values.row(k) << b[0], b[2];
        out.slopes.row(k) << b[1], b[3];
    }
    return out;
#else
    return {};
#endif
}

}  // namespace cagd::smoothing
