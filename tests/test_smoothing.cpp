// hosaka section 6: elastic-line smoothing (eq 44–52) — the five-term system, the paper's iteration,
// the Hermite minimisation of V with Lagrange constraints.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/errors.hpp"
#include "smoothing/elastic_line.hpp"

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
        for (double u : {0.0, 0.25, 0.5, 0.75, 1.0}) diff = std::max(diff, (p.evaluate_in(static_cast<int>(s), u) - q.evaluate_in(static_cast<int>(s), u)).norm());
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
        double d2 = 0.0;   // δ²M_i with the terms beyond the ends dropped
        if (i + 1 < d.x.size()) d2 += (m(k + 1) - m(k)) / (d.x[i + 1] - d.x[i]);
        if (i > 0) d2 -= (m(k) - m(k - 1)) / (d.x[i] - d.x[i - 1]);
        EXPECT_NEAR(line.values()(k, 0) - d.a(k) + d.lambda[i] * d2, 0.0, 1e-12) << "y_i - a_i + lambda_i delta^2 y''_i = 0 at i = " << i;
    }
    // The curve's own second derivatives at the nodes are the M_i (the curve is C2).
    for (std::size_t i = 1; i + 1 < d.x.size(); ++i)
        EXPECT_NEAR(line.curve.evaluate(d.x[i], 2)(0), m(static_cast<Eigen::Index>(i)), 1e-10 * (1 + std::abs(m(static_cast<Eigen::Index>(i)))));
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
    e.lambda[4] = 0.3;   // any spring: the constraint overrides it
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
        EXPECT_NEAR(clamped.curve.evaluate_in(static_cast<int>(i) - 1, 1.0, 2)(0), clamped.curve.evaluate_in(static_cast<int>(i), 0.0, 2)(0), 1e-9);
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
    const ElasticLineIteration large = elastic_line_iterative(x, a, {0.1});   // 48 λ / l³ = 4.8
    EXPECT_EQ(large.outcome.status, Status::no_convergence);
    EXPECT_GT(large.contraction, 1.0);
}

TEST(ElasticLine, InflectionsAreSignChangesOfSecondDerivatives) {
    const std::vector<double> x{0, 1, 2, 3, 4, 5};
    Eigen::VectorXd zigzag(6), convex(6);
    zigzag << 0, 1, 0, 1, 0, 1;
    for (int i = 0; i < 6; ++i) convex(i) = 0.1 * i * i + (i % 2 ? 0.3 : -0.3);   // a convex trend plus alternating noise
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
