// numeric/banded_lu.hpp: LAPACK's banded LU behind row and column orderings.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

#include "../support/messages.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/numeric/banded_lu.hpp"
#include "cagd/numeric/banded_or_sparse_lu.hpp"

namespace {

using cagd::numeric::BandedLu;
using cagd::test::invalid_input_message;

std::vector<int> identity(int n) {
    std::vector<int> v(static_cast<std::size_t>(n));
    std::iota(v.begin(), v.end(), 0);
    return v;
}

// B with kl = 3 subdiagonals and ku = 2 superdiagonals, then scrambled: A(r, c) = B(row[r], col[c]).
struct Scrambled {
    Eigen::SparseMatrix<double> a;
    std::vector<int> row, col;
};
Scrambled scrambled_band(int n, std::mt19937& rng, bool zero_diagonal = false) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<int> row = identity(n), col = identity(n);
    std::shuffle(row.begin(), row.end(), rng);
    std::shuffle(col.begin(), col.end(), rng);
    std::vector<int> row_at(static_cast<std::size_t>(n)), col_at(static_cast<std::size_t>(n));  // inverse permutations
    for (int i = 0; i < n; ++i)
        row_at[static_cast<std::size_t>(row[static_cast<std::size_t>(i)])] = i,
        col_at[static_cast<std::size_t>(col[static_cast<std::size_t>(i)])] = i;
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i)
        for (int j = std::max(0, i - 3); j <= std::min(n - 1, i + 2); ++j) {
            const double v = i == j ? (zero_diagonal ? 0.0 : 1.0 + u(rng)) : u(rng);
            if (v != 0.0) t.emplace_back(row_at[static_cast<std::size_t>(i)], col_at[static_cast<std::size_t>(j)], v);
        }
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(t.begin(), t.end());
    return {a, row, col};
}

}  // namespace

// The band is read through the orderings (kl = 3, ku = 2 of the unscrambled matrix; far wider in
// the scrambled one's own order), and the solution is a dense partial-pivoting LU's, also after
// a re-factorisation with new values and for a matrix with a zero diagonal (pivoting needed).
TEST(BandedLu, SolvesLikeADenseLuThroughItsOrderings) {
    if (!BandedLu::available()) GTEST_SKIP() << "this build has no LAPACK";
    std::mt19937 rng(11);
    for (bool zero_diagonal : {false, true}) {
        const int n = 200;
        const Scrambled s = scrambled_band(n, rng, zero_diagonal);
        BandedLu lu(s.a, s.row, s.col);
        EXPECT_EQ(lu.lower_width(), 3);
        EXPECT_EQ(lu.upper_width(), 2);
        EXPECT_EQ(lu.storage_rows(), 2 * 3 + 2 + 1);
        const BandedLu natural(s.a, identity(n), identity(n));
        EXPECT_GT(natural.lower_width() + natural.upper_width(), 50)
            << "the scrambled matrix in its own order is not banded";
        EXPECT_THROW(static_cast<void>(lu.solve(Eigen::VectorXd::Ones(n))), std::logic_error);
        ASSERT_TRUE(lu.factorize(s.a));
        const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
        const Eigen::VectorXd dense = Eigen::MatrixXd(s.a).partialPivLu().solve(b);
        EXPECT_LT((lu.solve(b) - dense).cwiseAbs().maxCoeff(), 1e-12 * (1.0 + dense.cwiseAbs().maxCoeff()))
            << "zero diagonal: " << zero_diagonal;
        EXPECT_LT((s.a * lu.solve(b) - b).cwiseAbs().maxCoeff(), 1e-12);
        Eigen::SparseMatrix<double> a2 = s.a;
        for (int k = 0; k < a2.nonZeros(); ++k) a2.valuePtr()[k] *= 1.0 + 0.01 * (k % 7);
        ASSERT_TRUE(lu.factorize(a2));
        EXPECT_LT((a2 * lu.solve(b) - b).cwiseAbs().maxCoeff(), 1e-12);
    }
}

