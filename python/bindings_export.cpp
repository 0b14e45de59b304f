// export/: a curve's exact Bézier and B-spline forms and its files (Curve.to_bezier, to_bspline,
// write), through the library's one writer per format (export/curve_formats.hpp).
#include "bindings.hpp"

#include "cagd/export/bspline_form.hpp"
#include "cagd/export/curve_formats.hpp"
#include "cagd/export/surface_form.hpp"

namespace cagd_python {

namespace {

cagd::exports::ApproximationOptions approximation(double tolerance, int degree) {
    cagd::exports::ApproximationOptions o;
    o.relative_tolerance = tolerance;
    o.degree = degree;
    return o;
}

// K × (p + 1) × dim control points of the pieces.
py::array_t<double> piece_array(const cagd::exports::BezierPieces& b) {
    py::array_t<double> out(std::vector<py::ssize_t>{b.pieces(), b.degree + 1, b.dimension()});
    double* w = out.mutable_data();
    for (Eigen::Index r = 0; r < b.control.rows(); ++r)
        for (Eigen::Index k = 0; k < b.control.cols(); ++k) *w++ = b.control(r, k);
    return out;
}

cagd::exports::BezierForm bezier_form(const PyCurve& c, std::optional<int> degree, double tolerance, int approximation_degree) {
    cagd::exports::BezierForm f;
    {
        py::gil_scoped_release release;
        f = degree ? cagd::exports::to_bezier_of_degree(*c.curve, *degree, approximation(tolerance, approximation_degree))
                   : cagd::exports::to_bezier(*c.curve, approximation(tolerance, approximation_degree));
    }
    require_ok(f.outcome);
    return f;
}

// The patches as a dict: nets has shape (cells_u, cells_v, degree_u + 1, degree_v + 1, 3).
py::dict surface_dict(const cagd::exports::SurfaceForm& f) {
    const cagd::exports::BezierSurfacePieces& p = f.pieces;
    py::array_t<double> nets(std::vector<py::ssize_t>{p.cells_u(), p.cells_v(), p.degree_u + 1, p.degree_v + 1, 3});
    double* w = nets.mutable_data();
    for (int a = 0; a < p.cells_u(); ++a)
        for (int b = 0; b < p.cells_v(); ++b)
            for (int i = 0; i <= p.degree_u; ++i)
                for (int j = 0; j <= p.degree_v; ++j)
                    for (int c = 0; c < 3; ++c) *w++ = p.net(a, b)[static_cast<std::size_t>(c)](i, j);
    py::dict d;
    d["degree_u"] = p.degree_u;
    d["degree_v"] = p.degree_v;
    d["u_breaks"] = from_vector(p.u_breaks);
    d["v_breaks"] = from_vector(p.v_breaks);
    d["nets"] = nets;
    d["exact"] = f.exact;
    d["conversion_error"] = f.conversion_error;
    return d;
}

// to_bezier and write for one surface class (export/surface_form.hpp).
template <class Surface>
void bind_surface_export(py::module_& m, const char* name, const char* kind, const char* example) {
    auto cls = py::reinterpret_borrow<py::class_<Surface>>(m.attr(name));
    cls.def(
        "to_bezier",
        [](const Surface& s) {
            cagd::exports::SurfaceForm f;
            {
                py::gil_scoped_release release;
                f = cagd::exports::to_bezier(s);
            }
            return surface_dict(f);
        },
        (std::string("The surface's exact Bézier patches (export/surface_form.hpp): a dict of degree_u, degree_v, u_breaks, v_breaks (cell (a, b) on "
                     "[u_a, u_a+1] × [v_b, v_b+1]), nets (cells_u × cells_v × (degree_u + 1) × (degree_v + 1) × 3), exact and conversion_error (the largest "
                     "distance to the surface measured inside every cell).\n\n") +
         example)
            .c_str());
    cls.def(
        "write",
        [kind](const Surface& s, const std::string& path, std::optional<std::string> format) {
            const cagd::exports::CurveFormat f = format ? cagd::exports::curve_format_named(*format) : cagd::exports::curve_format_of_path(path);
            cagd::OutputFile out(path, "path");
            cagd::Outcome written;
            {
                py::gil_scoped_release release;
                const cagd::exports::SurfaceForm form = cagd::exports::to_bezier(s);
                if (!form.exact) written = {cagd::Status::not_representable, "the Bézier patches differ from the surface by " + std::to_string(form.conversion_error)};
                else written = cagd::exports::write_surface(out.stream(), f, form, {kind, {}});
            }
            require_ok(written);
            out.commit();
        },
        py::arg("path"), py::arg("format") = py::none(),
        "Writes the surface's exact patches to `path` in the format of `format` or of its extension: json (the Bézier patches) or step (one B-spline "
        "surface, where the library has OpenCASCADE). The file is replaced atomically, or left as it was when anything fails; another format is a ValueError.");
}

}  // namespace

void bind_export(py::module_& m) {
    bind_surface_export<cagd::surface::HosakaPatch>(m, "TensorPatch", "hosaka-tensor",
                                                    ">>> import numpy as np, cagd\n"
                                                    ">>> c = np.zeros((2, 2, 2, 2, 3))\n"
                                                    ">>> for k in (0, 1):\n"
                                                    "...     for l in (0, 1):\n"
                                                    "...         c[k, l, 0, 0] = [k, l, k * l]\n"
                                                    ">>> b = cagd.tensor_patch(c).to_bezier()\n"
                                                    ">>> b[\"degree_u\"], b[\"nets\"].shape, b[\"exact\"]\n"
                                                    "(3, (1, 1, 4, 4, 3), True)\n"
                                                    ">>> b[\"nets\"][0, 0, 3, 3]  # the corner (1, 1)\n"
                                                    "array([1., 1., 1.])\n");
    bind_surface_export<cagd::surface::EdgeFormPatch>(m, "EdgePatch", "hosaka-coons",
                                                      ">>> import numpy as np, cagd\n"
                                                      ">>> s = np.linspace(0, 1, 4)\n"
                                                      ">>> p = cagd.coons_patch(np.column_stack([s, 0 * s, 0 * s]), np.column_stack([0 * s, s, s * s]),\n"
                                                      "...                      np.column_stack([s, 1 + 0 * s, 1 + 0 * s]), np.column_stack([1 + 0 * s, s, s * s]))\n"
                                                      ">>> b = p.to_bezier()\n"
                                                      ">>> b[\"nets\"].shape[:2], b[\"exact\"]  # a cell per span of the edges\n"
                                                      "((3, 3), True)\n");
    bind_surface_export<cagd::surface::CartesianSurface>(m, "CartesianSurface", "hosaka-cartesian",
                                                         ">>> import numpy as np, cagd\n"
                                                         ">>> x = np.array([0.0, 1.0, 3.0]); y = np.array([0.0, 2.0])\n"
                                                         ">>> s = cagd.cartesian_surface(x, y, np.array([[0.0, 1.0], [1.0, 0.0], [2.0, 2.0]]))\n"
                                                         ">>> b = s.to_bezier()\n"
                                                         ">>> b[\"nets\"].shape, b[\"u_breaks\"].tolist(), b[\"exact\"]\n"
                                                         "((2, 1, 4, 4, 3), [0.0, 1.0, 3.0], True)\n");

    auto curve = py::reinterpret_borrow<py::class_<PyCurve>>(m.attr("Curve"));
    curve.def(
        "to_bezier",
        [](const PyCurve& c, std::optional<int> degree, double tolerance, int approximation_degree) {
            const cagd::exports::BezierForm f = bezier_form(c, degree, tolerance, approximation_degree);
            py::dict d;
            d["degree"] = f.pieces.degree;
            d["breaks"] = from_vector(f.pieces.breaks);
            d["control"] = piece_array(f.pieces);
            d["exact"] = f.exact;
            d["max_distance"] = f.max_distance;
            d["tolerance"] = f.tolerance;
            return d;
        },
        py::arg("degree") = py::none(), py::arg("tolerance") = 1e-6, py::arg("approximation_degree") = 3,
        "The curve as Bézier pieces: a dict of degree, breaks (piece i on [breaks[i], breaks[i+1]] in the curve's parameter), control (pieces × (degree + 1) × "
        "dimension), exact, max_distance and tolerance. A polynomial curve gives its own pieces exactly (degree None) or raised to `degree`; a curve that is "
        "not polynomial, or of higher degree than `degree`, is approximated by Hermite pieces (degree 3, or approximation_degree 5 when degree is None) within "
        "tolerance × its bounding-box diagonal (max_distance is the bound reached).\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> c = cagd.interpolate(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]), \"cubic-b\")\n"
        ">>> b = c.to_bezier()\n"
        ">>> b[\"degree\"], b[\"control\"].shape, b[\"exact\"]\n"
        "(3, (3, 4, 2), True)\n"
        ">>> b[\"control\"][1, 0], b[\"control\"][1, 3]  # the second piece runs from point 1 to point 2\n"
        "(array([1., 1.]), array([2., 0.]))\n");
    curve.def(
        "to_bspline",
        [](const PyCurve& c, double tolerance, int approximation_degree) {
            const cagd::exports::BezierForm f = bezier_form(c, std::nullopt, tolerance, approximation_degree);
            const cagd::exports::BSplineForm b = cagd::exports::to_bspline(f.pieces);
            py::dict d;
            d["degree"] = b.curve.degree();
            d["knots"] = from_vector(b.curve.knots());
            d["control"] = from_matrix(b.curve.control_points());
            d["exact"] = f.exact;
            d["max_distance"] = f.max_distance;
            d["conversion_error"] = b.conversion_error;
            return d;
        },
        py::arg("tolerance") = 1e-6, py::arg("approximation_degree") = 3,
        "The curve as one clamped B-spline with the fewest knots that keep it exact (a knot of multiplicity degree − c where the pieces join C^c): a dict of "
        "degree, knots, control (n × dimension), exact, max_distance (of an approximation, as to_bezier) and conversion_error (the measured spread of the "
        "control points' blossoms). scipy.interpolate.BSpline(knots, control, degree) is the same curve.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> c = cagd.interpolate(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]), \"cubic-a\")\n"
        ">>> b = c.to_bspline()\n"
        ">>> b[\"degree\"], b[\"knots\"].tolist()  # a C2 cubic: simple interior knots\n"
        "(3, [0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0, 3.0])\n");
    curve.def(
        "write",
        [](const PyCurve& c, const std::string& path, std::optional<std::string> format, double tolerance, int approximation_degree, bool points, bool comb,
           int samples, int arc_length_samples) {
            const cagd::exports::CurveFormat f = format ? cagd::exports::curve_format_named(*format) : cagd::exports::curve_format_of_path(path);
            cagd::exports::ExportOptions o;
            o.approximation = approximation(tolerance, approximation_degree);
            o.samples.per_piece = samples;
            o.samples.arc_length_samples = arc_length_samples;
            o.points = points;
            o.comb = comb;
            cagd::exports::CurveProvenance provenance;
            if (c.provenance) provenance = *c.provenance;
            else provenance.method = c.method;
            cagd::OutputFile out(path, "path");  // the one atomic, checked writer
            cagd::Outcome written;
            {
                py::gil_scoped_release release;
                written = cagd::exports::write_curve(out.stream(), f, *c.curve, provenance, o);
            }
            require_ok(written);
            out.commit();
        },
        py::arg("path"), py::arg("format") = py::none(), py::arg("tolerance") = 1e-6, py::arg("approximation_degree") = 3, py::arg("points") = false,
        py::arg("comb") = false, py::arg("samples") = 16, py::arg("arc_length_samples") = 0,
        "Writes the curve to `path` in the format of `format` or of its extension: csv (samples), json (exact pieces, method, parameters, points), svg (cubic "
        "path; points and comb optional), dxf (one SPLINE entity), step (B-spline, where the library has OpenCASCADE). The file is replaced atomically, or "
        "left as it was when anything fails; an unknown extension is a ValueError.\n\n"
        ">>> import numpy as np, cagd, os, tempfile\n"
        ">>> c = cagd.interpolate(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]), \"cubic-b\")\n"
        ">>> folder = tempfile.TemporaryDirectory()\n"
        ">>> path = os.path.join(folder.name, \"curve.svg\")\n"
        ">>> c.write(path, comb=True)\n"
        ">>> open(path).read().count(\"\\nC\")  # one cubic segment per span\n"
        "3\n"
        ">>> folder.cleanup()\n");
}

}  // namespace cagd_python
