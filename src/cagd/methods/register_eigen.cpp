// Eigen's SplineFitting::Interpolate (unsupported/Eigen/Splines) as a peer: global B-spline
// interpolation of Piegl and Tiller (The NURBS Book, 2nd ed., section 9.2.1). Its parameters are
// the chord lengths normalised to [0, 1] (the curve's u; the method's τ is the chord length, L u), its knots the
// averages of `degree` consecutive parameters (clamped at 0 and 1), and its control points solve the n × n collocation
// system, which Eigen builds dense and solves by Householder QR: O(n³) time and O(n²) memory. The peer therefore takes
// at most kMaxEigenSplinePoints points, and says so. Open curves only: SplineFitting has no periodic form.
#include "cagd/methods/detail/registration.hpp"

#include <unsupported/Eigen/Splines>

#include "cagd/spline/bspline.hpp"

namespace cagd::methods::detail {

namespace {

// The dense system has n² entries (2,000 points: 4·10^6 doubles).
constexpr int kMaxEigenSplinePoints = 2000;

template <int Dim>
InterpolationResult eigen_spline_interpolant(const PointList& p, int degree) {
    using Spline = Eigen::Spline<double, Dim>;
    const Eigen::Matrix<double, Dim, Eigen::Dynamic> points = p.transpose();
    typename Spline::KnotVectorType parameters;
    Eigen::ChordLengths(points, parameters);
    const Spline s = Eigen::SplineFitting<Spline>::Interpolate(points, degree, parameters);
    // The first and last rows of the collocation system are e_0 and e_{n−1} (the knots are
    // clamped): the end control points are the end points, which QR gives only to rounding.
    Eigen::MatrixXd control = s.ctrls().transpose();
    control.row(0) = p.row(0);
    control.row(control.rows() - 1) = p.row(p.rows() - 1);
    // Eigen's parameter u runs over [0, 1]; the method's τ is the chord length itself, τ = L u.
    double total = 0.0;
    for (Eigen::Index i = 1; i < p.rows(); ++i) total += (p.row(i) - p.row(i - 1)).norm();
    Interpolant in;
    in.node_parameters.assign(parameters.data(), parameters.data() + parameters.size());
    in.dtau_du.assign(static_cast<std::size_t>(p.rows() - 1), total);
    std::vector<double> knots(s.knots().data(), s.knots().data() + s.knots().size());
    in.curve = std::make_shared<BSplineCurve>(degree, std::move(knots), std::move(control));
    return result_of(std::move(in));
}

}  // namespace

std::vector<Method> eigen_methods() {
    return {{
        .name = "eigen-spline",
        .paper = "Eigen",
        .source = "Eigen::SplineFitting::Interpolate (unsupported/Eigen/Splines), chord length",
        .summary = "global B-spline interpolation with averaged knots, dense solve (a peer)",
        .parameters = {{.name = "degree",
                        .type = P::integer,
                        .default_text = "3",
                        .lower = 1,
                        .upper = 5,
                        .help = "degree p of the B-spline (C^(p-1))"}},
        .claims =
            [](const ParameterValues& v) {
                const int p = v.integer("degree");
                return MethodClaims{.parametric_continuity = p - 1,
                                    .parameter = "chord length",
                                    .invariance = Invariance::similarity,
                                    .supports_closed = false,
                                    .min_points = p + 1,
                                    .min_points_closed = 0,
                                    .max_points = kMaxEigenSplinePoints,
                                    .max_dimension = 3};
            },
        .build =
            [](const ValidPoints& valid, const ParameterValues& v) {
                const PointList& p = valid.points();
                const int degree = v.integer("degree");
                return p.cols() == 2 ? eigen_spline_interpolant<2>(p, degree) : eigen_spline_interpolant<3>(p, degree);
            },
        .presets = {{"eigen-spline-3", {{"degree", "3"}}}, {"eigen-spline-5", {{"degree", "5"}}}},
    }};
}

}  // namespace cagd::methods::detail
