#include "cagd/numeric/tridiagonal.hpp"

#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

Eigen::MatrixXd solve_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag,
                                  const std::vector<double>& sup, Eigen::MatrixXd rhs) {
    const char* who = "cagd::numeric::solve_tridiagonal";
    const std::size_t n = diag.size();
    if (n == 0 || sub.size() != n || sup.size() != n || static_cast<std::size_t>(rhs.rows()) != n)
        fail_input(who, "needs sub, diag, sup and the right-hand side of one length n >= 1");
    // The rows' right-hand sides are already in place in rhs (column-major, column j at x + j·n).
    detail::solve_tridiagonal_rows(
        who, n, static_cast<std::size_t>(rhs.cols()),
        [&](std::size_t r, double*, std::size_t) {
            return TridiagonalRow{sub[r], diag[r], sup[r]};
        },
        rhs.data());
    return rhs;
}

Eigen::MatrixXd solve_cyclic_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag,
                                         const std::vector<double>& sup, const Eigen::MatrixXd& rhs) {
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
