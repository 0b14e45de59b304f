// hosaka section 6: elastic-line smoothing (eq 44–52) — the five-term system, the paper's iteration,
// the Hermite minimisation of V with Lagrange constraints.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cagd/core/errors.hpp"
#include "cagd/smoothing/elastic_line.hpp"

using namespace cagd;
using namespace cagd::smoothing;

namespace {

struct Data {
    std::vector<double> x;
    Eigen::VectorXd a;
    std::vector<double> lambda;
};

// Uneven abscissae, noisy values, per-point λ in [0.01, 0.5].
Data noisy_sine(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> step(0.3, 1.5), noise(-0.3, 0.3), lam(0.01, 0.5);
    Data d;
    d.a.resize(n);
    double x = 0.0;
    for (int i = 0; i < n; ++i) {
        d.x.push_back(x);
        d.a(i) = std::sin(0.7 * x) + noise(rng);
        d.lambda.push_back(lam(rng));
        x += step(rng);
    }
    return d;
}

double max_curve_difference(const spline::ExplicitSpline& p, const spline::ExplicitSpline& q) {
    double diff = 0.0;
    for (std::size_t s = 0; s + 1 < p.x.size(); ++s)
        for (double u : {0.0, 0.25, 0.5, 0.75, 1.0})
            diff =
                std::max(diff, (p.evaluate_in(static_cast<int>(s), u) - q.evaluate_in(static_cast<int>(s), u)).norm());
    return diff;
}

}  // namespace

TEST(ElasticLine, LambdaZeroIsTheInterpolatingSplineOfEq23) {
    const Data d = noisy_sine(9, 1);
    const ElasticLine line = elastic_line(d.x, d.a, 0.0);
    const spline::ExplicitSpline spline = spline::hosaka_explicit_spline(d.x, d.a);
    EXPECT_LT((line.values() - d.a).cwiseAbs().maxCoeff(), 1e-14) << "lambda = 0 interpolates";
    EXPECT_LT((line.curve.slopes - spline.slopes).cwiseAbs().maxCoeff(), 1e-12) << "same slopes as eq (23)";
}

TEST(ElasticLine, SpringLawEq50CorrectedHoldsAndNaturalEnds) {
    const Data d = noisy_sine(12, 2);
    const ElasticLine line = elastic_line(d.x, d.a, d.lambda);
    const Eigen::VectorXd m = line.second_derivatives.col(0);
    EXPECT_EQ(m(0), 0.0);
    EXPECT_EQ(m(m.size() - 1), 0.0);
    for (std::size_t i = 0; i < d.x.size(); ++i) {
        const Eigen::Index k = static_cast<Eigen::Index>(i);
        double d2 = 0.0;  // δ²M_i with the terms beyond the ends dropped
        if (i + 1 < d.x.size()) d2 += (m(k + 1) - m(k)) / (d.x[i + 1] - d.x[i]);
        if (i > 0) d2 -= (m(k) - m(k - 1)) / (d.x[i] - d.x[i - 1]);
        EXPECT_NEAR(line.values()(k, 0) - d.a(k) + d.lambda[i] * d2, 0.0, 1e-12)
            << "y_i - a_i + lambda_i delta^2 y''_i = 0 at i = " << i;
    }
    // The curve's own second derivatives at the nodes are the M_i (the curve is C2).
    for (std::size_t i = 1; i + 1 < d.x.size(); ++i)
        EXPECT_NEAR(line.curve.evaluate(d.x[i], 2)(0), m(static_cast<Eigen::Index>(i)),
                    1e-10 * (1 + std::abs(m(static_cast<Eigen::Index>(i)))));
}

TEST(ElasticLine, FiveTermSystemEqualsHermiteMinimisationOfV) {
    for (unsigned seed = 3; seed < 8; ++seed) {
        const Data d = noisy_sine(15, seed);
        const ElasticLine line = elastic_line(d.x, d.a, d.lambda);
        const HermiteElasticLine direct = elastic_line_hermite(d.x, d.a, d.lambda);
        EXPECT_LT(max_curve_difference(line.curve, direct.curve), 1e-10) << "seed " << seed;
        EXPECT_NEAR(elastic_line_energy(line.curve, d.a, d.lambda), direct.energy, 1e-12 * direct.energy);
    }
}

