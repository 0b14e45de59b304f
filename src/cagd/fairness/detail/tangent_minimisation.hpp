#pragma once
// The minimisation of w over a tangent angle (pseudo_energy eq 12) by the modes of
// pseudo_spline.hpp: Brent (exact) or the paper's three points and a parabola (approx); shared by
// the planar and the space pseudo-spline.
#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

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
        const std::pair<double, double> found = boost::math::tools::brent_find_minima(w, lo, hi, std::numeric_limits<double>::digits / 2, iters);
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

}  // namespace cagd::fairness::detail
