#pragma once
/// @file
/// A curve as a DXF drawing (ASCII, AutoCAD 2000 = AC1015, the first version with SPLINE's current
/// form): one SPLINE entity on layer CURVE holding the B-spline of bspline_form.hpp, exact for
/// polynomial curves (degree, knots, control points, no weights), and optionally the data points
/// as POINT entities on layer POINTS. A planar curve has the planar flag and the normal (0, 0, 1),
/// z = 0; a space curve neither.
/// A closed curve is the clamped B-spline with the closed flag (its ends coincide; the periodic form
/// is not written yet: docs/export.md). As DXF requires, knots = control points + degree + 1.
/// The file has the header, tables (VPORT, LTYPE, LAYER, STYLE, VIEW, UCS, APPID, DIMSTYLE,
/// BLOCK_RECORD), blocks, entities and objects sections that AutoCAD 2000 and later expect, with
/// unique handles. Numbers have 17 significant digits (they read back to the same doubles).
#include <ostream>

#include "cagd/core/points.hpp"
#include "cagd/export/bspline_form.hpp"

namespace cagd::exports {

/// Writes the DXF drawing of `curve` to `out`, flagged closed when `closed`, with `points` (any
/// number of rows, the curve's dimension) as POINT entities.
void write_dxf(std::ostream& out, const BSplineCurve& curve, bool closed, const PointList& points);

}  // namespace cagd::exports
