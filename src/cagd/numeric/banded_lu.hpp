#pragma once
/// @file
/// LU factorisation with partial pivoting of a square sparse matrix whose nonzeros lie in a narrow
/// band once its rows and columns are reordered: with B = R A C (R, C the given permutations),
///   P B = L U,   L unit lower with at most kl subdiagonals, U upper with at most kl + ku superdiagonals,
/// computed by LAPACK's dgbtrf (Gaussian elimination with partial pivoting in band storage: row
/// interchanges stay inside the band) and solved by dgbtrs. kl and ku are read from A's pattern
/// under the orderings.
///
/// Cost: O(n·kl·(kl + ku)) per factorisation, O(n·(2kl + ku)) per solve, (2kl + ku + 1)·n doubles.
/// For the curvature-profile Newton steps of an open curve (kl = ku = 4 at degree 2): the band
/// needs no fill-reducing ordering, unlike a general sparse LU.
/// Accuracy: that of Gaussian elimination with partial pivoting (backward stable in practice), the
/// same as SparseLU's threshold-1 partial pivoting; solutions agree to rounding.
/// Outcomes: factorize returns false when a pivot is exactly zero (A singular), as SparseLU does.
/// Preconditions (InvalidInput): A square; the orderings permutations of 0..n−1; the matrices
/// factorised have their nonzeros inside the band of the pattern given to the constructor.
/// Needs LAPACK (CMake option CAGD_WITH_LAPACK, on by default; off in the WebAssembly build):
/// available() says whether this build has it; without it the constructor throws InvalidInput.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace cagd::numeric {

/// P (R A C) = L U in LAPACK band storage (see above).
class BandedLu {
public:
    /// True when this build of the library has LAPACK.
    static bool available();
    /// The band of `pattern` with row r of A at position row_position[r] and column c at
    /// column_position[c]. Nothing is factorised yet.
    BandedLu(const Eigen::SparseMatrix<double>& pattern, std::vector<int> row_position,
             std::vector<int> column_position);

    int size() const { return n_; }          ///< n, the order of A
    int lower_width() const { return kl_; }  ///< kl: nonzeros at most kl below the diagonal of R A C
    int upper_width() const { return ku_; }  ///< ku: nonzeros at most ku above it
    /// Band storage rows, 2kl + ku + 1 (the factors' memory is that times n doubles).
    int storage_rows() const { return 2 * kl_ + ku_ + 1; }

    /// The numeric factorisation of A (nonzeros inside the band); false if a pivot is exactly zero.
    bool factorize(const Eigen::SparseMatrix<double>& a);
    /// x with A x = b, after a successful factorisation (std::logic_error before one).
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

private:
    int n_ = 0, kl_ = 0, ku_ = 0;
    std::vector<int> row_position_, column_position_;
    std::vector<double> band_;
    std::vector<int> pivots_;
    bool factored_ = false;
};

}  // namespace cagd::numeric
