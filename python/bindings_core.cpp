// core/: the Curve class (cagd::Curve): evaluation, curvature, torsion, measures.
#include "bindings.hpp"

#include "cagd/analysis/arc_length_parameter.hpp"

namespace cagd_python {

void bind_core(py::module_& m) {
    py::class_<PyCurve>(
        m, "Curve",
        "A curve of the library: position and derivatives at a parameter t in parameter_range. An interpolant runs in "
        "its method's own "
        "parameter (the registry's claims: chord length for cubic-b and hosaka, arc length for curvature-profile, "
        "uniform for cubic-a and the "
        "S-/B2-splines), and derivatives are with respect to it; node_parameters are its values at the data points.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> c = cagd.interpolate(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]), \"cubic-b\")\n"
        ">>> c.node_parameters.round(6)  # chord length: each chord is √2\n"
        "array([0.      , 1.414214, 2.828427, 4.242641])\n"
        ">>> c(np.sqrt(2))  # the second point\n"
        "array([1., 1.])\n"
        ">>> c(np.sqrt(2), 1).round(6), round(c.curvature(np.sqrt(2)), 6)\n"
        "(array([ 0.707107, -0.235702]), -3.41526)\n"
        ">>> round(c.arc_length(), 6), round(c.bending_energy(), 6)\n"
        "(4.423849, 8.398562)\n"
        ">>> c.span_parameter(np.sqrt(2)), round(c.method_parameter(1.5), 6)\n"
        "(1.0, 2.12132)\n")
        .def_property_readonly(
            "dimension", [](const PyCurve& c) { return c.curve->dimension(); }, "2 (planar) or 3 (space)")
        .def_property_readonly(
            "parameter_range", [](const PyCurve& c) { return py::make_tuple(c.curve->t_min(), c.curve->t_max()); },
            "(t_min, t_max): where the curve is defined")
        .def_property_readonly(
            "node_parameters", [](const PyCurve& c) { return from_vector(c.node_parameters); },
            "the parameter of each data point (interpolants; closed: n + 1 values)")
        .def_property_readonly(
            "method", [](const PyCurve& c) { return c.method; }, "the method or function that made the curve")
        .def(
            "breakpoints", [](const PyCurve& c) { return from_vector(c.curve->breakpoints()); },
            "parameters where the curve's pieces join")
        .def("evaluate", &PyCurve::evaluate, py::arg("t"), py::arg("derivatives") = 0,
             "Positions at t (shape t.shape + (dim,): (dim,) for a number), or with derivatives = k the jets r, r', …, "
             "r^(k) (shape t.shape + (k + 1, dim)), "
             "0 ≤ k ≤ 16. TypeError unless t holds real numbers; ValueError outside parameter_range.")
        .def(
            "curvature",
            [](const PyCurve& c, const py::object& t) {
                return c.map_parameters(t, [&](double u) {
                    return c.curve->dimension() == 2 ? cagd::analysis::signed_curvature(*c.curve, u)
                                                     : cagd::analysis::curvature(*c.curve, u);
                });
            },
            py::arg("t"),
            "Curvature at t (a float for a number, an array of t's shape otherwise): signed (counter-clockwise "
            "positive) for planar curves, its absolute value for space curves. "
            "ValueError where the speed vanishes.")
        .def(
            "torsion",
            [](const PyCurve& c, const py::object& t) {
                const double extent = cagd::analysis::curve_extent(*c.curve);
                return c.map_parameters(t, [&](double u) { return cagd::analysis::torsion(*c.curve, u, extent); });
            },
            py::arg("t"),
            "Torsion at t (space curves); NaN where the curve is straight, its curvature times the diagonal of its "
            "bounding box at most 1e-9 "
            "(the library's flatness policy): there the torsion is undefined.")
        .def(
            "arc_length",
            [](const PyCurve& c, bool with_error) -> py::object {
                cagd::analysis::ArcLength a;
                {
                    py::gil_scoped_release release;
                    a = cagd::analysis::accurate_arc_length(*c.curve);
                }
                if (with_error) return py::make_tuple(a.value, a.error_estimate);
                return py::float_(a.value);
            },
            py::arg("error_estimate") = false,
            "Arc length by adaptive Gauss–Kronrod to 1e-12 (as `cagd analyze --in`); with error_estimate=True the pair "
            "(length, estimate).")
        .def(
            "area", [](const PyCurve& c) { return cagd::analysis::area_closed_by_chord(*c.curve); },
            "Signed enclosed area (counter-clockwise positive; planar); an open curve is closed by the chord from its "
            "end to its start.")
        .def(
            "bending_energy", [](const PyCurve& c) { return cagd::analysis::bending_energy(*c.curve); },
            "∫ κ² ds (Gauss–Legendre per piece)")
        .def(
            "__call__",
            [](const PyCurve& c, const py::object& t, int nu) -> py::object {
                if (nu == 0) return c.evaluate(t, 0);
                const py::array jets = c.evaluate(t, nu);  // t.shape + (nu + 1, dim)
                return jets[py::make_tuple(py::ellipsis(), nu, py::slice(py::none(), py::none(), py::none()))];
            },
            py::arg("t"), py::arg("nu") = 0,
            "The nu-th derivative at t, as scipy's splines: shape t.shape + (dim,). c(t) is c.evaluate(t); c(t, 1) the "
            "first derivative.")
        .def_property_readonly(
            "closed", [](const PyCurve& c) { return c.closed; }, "whether the curve interpolates closed data")
        .def(
            "at_arc_length",
            [](const PyCurve& c, const py::object& s) {
                const cagd::analysis::ArcLengthParameter inverse(c.curve);
                return c.map_parameters(s, [&](double x) { return inverse.parameter_at(x); });
            },
            py::arg("s"),
            "The parameter t at arc length s from the start, 0 ≤ s ≤ arc_length() (a float for a number, an array of "
            "s's shape otherwise): "
            "Newton on the arc-length integral, to about 1e-12 of the length. c(c.at_arc_length(s)) samples the curve "
            "at equal arc length.\n\n"
            ">>> import numpy as np, cagd\n"
            ">>> c = cagd.interpolate(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]), \"cubic-b\")\n"
            ">>> s = c.arc_length()\n"
            ">>> c.at_arc_length(0.0), round(c.at_arc_length(s), 9) == round(c.parameter_range[1], 9)\n"
            "(0.0, True)\n"
            ">>> c(c.at_arc_length(np.linspace(0.0, s, 9))).shape  # 9 points at equal arc length\n"
            "(9, 2)\n")
        .def(
            "span_parameter",
            [](const PyCurve& c, const py::object& t) {
                if (!c.in_tau) throw cagd::InvalidInput("span_parameter: only an interpolant has a span parameter");
                return c.map_parameters(t, [&](double tau) { return c.in_tau->span_parameter(tau); });
            },
            py::arg("t"),
            "An interpolant's span parameter u at its parameter t: u runs from k to k + 1 between data points k and k "
            "+ 1 (the registry's curve; "
            "`cagd interpolate --parameter span`). t is piecewise affine in u.")
        .def(
            "method_parameter",
            [](const PyCurve& c, const py::object& u) {
                if (!c.in_tau) throw cagd::InvalidInput("method_parameter: only an interpolant has a span parameter");
                return c.map_parameters(u, [&](double x) { return c.in_tau->method_parameter(x); });
            },
            py::arg("u"), "The inverse of span_parameter: the parameter t at the span parameter u.")
        .def("__repr__",
             [](const PyCurve& c) {
                 std::ostringstream s;
                 s << "<cagd.Curve" << (c.method.empty() ? "" : " " + c.method);
                 if (c.points > 0) s << " through " << c.points << " points" << (c.closed ? ", closed" : ", open");
                 s << ", dim=" << c.curve->dimension() << ", t=[" << c.curve->t_min() << ", " << c.curve->t_max()
                   << "]>";
                 return s.str();
             })
        .def(py::pickle(
            [](const PyCurve& c) -> py::tuple {
                if (c.recipe.is_none())
                    throw py::type_error("this cagd.Curve cannot be pickled: it was not built by a function of cagd");
                return c.recipe;
            },
            [](const py::tuple& recipe) {
                // Built again by the same call: the state is the call, not the pieces. A state that is
                // not such a call, or a call that makes no Curve, is ValueError naming what it holds.
                const py::module_ cagd = py::module_::import("cagd");
                if (recipe.size() != 4 || !py::isinstance<py::str>(recipe[0]) || !py::hasattr(cagd, recipe[0]) ||
                    !py::isinstance<py::tuple>(recipe[1]) || !py::isinstance<py::dict>(recipe[2]))
                    throw py::value_error(
                        "state: not a cagd.Curve's pickle (a call of a cagd function, its arguments "
                        "and the key of the curve in its result)");
                const py::object made = cagd.attr(recipe[0])(*recipe[1], **recipe[2]);
                const py::object curve = recipe[3].is_none() ? made : made[recipe[3]];
                if (!py::isinstance<PyCurve>(curve))
                    throw py::value_error("state: cagd." + recipe[0].cast<std::string>() + " made a " +
                                          py::str(py::type::of(curve).attr("__name__")).cast<std::string>() +
                                          ", not a cagd.Curve");
                return curve.cast<PyCurve>();
            }));
}

}  // namespace cagd_python
