#pragma once
/// @file
/// A planar curve as SVG: one path of cubic Bézier segments (`M x0 y0 C x1 y1 x2 y2 x3 y3 …`), the
/// pieces of to_bezier_of_degree(curve, 3): exact for curves of degree ≤ 3 (raised exactly where
/// lower), and for the others (the quartic S-spline, Hosaka's curves of degree 2m + 1, the
/// transcendental curves) an approximation whose distance bound is written in the file's `desc`
/// (bezier_form.hpp). Coordinates are the curve's own, to 17 significant digits (they read back to
/// the same doubles), inside a group that flips y (SVG's y axis points down), so a reader's path
/// geometry (getPointAtLength) is in the curve's coordinates.
/// Optional groups: id="points" (the data points as circles) and id="comb" (the curvature comb of
/// analysis/curvature_comb.hpp on the exact curve, its length factor c in the group's
/// data-comb-scale attribute and in `desc`). The drawing is 800 px wide, its viewBox the control
/// points' bounding box (and the comb) with a 5 % margin.
/// Preconditions (InvalidInput): a planar curve; a cubic form; comb_teeth ≥ 2.
#include <ostream>
#include <string>

#include "cagd/core/curve.hpp"
#include "cagd/core/points.hpp"
#include "cagd/export/bezier_form.hpp"

namespace cagd::exports {

/// What the SVG shows besides the curve.
struct SvgOptions {
    PointList points{};     ///< drawn as circles in group "points" when it has rows
    bool comb = false;      ///< the curvature comb in group "comb"
    int comb_teeth = 1000;  ///< the most teeth of the comb
    std::string title{};    ///< the `title` (e.g. the method)
};

/// Writes `cubic` (the curve's cubic pieces, from to_bezier_of_degree(curve, 3)) as SVG to `out`.
void write_svg(std::ostream& out, const Curve& curve, const BezierForm& cubic, const SvgOptions& options);

}  // namespace cagd::exports
