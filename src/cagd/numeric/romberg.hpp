#pragma once
/// @file
/// Romberg integration: the reference quadrature the papers prescribe.
///
/// Trapezoid sums T(h), h = (b−a)/2^k, extrapolated by Richardson's scheme
/// R(k, j) = R(k, j−1) + (R(k, j−1) − R(k−1, j−1)) / (4^j − 1).
/// The error estimate is |R(k, k) − R(k−1, k−1)|; the result is converged when that
/// estimate is ≤ max(rel_tol·|R(k, k)|, abs_tol) for two consecutive levels (a single
/// small difference can be a coincidence of the trapezoid samples).
/// Accuracy: O(h^{2k+2}) for integrands smooth on [a, b]; integrate piecewise smooth
/// functions piece by piece. Cost: 2^max_levels + 1 evaluations at most.
/// Not converging within max_levels is an Outcome, not an exception.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

/// What romberg returns: the integral, its error estimate, the work done and the outcome.
struct RombergResult {
    double value = 0.0;           ///< the integral at the last level
    double error_estimate = 0.0;  ///< |R(k,k) − R(k−1,k−1)| at the last level
    int levels = 0;               ///< k reached
    long evaluations = 0;         ///< integrand evaluations
    Outcome outcome;              ///< ok, or no_convergence when max_levels did not meet the tolerances
};

/// Preconditions: a, b finite; rel_tol > 0; abs_tol ≥ 0; 2 ≤ max_levels ≤ 30.
RombergResult romberg(const std::function<double(double)>& f, double a, double b, double rel_tol = 1e-12,
                      double abs_tol = 0.0, int max_levels = 24);

/// The same scheme for N integrals sharing one integrand evaluation, f(t) → std::array<double, N>:
/// converged when every component meets the test above at two consecutive levels, with the
/// relative test taken against the trapezoid sum of |f_c| (QUADPACK's "resabs"), so that an
/// integral that cancels to ~0 — a gradient component at a minimum — still converges.
template <std::size_t N>
struct RombergVectorResult {
    std::array<double, N> value{};           ///< the N integrals
    std::array<double, N> error_estimate{};  ///< their error estimates (as for romberg)
    int levels = 0;                          ///< levels reached
    long evaluations = 0;                    ///< evaluations of the integrand (points, each giving all N values)
    Outcome outcome;                         ///< ok, or no_convergence
};

/// The points of a level are handed to the integrand in batches of up to kRombergBatch:
/// fb(const double* t, std::size_t m, std::array<double, N>* out) fills out[0..m), so an integrand
/// can evaluate them together (vectorised); the sums still run point by point in order, so the
/// result is that of romberg_vector with the same integrand one point at a time.
inline constexpr std::size_t kRombergBatch = 16;

template <std::size_t N, class FB>
/// N integrals of one batched integrand fb over [a, b] (see kRombergBatch).
RombergVectorResult<N> romberg_vector_batched(const FB& fb, double a, double b, double rel_tol = 1e-12,
                                              double abs_tol = 0.0, int max_levels = 24) {
    using Row = std::vector<std::array<double, N>>;
    const std::string who = "cagd::numeric::romberg_vector";
    if (!std::isfinite(a) || !std::isfinite(b))
        fail_input(who, "interval [" + full_precision(a) + ", " + full_precision(b) + "] must be finite");
    if (!(rel_tol > 0.0)) fail_input(who, "rel_tol must be > 0, got " + full_precision(rel_tol));
    if (!(abs_tol >= 0.0)) fail_input(who, "abs_tol must be >= 0, got " + full_precision(abs_tol));
    if (max_levels < 2 || max_levels > 30)
        fail_input(who, "max_levels must be in [2, 30], got " + std::to_string(max_levels));
    RombergVectorResult<N> r;
    const double h0 = b - a;
    const std::array<double, 2> ends{a, b};
    std::array<std::array<double, N>, 2> f_ends;
    fb(ends.data(), 2, f_ends.data());
    const std::array<double, N>&fa = f_ends[0], &f_b = f_ends[1];
    Row prev(1), cur;
    std::array<double, N> abs_trap{};
    for (std::size_t c = 0; c < N; ++c) {
        prev[0][c] = 0.5 * h0 * (fa[c] + f_b[c]);
        abs_trap[c] = 0.5 * h0 * (std::abs(fa[c]) + std::abs(f_b[c]));
    }
    r.evaluations = 2;
    int small_in_a_row = 0;
    for (int k = 1; k <= max_levels; ++k) {
        const long n_new = 1L << (k - 1);
        const double h = h0 / static_cast<double>(1L << k);
        std::array<double, N> sum{}, abs_sum{};
        std::array<double, kRombergBatch> t;
        std::array<std::array<double, N>, kRombergBatch> v;
        for (long i0 = 0; i0 < n_new; i0 += static_cast<long>(kRombergBatch)) {
            const std::size_t m =
                static_cast<std::size_t>(std::min<long>(static_cast<long>(kRombergBatch), n_new - i0));
            for (std::size_t i = 0; i < m; ++i) t[i] = a + static_cast<double>(2 * (i0 + static_cast<long>(i)) + 1) * h;
            fb(t.data(), m, v.data());
            for (std::size_t i = 0; i < m; ++i)
                for (std::size_t c = 0; c < N; ++c) {
                    sum[c] += v[i][c];
                    abs_sum[c] += std::abs(v[i][c]);
                }
        }
        r.evaluations += n_new;
        cur.assign(static_cast<std::size_t>(k + 1), std::array<double, N>{});
        for (std::size_t c = 0; c < N; ++c) {
            cur[0][c] = 0.5 * prev[0][c] + h * sum[c];
            abs_trap[c] = 0.5 * abs_trap[c] + h * abs_sum[c];
        }
        double factor = 1.0;
        for (int j = 1; j <= k; ++j) {
            factor *= 4.0;
            for (std::size_t c = 0; c < N; ++c)
                cur[j][c] = cur[j - 1][c] + (cur[j - 1][c] - prev[j - 1][c]) / (factor - 1.0);
        }
        bool small = true;
        for (std::size_t c = 0; c < N; ++c) {
            r.value[c] = cur[k][c];
            r.error_estimate[c] = std::abs(cur[k][c] - prev[k - 1][c]);
            if (!std::isfinite(r.value[c])) {
                r.levels = k;
                r.outcome = {Status::no_convergence,
                             who + ": integrand produced a non-finite value at level " + std::to_string(k)};
                return r;
            }
            small = small &&
                    r.error_estimate[c] <= std::max(rel_tol * std::max(std::abs(r.value[c]), abs_trap[c]), abs_tol);
        }
        r.levels = k;
        small_in_a_row = small ? small_in_a_row + 1 : 0;
        if (small_in_a_row >= 2 && k >= 4) return r;
        prev.swap(cur);
    }
    r.outcome = {Status::no_convergence, who + ": no convergence after " + std::to_string(max_levels) + " levels"};
    return r;
}

/// The same with an integrand of one point, f(t) → std::array<double, N>.
template <std::size_t N, class F>
RombergVectorResult<N> romberg_vector(const F& f, double a, double b, double rel_tol = 1e-12, double abs_tol = 0.0,
                                      int max_levels = 24) {
    return romberg_vector_batched<N>(
        [&f](const double* t, std::size_t m, std::array<double, N>* out) {
            for (std::size_t i = 0; i < m; ++i) out[i] = f(t[i]);
        },
        a, b, rel_tol, abs_tol, max_levels);
}

}  // namespace cagd::numeric
