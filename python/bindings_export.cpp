// export/: a curve's exact Bézier and B-spline forms and its files (Curve.to_bezier, to_bspline,
// write), through the library's one writer per format (export/curve_formats.hpp).
#include "bindings.hpp"

#include "cagd/export/bspline_form.hpp"
#include "cagd/export/curve_formats.hpp"
#include "cagd/export/curve_json.hpp"
#include "cagd/export/surface_form.hpp"
#include "cagd/methods/curve_provenance.hpp"

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

cagd::exports::BezierForm bezier_form(const PyCurve& c, std::optional<int> degree, double tolerance,
                                      int approximation_degree) {
    cagd::exports::BezierForm f;
    {
        py::gil_scoped_release release;
        f = degree
                ? cagd::exports::to_bezier_of_degree(*c.curve, *degree, approximation(tolerance, approximation_degree))
                : cagd::exports::to_bezier(*c.curve, approximation(tolerance, approximation_degree));
    }
    require_ok(f.outcome);
    return f;
}

// scipy's PPoly coefficients c (p + 1, K, dim), highest power first, and breaks x (K + 1) → a curve.
// The degrees a curve leaves Python with: the curve document's (export/curve_json.hpp), at which
// from_bspline and from_ppoly are tested to 1e-10 of the control points (tests/test_cagd.py); the
// Taylor and power-basis forms behind them lose accuracy beyond it (1.4 at degree 60).
constexpr int kMaxBridgeDegree = cagd::exports::kMaxDocumentDegree;

PyCurve curve_from_ppoly(const py::object& c_in, const py::object& x_in) {
    const Array c = real_array(c_in, "c");
    if (c.ndim() != 3 || c.shape(2) < 2 || c.shape(2) > 3 || c.shape(0) < 1 || c.shape(1) < 1)
        throw cagd::InvalidInput("c: expected PPoly coefficients of shape (degree + 1, pieces, 2 or 3), got " +
                                 std::to_string(c.ndim()) + " dimension(s)");
    if (c.shape(0) - 1 > kMaxBridgeDegree)
        throw py::value_error("c: PPoly coefficients of degree " + std::to_string(c.shape(0) - 1) + "; degrees up to " +
                              std::to_string(kMaxBridgeDegree) + " are taken");
    cagd::exports::PowerPieces w;
    w.degree = static_cast<int>(c.shape(0)) - 1;
    w.breaks = to_vector(real_array(x_in, "x"), "x");
    auto r = c.unchecked<3>();
    for (py::ssize_t i = 0; i < c.shape(1); ++i) {
        Eigen::MatrixXd piece(c.shape(0), c.shape(2));
        for (py::ssize_t k = 0; k < c.shape(0); ++k)
            for (py::ssize_t d = 0; d < c.shape(2); ++d) piece(k, d) = r(k, i, d);
        w.coefficients.push_back(std::move(piece));
    }
    const cagd::exports::BezierPieces b = cagd::exports::bezier_pieces_from_power(w);
    if (!b.control.allFinite())
        throw py::value_error(
            "x, c: the pieces' Bézier control points overflow (coefficient × width^power beyond "
            "double: a subnormal or tiny piece width)");
    return with_recipe(wrap(std::make_shared<cagd::BSplineCurve>(cagd::exports::bezier_pieces_curve(b)), "ppoly"),
                       "_curve_from_ppoly", py::make_tuple(c, from_vector(w.breaks)));
}