TEST(ElasticLine, ZeroLambdaPointEqualsLagrangeFixedPoint) {
    Data d = noisy_sine(10, 9);
    d.lambda[4] = 0.0;
    const ElasticLine line = elastic_line(d.x, d.a, d.lambda);
    EXPECT_NEAR(line.values()(4, 0), d.a(4), 1e-14);
    Data e = d;
    e.lambda[4] = 0.3;  // any spring: the constraint overrides it
    ElasticLineConstraints c;
    c.fixed_values = {{4, d.a(4)}};
    std::vector<double> lam = e.lambda;
    const HermiteElasticLine direct = elastic_line_hermite(e.x, e.a, lam, c);
    // With the spring at 4 replaced by the constraint the energies differ only by that spring's term, which is 0.
    EXPECT_LT(max_curve_difference(line.curve, direct.curve), 1e-10);
    EXPECT_EQ(direct.multipliers.size(), 1);
}

TEST(ElasticLine, FixedEndSlopesHoldAndCostEnergy) {
    const Data d = noisy_sine(10, 11);
    ElasticLineConstraints c;
    c.start_slope = 2.0;
    c.end_slope = -1.0;
    const HermiteElasticLine free = elastic_line_hermite(d.x, d.a, d.lambda);
    const HermiteElasticLine clamped = elastic_line_hermite(d.x, d.a, d.lambda, c);
    EXPECT_NEAR(clamped.curve.slopes(0, 0), 2.0, 1e-12);
    EXPECT_NEAR(clamped.curve.slopes(9, 0), -1.0, 1e-12);
    EXPECT_GT(clamped.energy, free.energy);
    // Interior joins stay C2 (eq 49 holds at the free nodes).
    for (std::size_t i = 1; i + 1 < d.x.size(); ++i)
        EXPECT_NEAR(clamped.curve.evaluate_in(static_cast<int>(i) - 1, 1.0, 2)(0),
                    clamped.curve.evaluate_in(static_cast<int>(i), 0.0, 2)(0), 1e-9);
}

