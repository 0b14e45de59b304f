#pragma once
/// @file
/// THE list of the formats a curve leaves in, and the one writer that serves the command, Python
/// and the comparison (a writer of each format exists once, in this folder):
///
///   csv   samples of position and derivatives (curve_samples.hpp)          2-D, 3-D
///   json  the exact pieces with method, parameters and points (curve_json.hpp)  2-D, 3-D
///   svg   a path of cubic Béziers, optional points and comb (svg_writer.hpp)    2-D
///   dxf   one SPLINE entity, the exact B-spline (dxf_writer.hpp)                  2-D, 3-D
///   step  a B_SPLINE_CURVE_WITH_KNOTS through OpenCASCADE (step_writer.hpp)     2-D, 3-D;
///         only in a library built with OpenCASCADE (step_available())
///
/// Surfaces (surface_form.hpp) leave in json (their Bézier patches) and step (one B-spline surface,
/// a B_SPLINE_SURFACE_WITH_KNOTS); the commands also write csv grids of samples. svg and dxf take
/// no surfaces (a DXF surface is an ACIS solid-modeller body, not a B-spline entity).
///
/// Exact or not: polynomial curves leave exactly in json, dxf and step (their own pieces, joined
/// with the fewest knots) and in svg when of degree ≤ 3; everything else is approximated within the
/// stated distance (bezier_form.hpp), and the file says so.
/// A format is chosen by name (--format) or by the output path's extension, case-insensitive
/// (.csv, .json, .svg, .dxf, .step/.stp); a path without an extension ("-", /dev/stdout) is csv;
/// any other extension is bad input (InvalidInput naming it and the known ones).
#include <ostream>
#include <string>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/export/bezier_form.hpp"
#include "cagd/export/curve_json.hpp"
#include "cagd/export/curve_samples.hpp"

namespace cagd::exports {

/// A curve's file format (see above).
enum class CurveFormat {
    csv,   ///< samples
    json,  ///< the curve document
    svg,   ///< cubic path
    dxf,   ///< SPLINE entity
    step   ///< B-spline through OpenCASCADE
};

/// One format's name, extensions and reach.
struct CurveFormatInfo {
    CurveFormat format;                   ///< the format
    const char* name;                     ///< as --format takes it
    std::vector<std::string> extensions;  ///< with the dot, lower case
    const char* summary;                  ///< one line for help texts
    bool space_curves;                    ///< takes 3-D curves
    bool surfaces;                        ///< takes surfaces (csv: the command's grids)
};
/// Every format, in the order above.
const std::vector<CurveFormatInfo>& curve_formats();
/// The format of `name`; InvalidInput listing the names.
CurveFormat curve_format_named(const std::string& name);
/// The format of an output path (see above).
CurveFormat curve_format_of_path(const std::string& path);
/// The format's entry.
const CurveFormatInfo& curve_format_info(CurveFormat format);
/// Whether this library writes STEP (it was built with OpenCASCADE).
bool step_available();
/// The largest surface degree (in u and in v) `format` takes: json 1000 (its reader's limit), step
/// OpenCASCADE's 25; InvalidInput for a format without surfaces, or step without OpenCASCADE.
int max_surface_degree(CurveFormat format);

/// What a written curve carries besides its shape.
struct ExportOptions {
    ApproximationOptions approximation{};  ///< for curves that are not exact in the format
    SampleOptions samples{};               ///< csv
    bool points = false;                   ///< svg, dxf: draw the provenance's points
    bool comb = false;                     ///< svg: the curvature comb
    /// The curve is itself an approximation, within this distance, of the curve it stands for (a
    /// peer's pieces where the peer gives samples only, docs/peers.md): json says exact false and
    /// adds it to max_distance. 0: the curve is what it stands for.
    double stands_within = 0.0;
};

/// Writes `curve` in `format` to `out`. Outcome not ok (nothing useful written: the caller does
/// not publish) when an approximation does not reach its tolerance or a value is not finite;
/// InvalidInput for a format that does not take the curve (svg of a 3-D curve, step without
/// OpenCASCADE) or invalid options.
Outcome write_curve(std::ostream& out, CurveFormat format, const Curve& curve, const CurveProvenance& provenance,
                    const ExportOptions& options);

/// Writes the patches of a surface in json or step. InvalidInput for another format, or step
/// without OpenCASCADE or above its degree limit; Outcome not_representable (nothing written) for a
/// form that is not exact (SurfaceForm::exact false) or a control point that is not finite, not ok
/// for a surface OpenCASCADE rejects.
Outcome write_surface(std::ostream& out, CurveFormat format, const SurfaceForm& form,
                      const SurfaceProvenance& provenance);

}  // namespace cagd::exports
