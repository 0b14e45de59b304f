#pragma once
/// @file
/// The LU of a sequence of square sparse matrices of one pattern by the cheaper of two
/// factorisations: LAPACK's banded LU (numeric/banded_lu.hpp) where the pattern's band under the
/// given row and column orderings is narrow and the build has LAPACK, Eigen's SparseLU
/// (numeric/sparse_lu.hpp) otherwise — a wide band (a closed curve's closing rows), no LAPACK (the
/// WebAssembly build), or a caller that asks for SparseLU alone. Either is Gaussian elimination
/// with partial pivoting, so the solutions agree to rounding.
///
/// Use: analyze(pattern, …) once per pattern, then factorize and solve for each matrix of it.
/// Outcomes: factorize returns false for a singular matrix (an exactly zero pivot, or Eigen's
/// report). Preconditions: those of the two factorisations (InvalidInput for orderings that are not
/// permutations; solve before a successful factorize throws std::logic_error).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>
#include <vector>

#include "cagd/numeric/banded_lu.hpp"
#include "cagd/numeric/sparse_lu.hpp"

namespace cagd::numeric {

/// Banded LU where the band is narrow, sparse LU otherwise (see above).
class BandedOrSparseLu {
public:
    /// `sparse_ordering`: the column ordering of the sparse LU, when it is the one used.
    explicit BandedOrSparseLu(ColumnOrdering sparse_ordering = ColumnOrdering::colamd) : sparse_(sparse_ordering) {}

    /// Prepares for matrices of `pattern`'s pattern: the banded LU with row r of A at
    /// row_position[r] and column c at column_position[c] when this build has LAPACK and that band
    /// takes at most max_storage_rows rows of band storage (BandedLu::storage_rows); otherwise the
    /// sparse LU's symbolic analysis. max_storage_rows = 0 asks for the sparse LU (the orderings
    /// are then not read). Call again when the pattern changes.
    void analyze(const Eigen::SparseMatrix<double>& pattern, std::vector<int> row_position,
                 std::vector<int> column_position, int max_storage_rows);
    /// The numeric factorisation of A (the pattern analysed); false when A is singular.
    bool factorize(const Eigen::SparseMatrix<double>& a) { return band_ ? band_->factorize(a) : sparse_.factorize(a); }
    /// x with A x = b after a successful factorize.
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return band_ ? band_->solve(b) : sparse_.solve(b); }
    /// True when the banded LU is the one used.
    bool banded() const { return band_.has_value(); }

private:
    SparseLu sparse_;
    std::optional<BandedLu> band_;
};

}  // namespace cagd::numeric
