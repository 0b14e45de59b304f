// Romberg and Gauss–Legendre against Boost.Math (gauss_kronrod, tanh_sinh, gauss<>) on
// integrands with known values.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>

#include <limits>
#include <numbers>
#include <random>
#include "cagd/core/errors.hpp"
#include "cagd/numeric/finite_difference.hpp"
#include "cagd/numeric/gauss_legendre.hpp"
#include "cagd/numeric/pentadiagonal.hpp"
#include "cagd/numeric/romberg.hpp"

using cagd::numeric::GaussLegendreRule;
using cagd::numeric::romberg;

TEST(Romberg, MatchesKnownValuesAndBoost) {
    const auto f = [](double x) { return std::exp(x) * std::cos(3 * x); };
    const double exact = (std::exp(1.0) * (std::cos(3.0) + 3 * std::sin(3.0)) - 1.0) / 10.0;
    const auto r = romberg(f, 0.0, 1.0, 1e-13);
    ASSERT_TRUE(r.outcome.ok()) << r.outcome.message;
    EXPECT_NEAR(r.value, exact, 1e-13 * std::abs(exact));
    double gk_err = 0.0;
    const double gk = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, 0.0, 1.0, 15, 1e-14, &gk_err);
    EXPECT_NEAR(r.value, gk, 2e-14);
    boost::math::quadrature::tanh_sinh<double> ts;
    EXPECT_NEAR(r.value, ts.integrate(f, 0.0, 1.0), 2e-14);
}

TEST(Romberg, ErrorEstimateBoundsActualErrorOnSmoothIntegrand) {
    const auto f = [](double x) { return 1.0 / (1.0 + x * x); };
    const auto r = romberg(f, 0.0, 1.0, 1e-8);
    ASSERT_TRUE(r.outcome.ok());
    // The estimate |R(k,k) − R(k−1,k−1)| is an upper bound of the error of R(k,k) here.
    EXPECT_LE(std::abs(r.value - std::numbers::pi / 4), r.error_estimate + 1e-16);
    EXPECT_LE(r.error_estimate, 1e-8);
}

TEST(Romberg, ReportsNoConvergenceAsStatusNotException) {
    // sqrt has an unbounded derivative at 0: Romberg converges only algebraically.
    const auto r = romberg([](double x) { return std::sqrt(x); }, 0.0, 1.0, 1e-15, 0.0, 6);
    EXPECT_EQ(r.outcome.status, cagd::Status::no_convergence);
    EXPECT_NE(r.outcome.message.find("no convergence"), std::string::npos);
}

TEST(Romberg, RejectsBadArguments) {
    const auto f = [](double x) { return x; };
    EXPECT_THROW(romberg(f, 0.0, INFINITY), cagd::InvalidInput);
    EXPECT_THROW(romberg(f, 0.0, 1.0, 0.0), cagd::InvalidInput);
    EXPECT_THROW(romberg(f, 0.0, 1.0, 1e-10, 0.0, 1), cagd::InvalidInput);
}

TEST(GaussLegendre, ExactForPolynomialsOfDegree2nMinus1) {
    for (int n = 1; n <= 12; ++n) {
        const GaussLegendreRule rule(n);
        const int deg = 2 * n - 1;
        // ∫_{-0.5}^{2} x^deg dx
        const double exact = (std::pow(2.0, deg + 1) - std::pow(-0.5, deg + 1)) / (deg + 1);
        EXPECT_NEAR(rule.integrate([&](double x) { return std::pow(x, deg); }, -0.5, 2.0), exact,
                    1e-13 * std::max(1.0, std::abs(exact)))
            << "n = " << n;
        // and not exact for degree 2n (the rule's order is sharp)
        const double exact2 = (std::pow(2.0, deg + 2) - std::pow(-0.5, deg + 2)) / (deg + 2);
        EXPECT_GT(std::abs(rule.integrate([&](double x) { return std::pow(x, deg + 1); }, -0.5, 2.0) - exact2), 1e-10);
    }
}

TEST(GaussLegendre, NodesAndWeightsMatchBoost) {
    const GaussLegendreRule rule(7);
    const auto& xs = boost::math::quadrature::gauss<double, 7>::abscissa();  // x ≥ 0 half
    const auto& ws = boost::math::quadrature::gauss<double, 7>::weights();
    for (std::size_t k = 0; k < xs.size(); ++k) {
        EXPECT_NEAR(rule.nodes()[3 + k], xs[k], 2e-16);
        EXPECT_NEAR(rule.weights()[3 + k], ws[k], 4e-16);
    }
}

