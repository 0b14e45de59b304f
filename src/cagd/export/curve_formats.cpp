#include "cagd/export/curve_formats.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/export/bspline_form.hpp"
#include "cagd/export/dxf_writer.hpp"
#include "cagd/export/step_writer.hpp"
#include "cagd/export/svg_writer.hpp"

namespace cagd::exports {

const std::vector<CurveFormatInfo>& curve_formats() {
    static const std::vector<CurveFormatInfo> formats{
        {CurveFormat::csv, "csv", {".csv"}, "samples: parameter, position, 1st and 2nd derivative", true, true},
        {CurveFormat::json,
         "json",
         {".json"},
         "the Bezier pieces with method, parameters and points (cagd analyze --in reads it)",
         true,
         true},
        {CurveFormat::svg,
         "svg",
         {".svg"},
         "a path of cubic Beziers (planar), optional points and curvature comb",
         false,
         false},
        {CurveFormat::dxf, "dxf", {".dxf"}, "one SPLINE entity (AutoCAD 2000 DXF), the exact B-spline", true, false},
        {CurveFormat::step,
         "step",
         {".step", ".stp"},
         "a B_SPLINE_CURVE_WITH_KNOTS (AP214, through OpenCASCADE)",
         true,
         true},
    };
    return formats;
}

const CurveFormatInfo& curve_format_info(CurveFormat f) {
    for (const CurveFormatInfo& i : curve_formats())
        if (i.format == f) return i;
    fail_input("cagd::exports::curve_format_info", "unknown format");
}

namespace {
std::string known_formats(bool extensions) {
    std::string s;
    for (const CurveFormatInfo& i : curve_formats())
        for (const std::string& e : extensions ? i.extensions : std::vector<std::string>{i.name})
            s += (s.empty() ? "" : ", ") + e;
    return s;
}
}  // namespace

CurveFormat curve_format_named(const std::string& name) {
    for (const CurveFormatInfo& i : curve_formats())
        if (name == i.name) return i.format;
    fail_input("cagd::exports::curve_format_named", "unknown format '" + name + "'; known: " + known_formats(false));
}

CurveFormat curve_format_of_path(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    if (ext.empty()) return CurveFormat::csv;
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    for (const CurveFormatInfo& i : curve_formats())
        if (std::find(i.extensions.begin(), i.extensions.end(), ext) != i.extensions.end()) return i.format;
    fail_input("cagd::exports::curve_format_of_path",
               path + ": unknown extension '" + ext + "'; known: " + known_formats(true) + " (or give --format)");
}

Outcome write_curve(std::ostream& out, CurveFormat format, const Curve& curve, const CurveProvenance& provenance,
                    const ExportOptions& o) {
    const CurveFormatInfo& info = curve_format_info(format);
    if (curve.dimension() == 3 && !info.space_curves)
        fail_input("cagd::exports::write_curve", std::string(info.name) + " is planar; the curve has 3 coordinates");
    const PointList no_points;
    switch (format) {
        case CurveFormat::csv: return write_curve_samples(out, curve, o.samples);
        case CurveFormat::svg: {
            const BezierForm cubic = to_bezier_of_degree(curve, 3, o.approximation);
            if (!cubic.outcome.ok()) return cubic.outcome;
            SvgOptions svg;
            if (o.points) svg.points = provenance.points;
            svg.comb = o.comb;
            svg.title = provenance.method.empty() ? "cagd curve" : "cagd " + provenance.method;
            write_svg(out, curve, cubic, svg);
            return {};
        }
        case CurveFormat::json:
        case CurveFormat::dxf:
        case CurveFormat::step: {
            if (format == CurveFormat::step && !step_available())
                fail_input("cagd::exports::write_curve",
                           "STEP needs a cagd library built with OpenCASCADE (Debian libocct-data-exchange-dev); this "
                           "one was built without it");
            if (!(o.stands_within >= 0.0) || !std::isfinite(o.stands_within))
                fail_input("cagd::exports::write_curve",
                           "stands_within must be finite and >= 0, got " + format_number(o.stands_within, 17));
            BezierForm form = to_bezier(curve, o.approximation);
            if (!form.outcome.ok()) return form.outcome;
            if (o.stands_within > 0.0) form.exact = false, form.max_distance += o.stands_within;
            if (!form.pieces.control.allFinite())
                return {Status::not_representable, "a control point of the curve is not finite"};
            if (format == CurveFormat::json) {
                write_curve_json(out, form, provenance);
                return {};
            }
            const PointList& points = o.points ? provenance.points : no_points;
            if (format == CurveFormat::dxf && provenance.closed) {
                if (const PeriodicBSpline periodic = periodic_bspline(form.pieces); !periodic.knots.empty()) {
                    write_dxf(out, periodic, points);
                    return {};
                }
            }
            const BSplineForm b = to_bspline(form.pieces);
            if (format == CurveFormat::dxf) {
                write_dxf(out, b.curve, provenance.closed ? DxfSpline::closed : DxfSpline::open, points);
                return {};
            }
            // STEP: clamped with closed_curve true; OpenCASCADE's translator writes every periodic
            // curve as its non-periodic form (docs/export.md).
            return write_step(out, b.curve);
        }
    }
    return {};
}

int max_surface_degree(CurveFormat format) {
    if (format == CurveFormat::json) return kMaxSurfaceDocumentDegree;
    if (format == CurveFormat::step) return step_max_surface_degree();
    fail_input("cagd::exports::max_surface_degree",
               std::string(curve_format_info(format).name) + " takes no surfaces as patches (json or step)");
}

Outcome write_surface(std::ostream& out, CurveFormat format, const SurfaceForm& form,
                      const SurfaceProvenance& provenance) {
    const char* who = "cagd::exports::write_surface";
    const CurveFormatInfo& info = curve_format_info(format);
    if (!info.surfaces || format == CurveFormat::csv)
        fail_input(who, std::string(info.name) +
                            " does not take surfaces; they leave in json or step (and as csv grids from the command)");
    // A conversion that is not exact to rounding is a numerical outcome, never written.
    if (!form.exact)
        return {Status::not_representable, "the Bézier patches differ from the surface by " +
                                               full_precision(form.conversion_error) + ": no exact form to write"};
    for (const surface::ControlNet& net : form.pieces.nets)
        for (const Eigen::MatrixXd& c : net)
            if (!c.allFinite()) return {Status::not_representable, "a control point of the surface is not finite"};
    if (format == CurveFormat::json) {
        write_surface_json(out, form, provenance);
        return {};
    }
    if (!step_available())
        fail_input(who,
                   "STEP needs a cagd library built with OpenCASCADE (Debian libocct-data-exchange-dev); this one was "
                   "built without it");
    return write_step(out, bspline_surface(form.pieces));
}

}  // namespace cagd::exports
