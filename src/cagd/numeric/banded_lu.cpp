#include "cagd/numeric/banded_lu.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "cagd/core/errors.hpp"

#if CAGD_WITH_LAPACK
// LAPACK's Fortran entry points (reference LAPACK and its drop-in replacements share this ABI;
// gfortran passes a CHARACTER argument's length after the others).
extern "C" {
void dgbtrf_(const int* m, const int* n, const int* kl, const int* ku, double* ab, const int* ldab, int* ipiv,
             int* info);
void dgbtrs_(const char* trans, const int* n, const int* kl, const int* ku, const int* nrhs, const double* ab,
             const int* ldab, const int* ipiv, double* b, const int* ldb, int* info, std::size_t trans_length);
}
#endif

namespace cagd::numeric {

namespace {

void require_permutation(const std::vector<int>& position, int n, const char* what) {
    const std::string who = "numeric::BandedLu";
    if (static_cast<int>(position.size()) != n)
        fail_input(who, std::string(what) + " ordering has " + std::to_string(position.size()) +
                            " entries for a matrix of size " + std::to_string(n));
    std::vector<char> seen(static_cast<std::size_t>(n), 0);
    for (std::size_t i = 0; i < position.size(); ++i) {
        const int p = position[i];
        if (p < 0 || p >= n || seen[static_cast<std::size_t>(p)])
            fail_input(who, std::string(what) + " ordering is not a permutation of 0.." + std::to_string(n - 1) +
                                ": entry " + std::to_string(i) + " is " + std::to_string(p) +
                                (p >= 0 && p < n ? " again" : ""));
        seen[static_cast<std::size_t>(p)] = 1;
    }
}

}  // namespace

bool BandedLu::available() { return CAGD_WITH_LAPACK != 0; }

BandedLu::BandedLu(const Eigen::SparseMatrix<double>& pattern, std::vector<int> row_position,
                   std::vector<int> column_position)
    : n_(static_cast<int>(pattern.rows())),
      row_position_(std::move(row_position)),
      column_position_(std::move(column_position)) {
    const std::string who = "numeric::BandedLu";
    if (!available())
        fail_input(
            who,
            "needs a cagd library built with LAPACK (CMake option CAGD_WITH_LAPACK); this one was built without it");
    if (pattern.rows() != pattern.cols())
        fail_input(who, "needs a square matrix, got " + std::to_string(pattern.rows()) + " × " +
                            std::to_string(pattern.cols()));
    require_permutation(row_position_, n_, "the row");
    require_permutation(column_position_, n_, "the column");
    for (int c = 0; c < pattern.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(pattern, c); it; ++it) {
            const int i = row_position_[static_cast<std::size_t>(it.row())],
                      j = column_position_[static_cast<std::size_t>(c)];
            kl_ = std::max(kl_, i - j);
            ku_ = std::max(ku_, j - i);
        }
}

bool BandedLu::factorize(const Eigen::SparseMatrix<double>& a) {
    factored_ = false;
    if (a.rows() != n_ || a.cols() != n_)
        fail_input("numeric::BandedLu::factorize", "the matrix is " + std::to_string(a.rows()) + " × " +
                                                       std::to_string(a.cols()) + ", the band was set up for " +
                                                       std::to_string(n_));
    const int ld = storage_rows();
    band_.assign(static_cast<std::size_t>(ld) * static_cast<std::size_t>(n_), 0.0);
    pivots_.resize(static_cast<std::size_t>(n_));
    // Band storage (LAPACK): B(i, j) at band_[j·ld + kl + ku + i − j]; the top kl rows take the fill.
    for (int c = 0; c < a.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it) {
            const int i = row_position_[static_cast<std::size_t>(it.row())],
                      j = column_position_[static_cast<std::size_t>(c)];
            if (i - j > kl_ || j - i > ku_)
                fail_input("numeric::BandedLu::factorize",
                           "entry (" + std::to_string(it.row()) + ", " + std::to_string(c) +
                               ") lies outside the band (kl = " + std::to_string(kl_) +
                               ", ku = " + std::to_string(ku_) + ") of the pattern analysed");
            band_[static_cast<std::size_t>(j) * static_cast<std::size_t>(ld) +
                  static_cast<std::size_t>(kl_ + ku_ + i - j)] = it.value();
        }
    if (n_ == 0) return factored_ = true;
#if CAGD_WITH_LAPACK
    int info = 0;
    dgbtrf_(&n_, &n_, &kl_, &ku_, band_.data(), &ld, pivots_.data(), &info);
    if (info < 0) throw std::logic_error("cagd::numeric::BandedLu: dgbtrf rejected argument " + std::to_string(-info));
    factored_ = info == 0;
#endif
    return factored_;
}

Eigen::VectorXd BandedLu::solve(const Eigen::VectorXd& b) const {
    if (!factored_) throw std::logic_error("cagd::numeric::BandedLu::solve before a successful factorisation");
    if (b.size() != n_)
        fail_input("numeric::BandedLu::solve", "the right-hand side has " + std::to_string(b.size()) +
                                                   " entries for a matrix of size " + std::to_string(n_));
    // R A C x = R b: permute b, solve, and read x back through C.
    std::vector<double> y(static_cast<std::size_t>(n_));
    for (int r = 0; r < n_; ++r) y[static_cast<std::size_t>(row_position_[static_cast<std::size_t>(r)])] = b(r);
#if CAGD_WITH_LAPACK
    if (n_ > 0) {
        const int ld = storage_rows(), one = 1;
        int info = 0;
        dgbtrs_("N", &n_, &kl_, &ku_, &one, band_.data(), &ld, pivots_.data(), y.data(), &n_, &info, 1);
        if (info != 0)
            throw std::logic_error("cagd::numeric::BandedLu: dgbtrs rejected argument " + std::to_string(-info));
    }
#endif
    Eigen::VectorXd x(n_);
    for (int c = 0; c < n_; ++c) x(c) = y[static_cast<std::size_t>(column_position_[static_cast<std::size_t>(c)])];
    return x;
}

}  // namespace cagd::numeric
