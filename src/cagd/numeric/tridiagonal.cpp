#include "cagd/numeric/tridiagonal.hpp"

#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

namespace {

// The elimination of solve_tridiagonal on the columns of x (n rows each, column j at x + j·n),
// with the column count fixed at compile time where it is small (Cols = 0: `cols` at run time).
// One pass computes pivot r and eliminates row r of every column, so the division chain of the
// pivots and those of the columns overlap (each used to wait for the one before); the operations
// on each entry, and their order, are those of the textbook form (row r −= sub[r] · row r−1,
// row r /= pivot r; back-substitution with c[r] = sup[r] / pivot r), so the results are the same
// to the bit.
template <int Cols>
void thomas_in_place(const char* who, const std::vector<double>& sub, const std::vector<double>& diag, const std::vector<double>& sup, double* x, std::size_t n,
                     std::size_t runtime_cols) {
    const std::size_t cols = Cols > 0 ? static_cast<std::size_t>(Cols) : runtime_cols;
    const auto zero_pivot = [&](std::size_t r) { fail_input(who, "zero pivot at row " + std::to_string(r) + " (the matrix needs pivoting)"); };
    std::vector<double> c;  // filled in order, without zeroing it first (at 10^7 rows a pass over 80 MB)
    c.reserve(n);
    double pivot = diag[0];
    if (pivot == 0.0) zero_pivot(0);
    c.push_back(n > 1 ? sup[0] / pivot : 0.0);
    for (std::size_t j = 0; j < cols; ++j) x[j * n] /= pivot;
    for (std::size_t r = 1; r < n; ++r) {
        pivot = diag[r] - sub[r] * c[r - 1];
        if (pivot == 0.0) [[unlikely]]
            zero_pivot(r);
        c.push_back(r + 1 < n ? sup[r] / pivot : 0.0);
        for (std::size_t j = 0; j < cols; ++j) {
            double* column = x + j * n;
            column[r] -= sub[r] * column[r - 1];
            column[r] /= pivot;
        }
    }
    for (std::size_t r = n - 1; r-- > 0;)
        for (std::size_t j = 0; j < cols; ++j) {
            double* column = x + j * n;
            column[r] -= c[r] * column[r + 1];
        }
}

}  // namespace

Eigen::MatrixXd solve_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag, const std::vector<double>& sup, Eigen::MatrixXd rhs) {
    const char* who = "cagd::numeric::solve_tridiagonal";
    const std::size_t n = diag.size();
    if (n == 0 || sub.size() != n || sup.size() != n || static_cast<std::size_t>(rhs.rows()) != n)
        fail_input(who, "needs sub, diag, sup and the right-hand side of one length n >= 1");
    const auto cols = static_cast<std::size_t>(rhs.cols());
    double* x = rhs.data();  // column-major, column j at x + j·n
    switch (cols) {
        case 1: thomas_in_place<1>(who, sub, diag, sup, x, n, cols); break;
        case 2: thomas_in_place<2>(who, sub, diag, sup, x, n, cols); break;
        case 3: thomas_in_place<3>(who, sub, diag, sup, x, n, cols); break;
        default: thomas_in_place<0>(who, sub, diag, sup, x, n, cols);
    }
    return rhs;
}

Eigen::MatrixXd solve_cyclic_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag, const std::vector<double>& sup, const Eigen::MatrixXd& rhs) {
    const char* who = "cagd::numeric::solve_cyclic_tridiagonal";
    const std::size_t n = diag.size();
    if (n < 3 || sub.size() != n || sup.size() != n || static_cast<std::size_t>(rhs.rows()) != n)
        fail_input(who, "needs sub, diag, sup and the right-hand side of one length n >= 3");
    if (diag[0] == 0.0) fail_input(who, "zero diagonal entry at row 0");
    const double alpha = sub[0], beta = sup[n - 1], gamma = -diag[0];
    std::vector<double> modified = diag;
    modified[0] -= gamma;
    modified[n - 1] -= alpha * beta / gamma;
    const Eigen::Index cols = rhs.cols(), last = static_cast<Eigen::Index>(n - 1);
    Eigen::MatrixXd both = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), cols + 1);
    both.leftCols(cols) = rhs;
    both(0, cols) = gamma;
    both(last, cols) = beta;
    both = solve_tridiagonal(sub, modified, sup, std::move(both));
    const double denominator = 1.0 + both(0, cols) + alpha * both(last, cols) / gamma;
    if (denominator == 0.0) fail_input(who, "singular cyclic system (Sherman-Morrison denominator 0)");
    Eigen::MatrixXd x = both.leftCols(cols);
    const Eigen::RowVectorXd factor = (x.row(0) + alpha * x.row(last) / gamma) / denominator;
    x -= both.col(cols) * factor;
    return x;
}

}  // namespace cagd::numeric