TEST(ElasticLine, LargeLambdaTendsToTheLeastSquaresLine) {
    const Data d = noisy_sine(11, 13);
    const ElasticLine line = elastic_line(d.x, d.a, 1e9);
    Eigen::MatrixXd design(d.a.size(), 2);
    for (Eigen::Index i = 0; i < d.a.size(); ++i) design.row(i) << 1.0, d.x[static_cast<std::size_t>(i)];
    const Eigen::VectorXd fit = design * design.colPivHouseholderQr().solve(d.a);
    EXPECT_LT((line.values().col(0) - fit).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(ElasticLine, IterationConvergesForSmallLambdaAndReportsDivergence) {
    std::vector<double> x;
    Eigen::VectorXd a(20);
    for (int i = 0; i < 20; ++i) {
        x.push_back(i);
        a(i) = std::cos(0.5 * i) + (i % 2 ? 0.1 : -0.1);
    }
    const ElasticLineIteration small = elastic_line_iterative(x, a, {0.01});
    ASSERT_TRUE(small.outcome.ok()) << small.outcome.message;
    EXPECT_LT((small.line.values() - elastic_line(x, a, 0.01).values()).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT(small.contraction, 48 * 0.01);
    const ElasticLineIteration large = elastic_line_iterative(x, a, {0.1});  // 48 λ / l³ = 4.8
    EXPECT_EQ(large.outcome.status, Status::no_convergence);
    EXPECT_GT(large.contraction, 1.0);
}

TEST(ElasticLine, InflectionsAreSignChangesOfSecondDerivatives) {
    const std::vector<double> x{0, 1, 2, 3, 4, 5};
    Eigen::VectorXd zigzag(6), convex(6);
    zigzag << 0, 1, 0, 1, 0, 1;
    for (int i = 0; i < 6; ++i)
        convex(i) = 0.1 * i * i + (i % 2 ? 0.3 : -0.3);  // a convex trend plus alternating noise
    EXPECT_EQ(inflection_count(elastic_line(x, zigzag, 0.0)), 3);
    EXPECT_EQ(inflection_count(elastic_line(x, convex, 0.0)), 3);
    EXPECT_EQ(inflection_count(elastic_line(x, convex, 1e3)), 0) << "the stiff line follows the convex trend";
    // Not a theorem for every data set: as lambda grows M -> (Q^T Q)^-1 Q^T a / (6 lambda), which keeps
    // the alternation of pure zigzag data.
    EXPECT_EQ(inflection_count(elastic_line(x, zigzag, 1e3)), 3);
}

TEST(ElasticLine, BadInputThrows) {
    const std::vector<double> x{0, 1, 2, 3};
    const Eigen::VectorXd a = Eigen::VectorXd::Ones(4);
    EXPECT_THROW(elastic_line(x, a, -0.1), InvalidInput);
    EXPECT_THROW(elastic_line(x, a, std::nan("")), InvalidInput);
    EXPECT_THROW(elastic_line({0, 2, 1, 3}, a, 0.1), InvalidInput);
    EXPECT_THROW(elastic_line({0, 1, 1, 3}, a, 0.1), InvalidInput);
    Eigen::VectorXd bad = a;
    bad(2) = std::nan("");
    EXPECT_THROW(elastic_line(x, bad, 0.1), InvalidInput);
    EXPECT_THROW(elastic_line(x, a, std::vector<double>{0.1, 0.2}), InvalidInput);
    ElasticLineConstraints c;
    c.fixed_values = {{7, 1.0}};
    EXPECT_THROW(elastic_line_hermite(x, a, {0.1}, c), InvalidInput);
    c.fixed_values = {{1, 1.0}, {1, 2.0}};
    EXPECT_THROW(elastic_line_hermite(x, a, {0.1}, c), InvalidInput);
}

// ---- surfaces (eq 53–60) ----
#include "cagd/smoothing/surface_smoothing.hpp"

namespace {
struct Grid {
    std::vector<double> x, y;
    Eigen::MatrixXd a;
};
// Uneven 8 × 7 grid with heights f(x, y).
template <typename F>
Grid uneven_grid(F f) {
    Grid g;
    for (int i = 0; i < 8; ++i) g.x.push_back(i + 0.2 * std::sin(1.0 * i));
    for (int j = 0; j < 7; ++j) g.y.push_back(0.5 * j + 0.1 * std::cos(2.0 * j));
    g.a.resize(8, 7);
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 7; ++j) g.a(i, j) = f(g.x[static_cast<std::size_t>(i)], g.y[static_cast<std::size_t>(j)]);
    return g;
}
Eigen::MatrixXd scalar(double v) { return Eigen::MatrixXd::Constant(1, 1, v); }
double node_error(const surface::CartesianSurface& s, const Grid& g) {
    double e = 0;
    for (std::size_t i = 0; i < g.x.size(); ++i)
        for (std::size_t j = 0; j < g.y.size(); ++j)
            e = std::max(
                e, std::abs(s.value(g.x[i], g.y[j]) - g.a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j))));
    return e;
}
}  // namespace

