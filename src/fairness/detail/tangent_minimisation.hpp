#pragma once
// The minimisation of w over a tangent angle (pseudo_energy eq 12) by the modes of
// pseudo_spline.hpp: Brent (exact) or the paper's three points and a parabola (approx); shared by
// the planar and the space pseudo-spline.
#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "cagd/fairness/pseudo_spline.hpp"

namespace cagd::fairness::detail {

// Minimiser of w over [lo, hi] (lo ≤ hi) by the chosen mode.
template <class W>
double minimise_w(const W& w, double lo, double hi, TangentOptimization mode) {
    if (hi - lo <= 0.0) return lo;
    if (mode == TangentOptimization::exact) {
        std::uintmax_t iters = 200;
        return boost::math::tools::brent_find_minima(w, lo, hi, std::numeric_limits<double>::digits / 2, iters).first;
    }
    // Approximate: the paper's three interior points and quadratic interpolation.
    const double h = (hi - lo) / 4.0;
    const double a = lo + h, b = lo + 2 * h, c = lo + 3 * h;
    const double wa = w(a), wb = w(b), wc = w(c);
    const double curvature = wa - 2 * wb + wc;  // h² × second derivative of the parabola
    // Differences of w within rounding of its values decide nothing: a parabola that is not clearly
    // convex is treated as a line (or a constant), and a line or concave parabola is least over the
    // interval at its lower end. (Deciding by the sign of a curvature that is rounding noise — w is
    // linear inside a table cell — sent α to lo in one orientation of the points and to lo + ¼ of
    // the interval in a rotated copy: 3.5e-3 of the diagonal.)
    const double noise = 64.0 * std::numeric_limits<double>::epsilon() * std::max({std::abs(wa), std::abs(wb), std::abs(wc)});
    if (curvature > noise) {
        const double vertex = b + h * (wa - wc) / (2.0 * curvature);
        return std::clamp(vertex, lo, hi);
    }
    if (std::abs(wa - wc) <= noise) return b;  // flat within rounding
    return wa < wc ? lo : hi;
}

}  // namespace cagd::fairness::detail