TEST(GaussLegendre, AgreesWithGaussKronrodOnAnalyticIntegrand) {
    const auto f = [](double x) { return std::log(2.0 + std::sin(5 * x)); };
    const double gk = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, 0.0, 2.0, 20, 1e-15);
    boost::math::quadrature::tanh_sinh<double> ts;
    EXPECT_NEAR(gk, ts.integrate(f, 0.0, 2.0), 1e-14);
    // Singularities at distance asinh(2)/5 from the real axis: convergence like ρ^{-2n}.
    EXPECT_NEAR(GaussLegendreRule(100).integrate(f, 0.0, 2.0), gk, 1e-14);
    EXPECT_GT(std::abs(GaussLegendreRule(20).integrate(f, 0.0, 2.0) - gk), 1e-9);
    EXPECT_THROW(GaussLegendreRule(0), cagd::InvalidInput);
}

#include "cagd/numeric/rational.hpp"

TEST(Rational, SimplestFractionWithinTolerance) {
    const auto f = cagd::numeric::simplest_fraction_within(std::numbers::pi, 0.002);
    EXPECT_EQ(f.numerator, 22);
    EXPECT_EQ(f.denominator, 7);
    const auto g = cagd::numeric::simplest_fraction_within(std::numbers::pi, 1e-6);
    EXPECT_EQ(g.numerator, 355);
    EXPECT_EQ(g.denominator, 113);
    const auto h = cagd::numeric::simplest_fraction_within(-0.366, 0.0005);
    EXPECT_NEAR(h.value(), -0.366, 0.0005);
    EXPECT_EQ(h.denominator, 41);
    EXPECT_THROW(cagd::numeric::simplest_fraction_within(1.0, 0.0), cagd::InvalidInput);
}

#include "cagd/numeric/tridiagonal.hpp"

TEST(Tridiagonal, MatchesADenseSolveAndRejectsAZeroPivot) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int n = 40;
    std::vector<double> sub(n), diag(n), sup(n);
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n), R(n, 2);
    for (int r = 0; r < n; ++r) {
        sub[static_cast<std::size_t>(r)] = r > 0 ? u(rng) : 0.0;
        sup[static_cast<std::size_t>(r)] = r + 1 < n ? u(rng) : 0.0;
        diag[static_cast<std::size_t>(r)] = 2.5 + u(rng);
        A(r, r) = diag[static_cast<std::size_t>(r)];
        if (r > 0) A(r, r - 1) = sub[static_cast<std::size_t>(r)];
        if (r + 1 < n) A(r, r + 1) = sup[static_cast<std::size_t>(r)];
        R.row(r) << u(rng), u(rng);
    }
    const Eigen::MatrixXd X = cagd::numeric::solve_tridiagonal(sub, diag, sup, R);
    EXPECT_LT((A * X - R).norm(), 1e-13);
    EXPECT_LT((X - A.partialPivLu().solve(R)).norm(), 1e-13);
    EXPECT_THROW(cagd::numeric::solve_tridiagonal({0, 1}, {0, 1}, {1, 0}, Eigen::MatrixXd::Ones(2, 1)),
                 cagd::InvalidInput);
}