TEST(SurfaceSmoothing, EnergyFreeSurfacesAreKept) {
    // A bilinear surface has ζxx = ζyy = 0: the net, the no-twist plate (57) and the mean-curvature
    // plate (58) leave it unchanged; the twist-penalising plate (56) does not (ζxy ≠ 0).
    const Grid g = uneven_grid([](double x, double y) { return 1 + 2 * x - y + 0.5 * x * y; });
    EXPECT_LT((elastic_net(g.x, g.y, g.a, scalar(0.5)).values - g.a).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT(node_error(plate_smoothing(g.x, g.y, g.a, scalar(0.5), PlateEnergy::no_twist).surface, g), 1e-10);
    EXPECT_LT(node_error(plate_smoothing(g.x, g.y, g.a, scalar(0.5), PlateEnergy::mean_curvature).surface, g), 1e-10);
    EXPECT_GT(node_error(plate_smoothing(g.x, g.y, g.a, scalar(0.5), PlateEnergy::no_poisson).surface, g), 1e-4);
    // A plane has no energy under any of (55)–(58).
    const Grid p = uneven_grid([](double x, double y) { return 0.3 - x + 2 * y; });
    for (PlateEnergy e :
         {PlateEnergy::poisson, PlateEnergy::no_poisson, PlateEnergy::no_twist, PlateEnergy::mean_curvature})
        EXPECT_LT(node_error(plate_smoothing(p.x, p.y, p.a, scalar(0.5), e).surface, p), 1e-10);
}

TEST(SurfaceSmoothing, SmallLambdaInterpolatesAndLargeLambdaSmooths) {
    const Grid g = uneven_grid([](double x, double y) { return std::sin(x) * std::cos(2 * y); });
    const ElasticNet tight = elastic_net(g.x, g.y, g.a, scalar(0.0));
    EXPECT_LT((tight.values - g.a).cwiseAbs().maxCoeff(), 1e-14) << "lambda = 0: the net passes through the data";
    const surface::CartesianSurface rough = surface::cartesian_spline_surface(g.x, g.y, g.a);
    const double e_rough = plate_energy(rough, PlateEnergy::no_twist);
    for (PlateEnergy e : {PlateEnergy::no_poisson, PlateEnergy::no_twist}) {
        const PlateSmoothing small = plate_smoothing(g.x, g.y, g.a, scalar(1e-9), e),
                             large = plate_smoothing(g.x, g.y, g.a, scalar(10.0), e);
        EXPECT_LT(node_error(small.surface, g), 1e-6);
        EXPECT_LT(plate_energy(large.surface, PlateEnergy::no_twist), 0.1 * e_rough);
    }
}

TEST(SurfaceSmoothing, PlateSolutionIsStationary) {
    // U(ζ + ε η) − U(ζ) = O(ε²) for the plate's own energy: perturb one node's height.
    const Grid g = uneven_grid([](double x, double y) { return std::exp(-0.1 * (x - 3) * (x - 3)) * std::cos(y); });
    const PlateSmoothing s = plate_smoothing(g.x, g.y, g.a, scalar(0.2), PlateEnergy::no_poisson);
    const auto total = [&](const surface::CartesianSurface& c) {
        double springs = 0;
        for (std::size_t i = 0; i < g.x.size(); ++i)
            for (std::size_t j = 0; j < g.y.size(); ++j)
                springs +=
                    std::pow(c.value(g.x[i], g.y[j]) - g.a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)),
                             2) /
                    0.2;
        return 0.5 * springs + 0.5 * plate_energy(c, PlateEnergy::no_poisson);
    };
    const double u0 = total(s.surface);
    std::vector<Eigen::MatrixXd> nodes;
    for (std::size_t j = 0; j < g.y.size(); ++j)
        for (std::size_t i = 0; i < g.x.size(); ++i)
            nodes.push_back(s.surface.node(static_cast<int>(i), static_cast<int>(j)));
    for (double eps : {1e-3, 1e-4}) {
        std::vector<Eigen::MatrixXd> moved = nodes;
        moved[3 + 8 * 2](0, 0) += eps;
        moved[3 + 8 * 2](1, 1) += eps;
        const double du = total(surface::CartesianSurface(1, g.x, g.y, moved)) - u0;
        EXPECT_GT(du, 0.0);
        EXPECT_LT(du, 100 * eps * eps) << "first-order change must vanish at the minimiser";
    }
}

