#include "cagd/numeric/rational.hpp"

#include <cmath>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

Fraction simplest_fraction_within(double x, double tol) {
    if (!std::isfinite(x) || !(tol > 0.0))
        fail_input("cagd::numeric::simplest_fraction_within",
                   "needs finite x and tol > 0, got x = " + full_precision(x) + ", tol = " + full_precision(tol));
    const double lo = x - tol, hi = x + tol;
    const auto fl = static_cast<std::int64_t>(std::floor(lo));
    if (std::ceil(lo) <= hi) return {static_cast<std::int64_t>(std::ceil(lo)), 1};
    // Stern–Brocot between fl/1 and (fl+1)/1.
    std::int64_t a = fl, b = 1, c = fl + 1, d = 1;
    for (int guard = 0; guard < 100000; ++guard) {
        const std::int64_t p = a + c, q = b + d;
        const double v = double(p) / double(q);
        if (v < lo) {
            a = p;
            b = q;
        } else if (v > hi) {
            c = p;
            d = q;
        } else
            return {p, q};
    }
    fail_input("cagd::numeric::simplest_fraction_within", "tolerance " + full_precision(tol) + " too small");
}

}  // namespace cagd::numeric
