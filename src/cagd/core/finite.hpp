#pragma once
/// @file
/// Whether every value of a dense array is finite (no ±∞, no NaN): a test of the exponent bits by
/// integer AND, ADD and OR over all values, which the compiler vectorises, with no early exit. Eigen's
/// `allFinite()` forms x − x per value and stops at the first failure, which keeps it scalar; on
/// the 10^6-point arrays a construction validates, this vectorises.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace cagd {

/// The bits of x (std::bit_cast, which Emscripten 3.1.6's libc++ lacks; compiled to a move).
inline std::uint64_t bits_of(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

/// True when none of values[0 … count − 1] is ±∞ or NaN.
inline bool all_finite(const double* values, std::size_t count) {
    // The exponent field plus one unit of it carries into the sign bit exactly when the field is all
    // ones (±∞ or NaN); for every finite value the sum stays below 2^63.
    constexpr std::uint64_t exponent = 0x7ff0000000000000ULL, unit = 0x0010000000000000ULL;
    std::uint64_t carries = 0;
    for (std::size_t i = 0; i < count; ++i) carries |= (bits_of(values[i]) & exponent) + unit;
    return (carries >> 63) == 0;
}

/// True when every coefficient of a dense, contiguous matrix or vector is finite.
template <class Derived>
bool all_finite(const Eigen::PlainObjectBase<Derived>& m) {
    return all_finite(m.data(), static_cast<std::size_t>(m.size()));
}

}  // namespace cagd