// scipy's B-spline (knots t, coefficients c (n, dim) or splprep's list of dim arrays, degree k) → a curve.
PyCurve curve_from_bspline(const py::object& t_in, const py::object& c_in, const py::object& k_in) {
    const int k = int_argument(k_in, "k", 0, kMaxBridgeDegree);
    Eigen::MatrixXd control;
    if (py::isinstance<py::list>(c_in) || py::isinstance<py::tuple>(c_in)) {  // splprep: [cx, cy(, cz)]
        const py::sequence seq = c_in.cast<py::sequence>();
        if (seq.size() < 2 || seq.size() > 3)
            throw cagd::InvalidInput("c: expected 2 or 3 coordinate arrays (splprep's tck), got " +
                                     std::to_string(seq.size()));
        for (std::size_t d = 0; d < seq.size(); ++d) {
            const std::vector<double> col = to_vector(real_array(seq[d], "c"), "c");
            if (d == 0) control.resize(static_cast<Eigen::Index>(col.size()), static_cast<Eigen::Index>(seq.size()));
            if (static_cast<Eigen::Index>(col.size()) != control.rows())
                throw cagd::InvalidInput("c: the coordinate arrays differ in length");
            control.col(static_cast<Eigen::Index>(d)) = Eigen::Map<const Eigen::VectorXd>(col.data(), control.rows());
        }
    } else {
        control = to_matrix(real_array(c_in, "c"), "c");
    }
    if (control.cols() < 2 || control.cols() > 3)
        throw cagd::InvalidInput("c: expected 2 or 3 coordinates per control point, got " +
                                 std::to_string(control.cols()));
    std::vector<double> knots = to_vector(real_array(t_in, "t"), "t");
    // splprep pads its coefficient arrays with k + 1 trailing zeros: n = len(t) − k − 1 are used.
    const Eigen::Index used = static_cast<Eigen::Index>(knots.size()) - k - 1;
    if (k < 0 || used < 1 || used > control.rows())
        throw cagd::InvalidInput("t, c, k: " + std::to_string(knots.size()) + " knots of degree " + std::to_string(k) +
                                 " need " + std::to_string(used) + " control points, got " +
                                 std::to_string(control.rows()));
    control.conservativeResize(used, Eigen::NoChange);
    py::array_t<double> c_out = from_matrix(control), t_out = from_vector(knots);
    return with_recipe(wrap(std::make_shared<cagd::BSplineCurve>(k, std::move(knots), std::move(control)), "bspline"),
                       "_curve_from_bspline", py::make_tuple(t_out, c_out, k));
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
        (std::string("The surface's exact Bézier patches (export/surface_form.hpp): a dict of degree_u, degree_v, "
                     "u_breaks, v_breaks (cell (a, b) on "
                     "[u_a, u_a+1] × [v_b, v_b+1]), nets (cells_u × cells_v × (degree_u + 1) × (degree_v + 1) × 3), "
                     "exact and conversion_error (the largest "
                     "distance to the surface measured inside every cell).\n\n") +
         example)
            .c_str());
    cls.def(
        "write",
        [kind](const Surface& s, const std::string& path, std::optional<std::string> format) {
            const cagd::exports::CurveFormat f =
                format ? cagd::exports::curve_format_named(*format) : cagd::exports::curve_format_of_path(path);
            cagd::OutputFile out(path, "path");
            cagd::Outcome written;
            {
                py::gil_scoped_release release;
                written = cagd::exports::write_surface(out.stream(), f, cagd::exports::to_bezier(s), {kind, {}});
            }
            require_ok(written);
            out.commit();
        },
        py::arg("path"), py::arg("format") = py::none(),
        "Writes the surface's exact patches to `path` in the format of `format` or of its extension: json (the Bézier "
        "patches) or step (one B-spline "
        "surface, where the library has OpenCASCADE). The file is replaced atomically, or left as it was when anything "
        "fails; another format is a ValueError.");
}

}  // namespace

