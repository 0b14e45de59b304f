#pragma once
/// @file
/// The forms in which the registry's builders hand curves over (methods/method_registry.hpp):
/// unit spans (u = 0, 1, …, one span per data span) and a piecewise cubic Hermite curve from
/// τ-slopes at the nodes (Boost.Math's interpolants, converted exactly).
#include <memory>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/core/points.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::methods {

/// A curve whose data points sit at u = 0, 1, …, nodes − 1, with dτ/du per span.
Interpolant unit_span_interpolant(std::shared_ptr<const Curve> curve, Eigen::Index nodes, std::vector<double> dtau_du);

/// Boost.Math pchip / makima on each coordinate over the chord-length parameter (open curves).
Interpolant boost_pchip_interpolant(const PointList& p);
/// Boost.Math makima on each coordinate over the chord-length parameter (open curves).
Interpolant boost_makima_interpolant(const PointList& p);
/// Boost.Math's centripetal Catmull–Rom (α = 1/2), 2-D or 3-D.
Interpolant boost_catmull_rom_interpolant(const PointList& p, bool closed);

namespace detail {
/// Whether the O(n) slope rules of boost_pchip_interpolant and boost_makima_interpolant give
/// Boost's slopes bit for bit at every node of p, each coordinate over chord length (so that no
/// construction falls back to reading them from Boost). For the tests.
bool boost_rules_match_everywhere(const PointList& p);
/// boost_pchip_interpolant with its O(n) slope rule spoilt (every span's start derivative one ulp
/// up): its check against Boost must notice and read every slope from Boost. For the tests.
Interpolant boost_pchip_interpolant_with_a_spoilt_rule(const PointList& p);
/// Whether boost_catmull_rom_interpolant's O(n) rule gives the slopes of Boost's prime bit for bit
/// at every node after the first (the first is always Boost's). For the tests.
bool boost_catmull_rom_rule_matches_everywhere(const PointList& p, bool closed);
/// boost_catmull_rom_interpolant with its rule spoilt (every x-slope one ulp up): its check against
/// Boost must notice and read every slope from Boost. For the tests.
Interpolant boost_catmull_rom_interpolant_with_a_spoilt_rule(const PointList& p, bool closed);
}  // namespace detail

}  // namespace cagd::methods
