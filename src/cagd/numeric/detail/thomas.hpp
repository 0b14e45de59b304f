#pragma once
/// @file
/// The elimination behind numeric/tridiagonal.hpp's solvers (include that header, not this one).
#include <cstddef>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

/// Row r of a tridiagonal system: sub x_{r−1} + diag x_r + sup x_{r+1}.
struct TridiagonalRow {
    double sub, diag, sup;
};

namespace detail {

// The Thomas elimination on the columns of x (n rows each, column j at x + j·n), with the column
// count fixed at compile time where it is small (Cols = 0: `cols` at run time). Row r is formed by
// row(r, x + r, n) when the elimination reaches it: it returns the row's three entries and writes
// its right-hand side to x[r + j·n] (or leaves what is there: solve_tridiagonal's rows are already
// in x). One pass computes pivot r and eliminates row r of every column, so the division chain of
// the pivots and those of the columns overlap (each used to wait for the one before); the
// operations on each entry, and their order, are those of the textbook form (row r −= sub_r · row
// r−1, row r /= pivot r; back-substitution with c_r = sup_r / pivot r), so the results are the same
// to the bit however the rows are formed.
template <int Cols, class Row>
void thomas_rows(const char* who, std::size_t n, std::size_t runtime_cols, Row&& row, double* x) {
    const std::size_t cols = Cols > 0 ? static_cast<std::size_t>(Cols) : runtime_cols;
    const auto zero_pivot = [&](std::size_t r) {
        fail_input(who, "zero pivot at row " + std::to_string(r) + " (the matrix needs pivoting)");
    };
    std::vector<double> c;  // filled in order, without zeroing it first
    c.reserve(n);
    TridiagonalRow a = row(std::size_t{0}, x, n);
    double pivot = a.diag;
    if (pivot == 0.0) zero_pivot(0);
    c.push_back(n > 1 ? a.sup / pivot : 0.0);
    for (std::size_t j = 0; j < cols; ++j) x[j * n] /= pivot;
    for (std::size_t r = 1; r < n; ++r) {
        a = row(r, x + r, n);
        pivot = a.diag - a.sub * c[r - 1];
        if (pivot == 0.0) [[unlikely]]
            zero_pivot(r);
        c.push_back(r + 1 < n ? a.sup / pivot : 0.0);
        for (std::size_t j = 0; j < cols; ++j) {
            double* column = x + j * n;
            column[r] -= a.sub * column[r - 1];
            column[r] /= pivot;
        }
    }
    for (std::size_t r = n - 1; r-- > 0;)
        for (std::size_t j = 0; j < cols; ++j) {
            double* column = x + j * n;
            column[r] -= c[r] * column[r + 1];
        }
}

// The above with the column count dispatched; errors name `who`.
template <class Row>
void solve_tridiagonal_rows(const char* who, std::size_t n, std::size_t cols, Row&& row, double* x) {
    if (n == 0) fail_input(who, "needs n >= 1 rows");
    switch (cols) {
        case 1: return thomas_rows<1>(who, n, cols, row, x);
        case 2: return thomas_rows<2>(who, n, cols, row, x);
        case 3: return thomas_rows<3>(who, n, cols, row, x);
        default: return thomas_rows<0>(who, n, cols, row, x);
    }
}

}  // namespace detail

template <class Row>
void solve_tridiagonal_rows(std::size_t n, std::size_t cols, Row&& row, double* x) {
    detail::solve_tridiagonal_rows("cagd::numeric::solve_tridiagonal_rows", n, cols, row, x);
}

}  // namespace cagd::numeric