// A zero column is an exactly zero pivot: factorize says false and solve is refused.
TEST(BandedLu, ReportsASingularMatrix) {
    if (!BandedLu::available()) GTEST_SKIP() << "this build has no LAPACK";
    std::mt19937 rng(3);
    Scrambled s = scrambled_band(40, rng);
    s.a.prune([](Eigen::Index, Eigen::Index col, double) { return col != 7; });
    BandedLu lu(s.a, s.row, s.col);
    EXPECT_FALSE(lu.factorize(s.a));
    EXPECT_THROW(static_cast<void>(lu.solve(Eigen::VectorXd::Ones(40))), std::logic_error);
}

// Bad input names the value: an ordering that is not a permutation, a matrix that is not square,
// an entry outside the band analysed, a right-hand side of another size.
TEST(BandedLu, RefusesBadInputByName) {
    if (!BandedLu::available()) {
        EXPECT_NE(invalid_input_message([] {
                      BandedLu(Eigen::SparseMatrix<double>(2, 2), identity(2), identity(2));
                  }).find("LAPACK"),
                  std::string::npos);
        return;
    }
    std::mt19937 rng(5);
    const Scrambled s = scrambled_band(30, rng);
    std::vector<int> repeated = s.row;
    repeated[4] = repeated[9];
    EXPECT_NE(invalid_input_message([&] {
                  BandedLu(s.a, repeated, s.col);
              }).find("entry 9 is " + std::to_string(repeated[9]) + " again"),
              std::string::npos);
    std::vector<int> outside = s.col;
    outside[2] = 30;
    EXPECT_NE(invalid_input_message([&] { BandedLu(s.a, s.row, outside); }).find("entry 2 is 30"), std::string::npos);
    EXPECT_NE(invalid_input_message([&] { BandedLu(s.a, identity(29), s.col); }).find("29 entries"), std::string::npos);
    EXPECT_NE(invalid_input_message([] {
                  BandedLu(Eigen::SparseMatrix<double>(3, 4), identity(3), identity(3));
              }).find("3 × 4"),
              std::string::npos);
    BandedLu lu(s.a, s.row, s.col);
    Eigen::SparseMatrix<double> wider = s.a;
    const int r = static_cast<int>(std::find(s.row.begin(), s.row.end(), 0) - s.row.begin());   // band row 0
    const int c = static_cast<int>(std::find(s.col.begin(), s.col.end(), 29) - s.col.begin());  // band column 29
    wider.coeffRef(r, c) = 1.0;
    EXPECT_NE(invalid_input_message([&] {
                  lu.factorize(wider);
              }).find("entry (" + std::to_string(r) + ", " + std::to_string(c) + ") lies outside the band"),
              std::string::npos);
    ASSERT_TRUE(lu.factorize(s.a));
    EXPECT_NE(invalid_input_message([&] { static_cast<void>(lu.solve(Eigen::VectorXd::Ones(3))); }).find("3 entries"),
              std::string::npos);
}

// numeric/banded_or_sparse_lu.hpp: the band where it is narrow and LAPACK is there, SparseLU
// otherwise (a storage limit below the band's 2·3 + 2 + 1 = 9 rows, or 0); the same solution.
TEST(BandedOrSparseLu, TakesTheBandWhereItIsNarrowAndSolvesAlike) {
    std::mt19937 rng(5);
    const int n = 120;
    const Scrambled s = scrambled_band(n, rng);
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) b(i) = std::sin(0.3 * i) + 0.5;
    const Eigen::VectorXd expected = Eigen::MatrixXd(s.a).partialPivLu().solve(b);
    for (const int limit : {48, 8, 0}) {
        cagd::numeric::BandedOrSparseLu lu;
        lu.analyze(s.a, s.row, s.col, limit);
        EXPECT_EQ(lu.banded(), limit >= 9 && BandedLu::available()) << limit;
        ASSERT_TRUE(lu.factorize(s.a)) << limit;
        EXPECT_LE((lu.solve(b) - expected).lpNorm<Eigen::Infinity>(), 1e-10 * (1 + expected.lpNorm<Eigen::Infinity>()))
            << limit;
        // A singular matrix of the same pattern (one column zeroed) is reported, not solved.
        Eigen::SparseMatrix<double> singular = s.a;
        for (Eigen::SparseMatrix<double>::InnerIterator it(singular, 7); it; ++it) it.valueRef() = 0.0;
        EXPECT_FALSE(lu.factorize(singular)) << limit;
    }
}
