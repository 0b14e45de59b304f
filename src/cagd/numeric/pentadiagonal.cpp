#include "cagd/numeric/pentadiagonal.hpp"

#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

Eigen::MatrixXd solve_symmetric_pentadiagonal(const std::vector<double>& diag, const std::vector<double>& first,
                                              const std::vector<double>& second, Eigen::MatrixXd rhs) {
    const char* who = "cagd::numeric::solve_symmetric_pentadiagonal";
    const std::size_t n = diag.size();
    if (n == 0 || rhs.rows() != static_cast<Eigen::Index>(n) || first.size() + 1 < n ||
        (n >= 2 && second.size() + 2 < n))
        fail_input(who,
                   "needs n diagonal, n-1 first and n-2 second off-diagonal entries and n right-hand-side rows, n = " +
                       std::to_string(n));
    std::vector<double> d(n), l1(n, 0.0), l2(n, 0.0);  // D, L(i+1, i), L(i+2, i)
    for (std::size_t i = 0; i < n; ++i) {
        double pivot = diag[i];
        if (i >= 1) pivot -= l1[i - 1] * l1[i - 1] * d[i - 1];
        if (i >= 2) pivot -= l2[i - 2] * l2[i - 2] * d[i - 2];
        if (!(pivot > 0.0))
            fail_input(who, "pivot " + std::to_string(i) + " is " + full_precision(pivot) +
                                "; the matrix is not positive definite");
        d[i] = pivot;
        if (i + 1 < n) l1[i] = (first[i] - (i >= 1 ? l1[i - 1] * l2[i - 1] * d[i - 1] : 0.0)) / pivot;
        if (i + 2 < n) l2[i] = second[i] / pivot;
    }
    for (std::size_t i = 1; i < n; ++i) {  // L z = r
        rhs.row(static_cast<Eigen::Index>(i)) -= l1[i - 1] * rhs.row(static_cast<Eigen::Index>(i - 1));
        if (i >= 2) rhs.row(static_cast<Eigen::Index>(i)) -= l2[i - 2] * rhs.row(static_cast<Eigen::Index>(i - 2));
    }
    for (std::size_t i = 0; i < n; ++i) rhs.row(static_cast<Eigen::Index>(i)) /= d[i];
    for (std::size_t k = n; k-- > 0;) {  // Lᵀ x = z
        if (k + 1 < n) rhs.row(static_cast<Eigen::Index>(k)) -= l1[k] * rhs.row(static_cast<Eigen::Index>(k + 1));
        if (k + 2 < n) rhs.row(static_cast<Eigen::Index>(k)) -= l2[k] * rhs.row(static_cast<Eigen::Index>(k + 2));
    }
    return rhs;
}

}  // namespace cagd::numeric
