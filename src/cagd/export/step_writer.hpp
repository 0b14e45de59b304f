#pragma once
/// @file
/// A curve or a surface as STEP (ISO 10303-21, application protocol AP214), written by OpenCASCADE's
/// STEPControl_Writer: one edge on a Geom_BSplineCurve, which the translator writes as a
/// B_SPLINE_CURVE_WITH_KNOTS (degree, control points, distinct knots with multiplicities, no
/// weights), in millimetres. Planar curves get z = 0. A closed curve is clamped at its first point
/// with closed_curve true: OpenCASCADE's translator writes a periodic curve as its non-periodic
/// form anyway. Reals carry OpenCASCADE's 13 significant digits.
/// Available only in a library built with OpenCASCADE (CMake found it; step_available());
/// otherwise write_step throws InvalidInput saying so. OpenCASCADE's own messages are silenced so
/// that nothing but the file reaches the output.
#include <ostream>

#include "cagd/core/errors.hpp"
#include "cagd/export/bspline_form.hpp"
#include "cagd/export/surface_form.hpp"

namespace cagd::exports {

/// The most control points a curve's STEP file takes. STEPControl_Writer builds OpenCASCADE's whole
/// model of the curve before it writes, several times the curve's own size, so the limit keeps a
/// run at it within 3 GB of address space and a minute on 2 cores; JSON, SVG and DXF, which stream,
/// take any curve.
inline constexpr long kMaxStepControlPoints = 2'500'000;

/// Writes the STEP file of `curve`. InvalidInput for more than kMaxStepControlPoints control points
/// (before OpenCASCADE sees it); Outcome not ok when OpenCASCADE rejects the curve or fails to write.
Outcome write_step(std::ostream& out, const BSplineCurve& curve);
/// Writes the STEP file of `surface`: one face on a Geom_BSplineSurface, which the translator
/// writes as a B_SPLINE_SURFACE_WITH_KNOTS bounded by its parameter rectangle. InvalidInput for a
/// degree above OpenCASCADE's limit (25; the typical surface of n > 26 control points per
/// direction leaves in JSON only); Outcome not ok when OpenCASCADE rejects the surface.
Outcome write_step(std::ostream& out, const BSplineSurface& surface);
/// OpenCASCADE's largest B-spline surface degree (Geom_BSplineSurface::MaxDegree(), 25); InvalidInput
/// in a library built without OpenCASCADE.
int step_max_surface_degree();

}  // namespace cagd::exports
