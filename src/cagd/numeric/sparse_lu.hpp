#pragma once
/// @file
/// Sparse LU with partial pivoting (Eigen::SparseLU: supernodal, threshold pivoting along the
/// columns of A Q) behind an interface compiled once. P A Q = L U with the column ordering Q chosen
/// by COLAMD (fill-reducing, the default) or left natural (a system whose fill is already at the
/// ends, e.g. a cyclic banded one). Solving is then the two triangular solves, for one right-hand
/// side or several.
///
/// Why a wrapper: Eigen's SparseLU is a header template that costs about 6 s of compile time in each
/// translation unit that instantiates it; the splines, the elastic line, the locality spline and the
/// curvature-profile Newton each did. The arithmetic is Eigen's, unchanged.
///
/// Use: compute(A) (= analyze_pattern(A) then factorize(A)), or, for a sequence of matrices of one
/// sparsity pattern, analyze_pattern once and factorize each; then solve. factorize/compute return
/// false when Eigen reports failure (a structurally or numerically singular A); solve before a
/// successful factorisation throws std::logic_error.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace cagd::numeric {

/// The column ordering Q: COLAMD (fill-reducing) or the matrix's own.
enum class ColumnOrdering { colamd, natural };

/// P A Q = L U of a square sparse matrix (Eigen::SparseLU, compiled once).
class SparseLu {
public:
    /// An empty factorisation with the given column ordering.
    explicit SparseLu(ColumnOrdering ordering = ColumnOrdering::colamd);
    ~SparseLu();
    /// Moves the factorisation.
    SparseLu(SparseLu&&) noexcept;
    /// Moves the factorisation.
    SparseLu& operator=(SparseLu&&) noexcept;

    /// The symbolic analysis (ordering, elimination tree) of A's pattern.
    void analyze_pattern(const Eigen::SparseMatrix<double>& a);
    /// The numeric factorisation of A (its pattern analysed before); false if Eigen reports failure.
    bool factorize(const Eigen::SparseMatrix<double>& a);
    /// analyze_pattern(A) then factorize(A); false if Eigen reports failure.
    bool compute(const Eigen::SparseMatrix<double>& a);
    /// x with A x = b, after a successful factorisation.
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
    /// X with A X = B, after a successful factorisation.
    Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace cagd::numeric
