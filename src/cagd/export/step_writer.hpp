#pragma once
/// @file
/// A curve as STEP (ISO 10303-21, application protocol AP214), written by OpenCASCADE's
/// STEPControl_Writer: one edge on a Geom_BSplineCurve, which the translator writes as a
/// B_SPLINE_CURVE_WITH_KNOTS (degree, control points, distinct knots with multiplicities, no
/// weights), in millimetres. Planar curves get z = 0. A closed curve is clamped at its first point
/// (the periodic form is not written yet: docs/export.md).
/// Available only in a library built with OpenCASCADE (CMake found it; step_available());
/// otherwise write_step throws InvalidInput saying so. OpenCASCADE's own messages are silenced so
/// that nothing but the file reaches the output.
#include <ostream>

#include "cagd/core/errors.hpp"
#include "cagd/export/bspline_form.hpp"

namespace cagd::exports {

/// Writes the STEP file of `curve`. Outcome not ok when OpenCASCADE rejects the curve or fails to
/// write.
Outcome write_step(std::ostream& out, const BSplineCurve& curve);

}  // namespace cagd::exports