// The solver eliminates all columns in one pass over the rows; each entry must still see the
// textbook operations in the textbook order (the spline results are compared byte for byte).
TEST(Tridiagonal, OnePassEliminationIsTheTextbookThomasBitForBit) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const int cols : {1, 2, 3, 5}) {
        const std::size_t n = 57;
        std::vector<double> sub(n), diag(n), sup(n);
        Eigen::MatrixXd R(static_cast<Eigen::Index>(n), cols);
        for (std::size_t r = 0; r < n; ++r) sub[r] = u(rng), diag[r] = 2.1 + u(rng), sup[r] = u(rng);
        for (Eigen::Index r = 0; r < R.rows(); ++r)
            for (int j = 0; j < cols; ++j) R(r, j) = u(rng);
        // Textbook: pivots and c first, then each column forward and back.
        std::vector<double> c(n), pivot(n);
        for (std::size_t r = 0; r < n; ++r) {
            pivot[r] = r == 0 ? diag[0] : diag[r] - sub[r] * c[r - 1];
            c[r] = r + 1 < n ? sup[r] / pivot[r] : 0.0;
        }
        Eigen::MatrixXd expected = R;
        for (int j = 0; j < cols; ++j) {
            double* x = expected.col(j).data();
            x[0] /= pivot[0];
            for (std::size_t r = 1; r < n; ++r) {
                x[r] -= sub[r] * x[r - 1];
                x[r] /= pivot[r];
            }
            for (std::size_t r = n - 1; r-- > 0;) x[r] -= c[r] * x[r + 1];
        }
        const Eigen::MatrixXd X = cagd::numeric::solve_tridiagonal(sub, diag, sup, R);
        for (Eigen::Index r = 0; r < X.rows(); ++r)
            for (int j = 0; j < cols; ++j)
                EXPECT_EQ(X(r, j), expected(r, j)) << "row " << r << ", column " << j << " of " << cols;
        // The same elimination with each row formed when it is reached (its right-hand side written
        // then, into the output), each row once and in order.
        Eigen::MatrixXd Y =
            Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(n), cols, std::numeric_limits<double>::quiet_NaN());
        std::size_t next_row = 0;
        cagd::numeric::solve_tridiagonal_rows(
            n, static_cast<std::size_t>(cols),
            [&](std::size_t r, double* rhs, std::size_t stride) {
                EXPECT_EQ(r, next_row++) << "rows out of order";
                for (int j = 0; j < cols; ++j)
                    rhs[static_cast<std::size_t>(j) * stride] = R(static_cast<Eigen::Index>(r), j);
                return cagd::numeric::TridiagonalRow{sub[r], diag[r], sup[r]};
            },
            Y.data());
        EXPECT_EQ(next_row, n);
        for (Eigen::Index r = 0; r < Y.rows(); ++r)
            for (int j = 0; j < cols; ++j)
                EXPECT_EQ(Y(r, j), expected(r, j))
                    << "rows formed on demand: row " << r << ", column " << j << " of " << cols;
    }
    // A zero pivot after the first row (diag[1] − sub[1]·sup[0]/diag[0] = 1 − 1·1/1) still throws.
    try {
        cagd::numeric::solve_tridiagonal({0, 1, 1}, {1, 1, 3}, {1, 1, 0}, Eigen::MatrixXd::Ones(3, 2));
        ADD_FAILURE() << "no exception for a zero pivot at row 1";
    } catch (const cagd::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("zero pivot at row 1"), std::string::npos) << e.what();
    }
}

TEST(CyclicTridiagonal, MatchesDenseLuWithCornerEntries) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int n : {3, 4, 40}) {
        std::vector<double> sub(static_cast<std::size_t>(n)), diag(sub), sup(sub);
        Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n), R(n, 3);
        for (int r = 0; r < n; ++r) {
            const auto k = static_cast<std::size_t>(r);
            sub[k] = u(rng);
            sup[k] = u(rng);
            diag[k] = 2.5 + u(rng);
            A(r, r) = diag[k];
            A(r, (r + n - 1) % n) += sub[k];  // row 0: the corner A(0, n−1)
            A(r, (r + 1) % n) += sup[k];      // row n−1: the corner A(n−1, 0)
            R.row(r) << u(rng), u(rng), u(rng);
        }
        const Eigen::MatrixXd X = cagd::numeric::solve_cyclic_tridiagonal(sub, diag, sup, R);
        EXPECT_LT((A * X - R).norm(), 1e-13) << n;
        EXPECT_LT((X - A.partialPivLu().solve(R)).norm(), 1e-13) << n;
    }
    EXPECT_THROW(cagd::numeric::solve_cyclic_tridiagonal({1, 1}, {3, 3}, {1, 1}, Eigen::MatrixXd::Ones(2, 1)),
                 cagd::InvalidInput);
}

TEST(OneSidedDerivatives, ExactForPolynomialsAndAccurateForSine) {
    const auto cubic = [](double x) { return 2 - x + 3 * x * x * x; };
    for (int side : {-1, 1}) {
        const std::vector<double> d = cagd::numeric::one_sided_derivatives(cubic, 0.5, 0.1, side, 5);
        EXPECT_NEAR(d[0], 2 - 0.5 + 3 * 0.125, 1e-12);
        EXPECT_NEAR(d[1], -1 + 9 * 0.25, 1e-11);
        EXPECT_NEAR(d[2], 18 * 0.5, 1e-9);
        EXPECT_NEAR(d[3], 18, 1e-7);
        EXPECT_NEAR(d[4], 0, 1e-5);
    }
    const std::vector<double> s =
        cagd::numeric::one_sided_derivatives([](double x) { return std::sin(x); }, 1.0, 0.02, -1, 7);
    EXPECT_NEAR(s[1], std::cos(1.0), 1e-9);
    EXPECT_NEAR(s[2], -std::sin(1.0), 1e-6);
    EXPECT_THROW(cagd::numeric::one_sided_derivatives(cubic, 0, 0.1, 0, 4), cagd::InvalidInput);
    EXPECT_THROW(cagd::numeric::one_sided_derivatives(cubic, 0, -0.1, 1, 4), cagd::InvalidInput);
}

