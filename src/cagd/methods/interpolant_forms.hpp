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

/// Chord lengths |P_{k+1} − P_k| of the spans (closed: the closing span last).
std::vector<double> chord_lengths(const PointList& p, bool closed);

/// A curve whose data points sit at u = 0, 1, …, nodes − 1, with dτ/du per span.
Interpolant unit_span_interpolant(std::shared_ptr<const Curve> curve, Eigen::Index nodes, std::vector<double> dtau_du);

/// A piecewise cubic through the points with τ-derivatives `slopes` at the nodes (rows as the
/// points; closed: the closing node's slope is row 0) and τ-lengths h per span, in unit-span
/// Hermite form.
Interpolant hermite_from_slopes(const PointList& p, const Eigen::MatrixXd& slopes, const std::vector<double>& h, bool closed);

/// Boost.Math pchip / makima on each coordinate over the chord-length parameter (open curves).
Interpolant boost_pchip_interpolant(const PointList& p);
/// Boost.Math makima on each coordinate over the chord-length parameter (open curves).
Interpolant boost_makima_interpolant(const PointList& p);
/// Boost.Math's centripetal Catmull–Rom (α = 1/2), 2-D or 3-D.
Interpolant boost_catmull_rom_interpolant(const PointList& p, bool closed);

}  // namespace cagd::methods
