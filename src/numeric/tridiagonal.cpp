#include "numeric/tridiagonal.hpp"

#include <string>

#include "core/errors.hpp"

namespace cagd::numeric {

Eigen::MatrixXd solve_tridiagonal(const std::vector<double>& sub, const std::vector<double>& diag, const std::vector<double>& sup, Eigen::MatrixXd rhs) {
    const char* who = "cagd::numeric::solve_tridiagonal";
    const std::size_t n = diag.size();
    if (n == 0 || sub.size() != n || sup.size() != n || static_cast<std::size_t>(rhs.rows()) != n)
        fail_input(who, "needs sub, diag, sup and the right-hand side of one length n >= 1");
    std::vector<double> c(n);  // modified super-diagonal
    double pivot = diag[0];
    for (std::size_t r = 0; r < n; ++r) {
        if (r > 0) {
            pivot = diag[r] - sub[r] * c[r - 1];
            rhs.row(static_cast<Eigen::Index>(r)) -= sub[r] * rhs.row(static_cast<Eigen::Index>(r - 1));
        }
        if (pivot == 0.0) fail_input(who, "zero pivot at row " + std::to_string(r) + " (the matrix needs pivoting)");
        c[r] = r + 1 < n ? sup[r] / pivot : 0.0;
        rhs.row(static_cast<Eigen::Index>(r)) /= pivot;
    }
    for (std::size_t r = n - 1; r-- > 0;) rhs.row(static_cast<Eigen::Index>(r)) -= c[r] * rhs.row(static_cast<Eigen::Index>(r + 1));
    return rhs;
}

}  // namespace cagd::numeric
