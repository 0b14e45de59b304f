#pragma once
/// @file
/// A curve as a DXF drawing (ASCII, AutoCAD 2000 = AC1015, the first version with SPLINE's current
/// form): one SPLINE entity on layer CURVE holding the B-spline of bspline_form.hpp, exact for
/// polynomial curves (degree, knots, control points, no weights), and optionally the data points
/// as POINT entities on layer POINTS. A planar curve has the planar flag and the normal (0, 0, 1),
/// z = 0; a space curve neither.
/// A closed curve is written periodic (flags closed | periodic) when it has a periodic form
/// (periodic_bspline): its n distinct control points followed by the first p again, and the
/// unclamped knots, so that, as DXF requires, knots = control points + degree + 1. This is the
/// layout of ezdxf's own closed splines (Spline.set_closed). The knots are shifted to start at 0:
/// the file's parameter is u = t − t_0 (t_0 < t_min, the first knot of the periodic form), since
/// readers do not all evaluate negative knots (ezdxf 0.18 does not). Otherwise, a closed curve is
/// the clamped B-spline with the closed flag (its ends coincide).
/// The file has the header, tables (VPORT, LTYPE, LAYER, STYLE, VIEW, UCS, APPID, DIMSTYLE,
/// BLOCK_RECORD), blocks, entities and objects sections that AutoCAD 2000 and later expect, with
/// unique handles. Numbers have 17 significant digits (they read back to the same doubles).
#include <ostream>

#include "cagd/core/points.hpp"
#include "cagd/export/bspline_form.hpp"

namespace cagd::exports {

/// How the SPLINE entity is flagged.
enum class DxfSpline {
    open,     ///< no flag
    closed,   ///< closed: a clamped B-spline whose ends coincide
    periodic  ///< closed | periodic: an unclamped B-spline with its first p control points repeated
};

/// Writes the DXF drawing of `curve` to `out` (its knots and control points as they are, flagged as
/// `kind` says), with `points` (any number of rows, the curve's dimension) as POINT entities.
void write_dxf(std::ostream& out, const BSplineCurve& curve, DxfSpline kind, const PointList& points);
/// Writes a closed curve's periodic form (see above).
void write_dxf(std::ostream& out, const PeriodicBSpline& periodic, const PointList& points);

}  // namespace cagd::exports
