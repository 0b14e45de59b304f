#pragma once
/// @file
/// Boost.Math's interpolants as peers of the registry's methods, called as their users call them
/// and converted exactly into the one piecewise cubic Hermite form (spline/hermite_spline.hpp):
///
/// - pchip and makima (`boost/math/interpolators/pchip.hpp`, `makima.hpp`): one interpolator per
///   coordinate over the chord-length parameter τ (τ_0 = 0, τ_{k+1} = τ_k + |P_{k+1} − P_k|); open
///   curves, at least 4 points (Boost's minimum);
/// - catmull_rom (`boost/math/interpolators/catmull_rom.hpp`): centripetal (α = 1/2), open or
///   closed, 2-D or 3-D, over Boost's own parameter (a running sum of |ΔP|^½).
///
/// Each is a cubic between consecutive nodes, so it is the Hermite spline of its values and its
/// slopes at the nodes; the slopes are read through Boost's public `prime(τ_k)`, nothing is
/// recomputed here, and the converted curve is Boost's (d/du at a span's ends = h_k · prime, bit for
/// bit: tests/methods/test_boost_peers.cpp). The data points sit at u = 0, 1, …; dτ/du = h_k.
/// Cost: Boost's construction and one prime (a binary search) per node and coordinate, O(n log n).
/// Preconditions (InvalidInput): as methods::interpolate checks them, and for catmull_rom every step
/// of Boost's parameter (the n + 1 steps, its wrap-around ghost nodes included) above 1e-12 of their
/// sum: a shorter one vanishes in double precision and Boost's span search reads past its arrays.
#include "cagd/core/points.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::methods {

/// Boost.Math pchip on each coordinate over the chord-length parameter (open curves, n ≥ 4).
Interpolant boost_pchip_interpolant(const PointList& p);
/// Boost.Math makima on each coordinate over the chord-length parameter (open curves, n ≥ 4).
Interpolant boost_makima_interpolant(const PointList& p);
/// Boost.Math's centripetal Catmull–Rom (α = 1/2), open or closed, 2-D or 3-D.
Interpolant boost_catmull_rom_interpolant(const PointList& p, bool closed);

}  // namespace cagd::methods