TEST(SurfaceSmoothing, OrthonormalPolynomialsAndApproximationOne) {
    const Eigen::MatrixXd psi = discrete_orthonormal_polynomials(5, 3);
    EXPECT_LT((discrete_gram_matrix(psi, 5) - Eigen::MatrixXd::Identity(4, 4)).cwiseAbs().maxCoeff(), 1e-14);
    Eigen::MatrixXd pair(2, 3);  // ψ_0 = 1 and the printed ψ_2 = (t² − 1)/2: Σ = 2.5, not 0 (erratum hosaka-E12)
    pair << 1, 0, 0, -0.5, 0, 0.5;
    EXPECT_NEAR(discrete_gram_matrix(pair, 5)(0, 1), 2.5, 1e-15);
    // Approximation 1 with λ = 0 reproduces a bicubic polynomial exactly (it lies in the span of ψ_i ψ_j).
    std::vector<double> x, y;
    for (int i = 0; i < 9; ++i) x.push_back(0.25 * i);
    for (int j = 0; j < 7; ++j) y.push_back(0.5 * j);
    Eigen::MatrixXd a(9, 7);
    const auto f = [](double u, double v) { return u * u * u - 2 * u * v * v + v * v * v * u + 1; };
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 7; ++j) a(i, j) = f(x[static_cast<std::size_t>(i)], y[static_cast<std::size_t>(j)]);
    const surface::CartesianSurface s = local_orthogonal_smoothing(x, y, a, 0.0, PlateEnergy::no_twist);
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 7; ++j) {
            EXPECT_NEAR(s.node(i, j)(0, 0), a(i, j), 1e-11);
            EXPECT_NEAR(s.node(i, j)(1, 0),
                        3 * x[static_cast<std::size_t>(i)] * x[static_cast<std::size_t>(i)] -
                            2 * y[static_cast<std::size_t>(j)] * y[static_cast<std::size_t>(j)] +
                            std::pow(y[static_cast<std::size_t>(j)], 3),
                        1e-10);
        }
}

TEST(SurfaceSmoothing, BoundaryPlateKeepsTheSmoothedBoundaryRows) {
    const Grid g = uneven_grid([](double x, double y) { return std::sin(0.5 * x) + y * y; });
    const BoundaryPlateSmoothing s = boundary_plate_smoothing(g.x, g.y, g.a, scalar(0.05), PlateEnergy::no_twist, 2);
    const ElasticLine lower = elastic_line(g.x, g.a.col(0), 0.05);
    for (std::size_t i = 0; i < g.x.size(); ++i)
        EXPECT_NEAR(s.surface.value(g.x[i], g.y.front()), lower.values()(static_cast<Eigen::Index>(i), 0), 1e-12);
    EXPECT_EQ(s.system_size, 2 * 2 * 8);
}

TEST(SurfaceSmoothing, BadInputThrows) {
    const Grid g = uneven_grid([](double x, double y) { return x + y; });
    EXPECT_THROW(elastic_net(g.x, g.y, g.a, scalar(-1.0)), InvalidInput);
    EXPECT_THROW(elastic_net(g.x, g.y, g.a.topRows(7), scalar(1.0)), InvalidInput)
        << "ragged: heights do not match the grid";
    EXPECT_THROW(elastic_net(g.x, g.y, g.a, Eigen::MatrixXd::Ones(3, 3)), InvalidInput);
    Eigen::MatrixXd bad = g.a;
    bad(2, 3) = std::nan("");
    EXPECT_THROW(elastic_net(g.x, g.y, bad, scalar(1.0)), InvalidInput);
    EXPECT_THROW(plate_smoothing(g.x, g.y, g.a, scalar(0.0), PlateEnergy::no_twist), InvalidInput)
        << "plates need finite springs";
    EXPECT_THROW(plate_energy_form(PlateEnergy::poisson, 0.7), InvalidInput);
    EXPECT_THROW(local_orthogonal_smoothing(g.x, g.y, g.a, 0.1, PlateEnergy::no_twist), InvalidInput) << "uneven grid";
    std::vector<double> x{0, 1, 2, 3}, y{0, 1, 2, 3, 4};
    EXPECT_THROW(local_orthogonal_smoothing(x, y, Eigen::MatrixXd::Zero(4, 5), 0.1, PlateEnergy::no_twist),
                 InvalidInput)
        << "fewer than 5 lines";
    EXPECT_THROW(surface::grid_from_points((PointList(3, 3) << 0, 0, 1, 1, 0, 1, 0, 1, 1).finished()), InvalidInput)
        << "ragged point grid";
}