void bind_export(py::module_& m) {
    m.def("_curve_from_ppoly", &curve_from_ppoly, py::arg("c"), py::arg("x"), "Curve.from_ppoly's builder (pickling).");
    m.def("_curve_from_bspline", &curve_from_bspline, py::arg("t"), py::arg("c"), py::arg("k"),
          "Curve.from_bspline's builder (pickling).");
    auto curve_class = py::reinterpret_borrow<py::class_<PyCurve>>(m.attr("Curve"));
    curve_class.def_static(
        "from_ppoly",
        [](const py::object& pp) {
            return py::hasattr(pp, "c") ? curve_from_ppoly(pp.attr("c"), pp.attr("x"))
                                        : curve_from_ppoly(pp[py::int_(0)], pp[py::int_(1)]);
        },
        py::arg("pp"),
        "A parametric piecewise polynomial of scipy's form as a cagd curve, exactly (each piece converted to its "
        "Bézier points): a "
        "scipy.interpolate.PPoly (CubicSpline included) whose values are points of 2 or 3 coordinates, or a tuple (c, "
        "x) of its coefficients "
        "(degree + 1, pieces, dim), highest power first, and breaks. Every measure of cagd then applies to it.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> from scipy.interpolate import CubicSpline\n"
        ">>> tau = np.array([0.0, 1.0, 2.5, 3.0]); p = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])\n"
        ">>> s = CubicSpline(tau, p, bc_type=\"natural\")\n"
        ">>> c = cagd.Curve.from_ppoly(s)\n"
        ">>> bool(np.allclose(c(1.7, 2), s(1.7, 2), rtol=0, atol=1e-12)), c.parameter_range\n"
        "(True, (0.0, 3.0))\n");
    curve_class.def_static(
        "from_bspline",
        [](const py::object& b) {
            return py::hasattr(b, "t") ? curve_from_bspline(b.attr("t"), b.attr("c"), b.attr("k"))
                                       : curve_from_bspline(b[py::int_(0)], b[py::int_(1)], b[py::int_(2)]);
        },
        py::arg("b"),
        "A B-spline curve of scipy's form as a cagd curve, knot for knot: a scipy.interpolate.BSpline "
        "(make_interp_spline) whose coefficients are "
        "points (n, 2 or 3), or a tuple (t, c, k) such as splprep's tck, c then a list of coordinate arrays (its "
        "trailing padding is dropped).\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> from scipy.interpolate import splprep\n"
        ">>> p = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0], [4.0, 0.5]])\n"
        ">>> tck, u = splprep(p.T, s=0)\n"
        ">>> c = cagd.Curve.from_bspline(tck)\n"
        ">>> float(np.max(np.abs(c(u) - p))) < 1e-12\n"
        "True\n");
    curve_class.def(
        "to_ppoly",
        [](const PyCurve& c, double tolerance, int approximation_degree) {
            const cagd::exports::BezierForm f = bezier_form(c, std::nullopt, tolerance, approximation_degree);
            const cagd::exports::PowerPieces w = cagd::exports::power_pieces(f.pieces);
            py::array_t<double> coefficients(std::vector<py::ssize_t>{
                w.degree + 1, static_cast<py::ssize_t>(w.coefficients.size()), f.pieces.dimension()});
            auto out = coefficients.mutable_unchecked<3>();
            for (std::size_t i = 0; i < w.coefficients.size(); ++i)
                for (int k = 0; k <= w.degree; ++k)
                    for (int d = 0; d < f.pieces.dimension(); ++d)
                        out(k, static_cast<py::ssize_t>(i), d) = w.coefficients[i](k, d);
            return py::make_tuple(coefficients, from_vector(w.breaks));
        },
        py::arg("tolerance") = 1e-6, py::arg("approximation_degree") = 3,
        "The curve as (c, x) for scipy.interpolate.PPoly(c, x): its own pieces when it is polynomial, else the Hermite "
        "approximation of to_bezier "
        "(within tolerance × its diagonal), in the local power basis, highest power first.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> from scipy.interpolate import PPoly\n"
        ">>> c = cagd.interpolate(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]), \"s-spline\")\n"
        ">>> pp = PPoly(*c.to_ppoly())\n"
        ">>> t = np.linspace(*c.parameter_range, 9)\n"
        ">>> float(np.max(np.abs(pp(t) - c(t)))) < 1e-12\n"
        "True\n");
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
    bind_surface_export<cagd::surface::EdgeFormPatch>(
        m, "EdgePatch", "hosaka-coons",
        ">>> import numpy as np, cagd\n"
        ">>> s = np.linspace(0, 1, 4)\n"
        ">>> p = cagd.coons_patch(np.column_stack([s, 0 * s, 0 * s]), np.column_stack([0 * s, s, s * s]),\n"
        "...                      np.column_stack([s, 1 + 0 * s, 1 + 0 * s]), np.column_stack([1 + 0 * s, s, s * s]))\n"
        ">>> b = p.to_bezier()\n"
        ">>> b[\"nets\"].shape[:2], b[\"exact\"]  # a cell per span of the edges\n"
        "((3, 3), True)\n");
    bind_surface_export<cagd::surface::CartesianSurface>(
        m, "CartesianSurface", "hosaka-cartesian",
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
        "The curve as Bézier pieces: a dict of degree, breaks (piece i on [breaks[i], breaks[i+1]] in the curve's "
        "parameter), control (pieces × (degree + 1) × "
        "dimension), exact, max_distance and tolerance. A polynomial curve gives its own pieces exactly (degree None) "
        "or raised to `degree`; a curve that is "
        "not polynomial, or of higher degree than `degree`, is approximated by Hermite pieces (degree 3, or "
        "approximation_degree 5 when degree is None) within "
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
        "The curve as one clamped B-spline with the fewest knots that keep it exact (a knot of multiplicity degree − c "
        "where the pieces join C^c): a dict of "
        "degree, knots, control (n × dimension), exact, max_distance (of an approximation, as to_bezier) and "
        "conversion_error (the measured spread of the "
        "control points' blossoms). scipy.interpolate.BSpline(knots, control, degree) is the same curve.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> c = cagd.interpolate(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]), \"cubic-a\")\n"
        ">>> b = c.to_bspline()\n"
        ">>> b[\"degree\"], b[\"knots\"].tolist()  # a C2 cubic: simple interior knots\n"
        "(3, [0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0, 3.0])\n");
    curve.def(
        "write",
        [](const PyCurve& c, const std::string& path, std::optional<std::string> format, double tolerance,
           int approximation_degree, bool points, bool comb, int samples, int arc_length_samples) {
            const cagd::exports::CurveFormat f =
                format ? cagd::exports::curve_format_named(*format) : cagd::exports::curve_format_of_path(path);
            cagd::exports::ExportOptions o;
            o.approximation = approximation(tolerance, approximation_degree);
            o.samples.per_piece = samples;
            o.samples.arc_length_samples = arc_length_samples;
            o.points = points;
            o.comb = comb;
            cagd::exports::CurveProvenance provenance;
            if (c.provenance)
                provenance = *c.provenance;
            else
                provenance = {.method = c.method, .registry = cagd::methods::registry_fingerprint()};
            cagd::OutputFile out(path, "path");  // the one atomic, checked writer
            cagd::Outcome written;
            {
                py::gil_scoped_release release;
                written = cagd::exports::write_curve(out.stream(), f, *c.curve, provenance, o);
            }
            require_ok(written);
            out.commit();
        },
        py::arg("path"), py::arg("format") = py::none(), py::arg("tolerance") = 1e-6,
        py::arg("approximation_degree") = 3, py::arg("points") = false, py::arg("comb") = false,
        py::arg("samples") = 16, py::arg("arc_length_samples") = 0,
        "Writes the curve to `path` in the format of `format` or of its extension: csv (samples), json (exact pieces, "
        "method, parameters, points), svg (cubic "
        "path; points and comb optional), dxf (one SPLINE entity), step (B-spline, where the library has OpenCASCADE). "
        "The file is replaced atomically, or "
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
