#include "cagd/numeric/tridiagonal.hpp"

#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

Eigen::MatrixXd solve_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag, const std::vector<double>& sup, Eigen::MatrixXd rhs) {
    const char* who = "cagd::numeric::solve_tridiagonal";
    const std::size_t n = diag.size();
    if (n == 0 || sub.size() != n || sup.size() != n || static_cast<std::size_t>(rhs.rows()) != n)
        fail_input(who, "needs sub, diag, sup and the right-hand side of one length n >= 1");
    // The pivots and the modified super-diagonal once, then each column (contiguous in memory) by
    // the same elimination: row r −= sub[r] · row r−1, row r /= pivot r; back-substitution.
    std::vector<double> c(n), pivot(n);
    for (std::size_t r = 0; r < n; ++r) {
        pivot[r] = r == 0 ? diag[0] : diag[r] - sub[r] * c[r - 1];
        if (pivot[r] == 0.0) fail_input(who, "zero pivot at row " + std::to_string(r) + " (the matrix needs pivoting)");
        c[r] = r + 1 < n ? sup[r] / pivot[r] : 0.0;
    }
    for (Eigen::Index col = 0; col < rhs.cols(); ++col) {
        double* x = rhs.col(col).data();
        x[0] /= pivot[0];
        for (std::size_t r = 1; r < n; ++r) {
            x[r] -= sub[r] * x[r - 1];
            x[r] /= pivot[r];
        }
        for (std::size_t r = n - 1; r-- > 0;) x[r] -= c[r] * x[r + 1];
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