TEST(Pentadiagonal, MatchesDenseSolveOfAnSpdBandMatrix) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int n : {1, 2, 3, 7, 40}) {
        // B Bᵀ with B lower bidiagonal plus a diagonal shift: SPD and pentadiagonal.
        Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, n);
        for (int i = 0; i < n; ++i) {
            b(i, i) = 1.5 + u(rng);
            if (i > 0) b(i, i - 1) = u(rng);
            if (i > 1) b(i, i - 2) = u(rng);
        }
        const Eigen::MatrixXd a = b * b.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);
        std::vector<double> d, f, s;
        for (int i = 0; i < n; ++i) {
            d.push_back(a(i, i));
            if (i + 1 < n) f.push_back(a(i, i + 1));
            if (i + 2 < n) s.push_back(a(i, i + 2));
        }
        const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(n, 2);
        const Eigen::MatrixXd x = cagd::numeric::solve_symmetric_pentadiagonal(d, f, s, rhs);
        EXPECT_LT((a * x - rhs).cwiseAbs().maxCoeff(), 1e-12) << "n = " << n;
    }
    EXPECT_THROW(cagd::numeric::solve_symmetric_pentadiagonal({1.0, 1.0}, {2.0}, {}, Eigen::MatrixXd::Ones(2, 1)),
                 cagd::InvalidInput)
        << "indefinite";
}

#include "cagd/numeric/sparse_lu.hpp"

// The compiled-once SparseLU: a random nonsymmetric sparse system (cyclic band plus scattered
// entries) solved in both column orderings against a dense partial-pivoting LU, one and several
// right-hand sides; a matrix with a zero column reports failure; a solve before a factorisation
// is a logic error; a re-factorisation with the analysed pattern gives the new matrix's solution.
TEST(SparseLu, SolvesLikeADenseLuInBothOrderingsAndReportsSingularity) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int n = 60;
    auto random_matrix = [&] {
        std::vector<Eigen::Triplet<double>> t;
        for (int i = 0; i < n; ++i) {
            t.emplace_back(i, i, 4.0 + u(rng));
            t.emplace_back(i, (i + 1) % n, u(rng));
            t.emplace_back(i, (i + n - 1) % n, u(rng));
            t.emplace_back(i, (i * 7 + 3) % n, u(rng));
        }
        Eigen::SparseMatrix<double> a(n, n);
        a.setFromTriplets(t.begin(), t.end());
        return a;
    };
    const Eigen::SparseMatrix<double> a = random_matrix(), a2 = random_matrix();
    Eigen::MatrixXd b(n, 3);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 3; ++j) b(i, j) = u(rng);
    const Eigen::MatrixXd dense = Eigen::MatrixXd(a).partialPivLu().solve(b);
    for (const cagd::numeric::ColumnOrdering ordering :
         {cagd::numeric::ColumnOrdering::colamd, cagd::numeric::ColumnOrdering::natural}) {
        cagd::numeric::SparseLu lu(ordering);
        EXPECT_THROW(static_cast<void>(lu.solve(Eigen::VectorXd(b.col(0)))), std::logic_error);
        ASSERT_TRUE(lu.compute(a));
        EXPECT_LT((lu.solve(b) - dense).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_LT((lu.solve(Eigen::VectorXd(b.col(1))) - dense.col(1)).cwiseAbs().maxCoeff(), 1e-12);
        ASSERT_TRUE(lu.factorize(a2));  // same pattern, new values
        EXPECT_LT((lu.solve(b) - Eigen::MatrixXd(a2).partialPivLu().solve(b)).cwiseAbs().maxCoeff(), 1e-12);
    }
    Eigen::SparseMatrix<double> singular = a;
    singular.prune([](Eigen::Index, Eigen::Index col, double) { return col != 5; });  // column 5 empty
    cagd::numeric::SparseLu lu;
    EXPECT_FALSE(lu.compute(singular));
    EXPECT_THROW(static_cast<void>(lu.solve(b)), std::logic_error);
}
