#pragma once
// The minimisation of w over a tangent angle (pseudo_energy eq 12) by the modes of
// pseudo_spline.hpp: Brent (exact) or the paper's three points and a parabola (approx); shared by
// the planar and the space pseudo-spline.
#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "cagd/fairness/pseudo_spline.hpp"

namespace cagd::fairness::detail {

// Minimiser of w over [lo, hi] (lo ≤ hi) by the chosen mode.
// Differences of w below this fraction of its value decide nothing. w is a sum of chord lengths times
// J: chords that are equal in the data come out of their coordinates unequal by rounding (1e-14
// relative on a helix with 64 points per turn, coordinates near 5), and data are seldom given to ten
// digits.
inline constexpr double kFlatRelative = 1e-10;

// Minimiser of w over [lo, hi] (lo ≤ hi) by the chosen mode.
template <class W>
double minimise_w(const W& w, double lo, double hi, TangentOptimization mode, TangentTie tie = {}) {
    if (hi - lo <= 0.0) return lo;
    if (mode == TangentOptimization::exact) {
        std::uintmax_t iters = 200;
        const std::pair<double, double> found =
            boost::math::tools::brent_find_minima(w, lo, hi, std::numeric_limits<double>::digits / 2, iters);
        const double x = found.first, wx = found.second;  // (not a structured binding: the lambdas below capture them)
        // J(θ) read linearly between a table's nodes makes w piecewise linear: where both of its
        // angles stay in one cell over a stretch, w is flat there and Brent stops anywhere in it,
        // as rounding decides (on a helix with 32 points per turn, 4.5° off the bisector). Take the
        // middle of the stretch of least values instead (or the point at tie.position along it).
        // A smooth w rises well above kFlatRelative within 1e-4 of the interval of its minimum
        // (relative rise ~1e-8), so it keeps Brent's point.
        const double noise = kFlatRelative * std::abs(wx);
        const auto least = [&](double a) { return w(a) <= wx + noise; };
        const double probe = 1e-4 * (hi - lo);
        const bool flat_left = x - probe >= lo && least(x - probe), flat_right = x + probe <= hi && least(x + probe);
        if (!flat_left && !flat_right) return x;
        // The stretch's ends, by bisection between x (in it) and lo or hi (when not in it).
        const auto end_toward = [&](double outer) {
            if (least(outer)) return outer;
            double in = x, out = outer;
            while (std::abs(out - in) > 1e-12 * (hi - lo)) {
                const double mid = 0.5 * (in + out);
                (least(mid) ? in : out) = mid;
            }
            return in;
        };
        const double left = end_toward(lo), right = end_toward(hi);
        return left + tie.position * (right - left);
    }
    // Approximate: the paper's three interior points and quadratic interpolation.
    const double h = (hi - lo) / 4.0;
    const double a = lo + h, b = lo + 2 * h, c = lo + 3 * h;
    const double wa = w(a), wb = w(b), wc = w(c);
    const double curvature = wa - 2 * wb + wc;  // h² × second derivative of the parabola
    // A parabola that is not clearly convex is treated as a line (or a constant), and a line or
    // concave parabola is least over the interval at its lower end. (Deciding by the sign of a
    // curvature that is rounding noise — w is linear inside a table cell — sent α to lo in one
    // orientation of the points and to lo + ¼ of the interval in a rotated copy: 3.5e-3 of the
    // diagonal; and a bound of 64 ε took a 1e-14 inequality of equal chords on a circle of 96
    // points for a slope and sent every tangent along a chord.)
    const double noise = kFlatRelative * std::max({std::abs(wa), std::abs(wb), std::abs(wc)});
    if (curvature > noise) {
        const double vertex = b + h * (wa - wc) / (2.0 * curvature);
        return std::clamp(vertex, lo, hi);
    }
    if (std::abs(wa - wc) <= noise) return b;  // flat
    return wa < wc ? lo : hi;
}

// The exact mode's minimiser when J(θ) is linear between `nodes` (ascending, one period of 2π):
// w(α) = a·J(α + τ) + b·J(α) is then linear between its breakpoints — lo, hi and every α in
// between at which α or α + τ is a node (mod 2π) — and least at one of them. All are evaluated, in
// ascending α. Ties (values within kFlatRelative of the least): the first such breakpoint (lowest
// α) and those that follow it within the same bound make a stretch on which w is flat, and
// tie.position picks the point along it, as minimise_w does for Brent's stretches. (Symmetric data
// can give w two mirror-image minima, equal but for rounding: taking the least value outright would
// let rounding choose between them, and a rotated copy of the points could take the other one.)
template <class W>
double minimise_piecewise_linear_w(const W& w, double lo, double hi, double tau, const std::vector<double>& nodes,
                                   TangentTie tie = {}) {
    if (hi - lo <= 0.0) return lo;
    std::vector<double> at{lo, hi};
    constexpr double two_pi = 2 * std::numbers::pi;
    for (const double x : nodes)
        for (const double shift : {-two_pi, 0.0, two_pi})
            for (const double c : {x + shift, x + shift - tau})
                if (c > lo && c < hi) at.push_back(c);
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    std::vector<double> value(at.size());
    for (std::size_t k = 0; k < at.size(); ++k) value[k] = w(at[k]);
    const double least = *std::min_element(value.begin(), value.end());
    const double ceiling = least + kFlatRelative * std::abs(least);
    std::size_t first = 0;
    while (value[first] > ceiling) ++first;
    std::size_t last = first;
    while (last + 1 < at.size() && value[last + 1] <= ceiling) ++last;
    if (first == last) return at[first];
    return at[first] + tie.position * (at[last] - at[first]);
}

}  // namespace cagd::fairness::detail
