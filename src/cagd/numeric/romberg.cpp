#include "cagd/numeric/romberg.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace cagd::numeric {

RombergResult romberg(const std::function<double(double)>& f, double a, double b, double rel_tol, double abs_tol,
                      int max_levels) {
    const std::string who = "cagd::numeric::romberg";
    if (!std::isfinite(a) || !std::isfinite(b))
        fail_input(who, "interval [" + full_precision(a) + ", " + full_precision(b) + "] must be finite");
    if (!(rel_tol > 0.0)) fail_input(who, "rel_tol must be > 0, got " + full_precision(rel_tol));
    if (!(abs_tol >= 0.0)) fail_input(who, "abs_tol must be >= 0, got " + full_precision(abs_tol));
    if (max_levels < 2 || max_levels > 30)
        fail_input(who, "max_levels must be in [2, 30], got " + std::to_string(max_levels));

    RombergResult r;
    const double h0 = b - a;
    std::vector<double> prev, cur;
    double trap = 0.5 * h0 * (f(a) + f(b));
    r.evaluations = 2;
    prev.push_back(trap);
    int small_in_a_row = 0;
    for (int k = 1; k <= max_levels; ++k) {
        const long n_new = 1L << (k - 1);
        const double h = h0 / static_cast<double>(1L << k);
        double sum = 0.0;
        for (long i = 0; i < n_new; ++i) sum += f(a + static_cast<double>(2 * i + 1) * h);
        r.evaluations += n_new;
        cur.assign(static_cast<std::size_t>(k + 1), 0.0);
        cur[0] = 0.5 * prev[0] + h * sum;
        double factor = 1.0;
        for (int j = 1; j <= k; ++j) {
            factor *= 4.0;
            cur[j] = cur[j - 1] + (cur[j - 1] - prev[j - 1]) / (factor - 1.0);
        }
        r.value = cur[k];
        r.error_estimate = std::abs(cur[k] - prev[k - 1]);
        r.levels = k;
        if (!std::isfinite(r.value)) {
            r.outcome = {Status::no_convergence,
                         who + ": integrand produced a non-finite value at level " + std::to_string(k)};
            return r;
        }
        const bool small = r.error_estimate <= std::max(rel_tol * std::abs(r.value), abs_tol);
        small_in_a_row = small ? small_in_a_row + 1 : 0;
        if (small_in_a_row >= 2 && k >= 4) return r;
        prev.swap(cur);
    }
    r.outcome = {Status::no_convergence, who + ": no convergence after " + std::to_string(max_levels) +
                                             " levels, error estimate " + full_precision(r.error_estimate)};
    return r;
}

}  // namespace cagd::numeric
