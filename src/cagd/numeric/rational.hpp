#pragma once
/// @file
/// The simplest fraction p/q (smallest q > 0) with |p/q − x| ≤ tol, by walking the
/// Stern–Brocot tree. Used to check a paper's "rationalised to k decimals" weights
/// (sb2_locality eq 18: 1/(1+α) → 56/41). Preconditions: x finite, tol > 0.
#include <cstdint>

namespace cagd::numeric {

/// A fraction p/q with q > 0.
struct Fraction {
    std::int64_t numerator;    ///< p
    std::int64_t denominator;  ///< q > 0
    /// p/q in double.
    double value() const { return double(numerator) / double(denominator); }
};

/// The simplest fraction within tol of x (smallest denominator).
Fraction simplest_fraction_within(double x, double tol);

}  // namespace cagd::numeric
