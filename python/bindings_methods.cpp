// methods/: the registry (cagd.methods) and interpolation by name (cagd.interpolate).
#include "bindings.hpp"
#include "cagd/methods/curve_provenance.hpp"

namespace cagd_python {

namespace {

// Registry parameters arrive as Python values; the registry parses their text, so a value is
// checked and reported exactly as on the command line. A value of the wrong Python type is a
// TypeError naming the parameter: a str for a number, a number for a choice or a text, a sequence
// holding anything but real numbers. Sequences (a vector parameter) become comma-separated numbers;
// a vector may also be given as its text ("2,3").
[[noreturn]] void wrong_type(const std::string& name, const char* expected, const py::handle& v) {
    throw py::type_error(name + ": expected " + expected + ", got " +
                         std::string(py::str(py::type::of(v).attr("__name__"))) + " " + std::string(py::repr(v)));
}

bool real_number(const py::handle& v) {
    return py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v) ||
           py::isinstance(v, py::module_::import("numbers").attr("Real"));
}

std::string parameter_text(const std::string& name, const cagd::methods::Parameter* declared, const py::handle& v) {
    using cagd::methods::ParameterType;
    const ParameterType type = declared ? declared->type : ParameterType::text;
    const bool numeric = declared && (type == ParameterType::integer || type == ParameterType::real);
    if (py::isinstance<py::str>(v)) {
        if (numeric) wrong_type(name, type == ParameterType::integer ? "an integer" : "a real number", v);
        return py::str(v);
    }
    if (declared && (type == ParameterType::choice || type == ParameterType::text)) wrong_type(name, "a str", v);
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "1" : "0";
    if (py::isinstance<py::int_>(v)) return py::str(v);
    if (real_number(v)) return cagd::full_precision(v.cast<double>());
    if (py::isinstance<py::sequence>(v) || py::isinstance<py::array>(v)) {
        if (numeric) wrong_type(name, type == ParameterType::integer ? "an integer" : "a real number", v);
        std::string s;
        for (const py::handle& x : py::iter(v)) {
            if (py::isinstance<py::str>(x) || py::isinstance<py::bool_>(x) || !real_number(x))
                wrong_type(name, "real numbers in the sequence", x);
            if (!s.empty()) s += ",";
            s += cagd::full_precision(x.cast<double>());
        }
        return s;
    }
    wrong_type(name, declared ? cagd::methods::to_string(type) : "a number, a str or a sequence of numbers", v);
}

cagd::methods::ParameterText parameter_texts(const std::string& method, const py::kwargs& params) {
    // The declared parameters of the method (or of a configuration's method); an unknown method is
    // left for the registry's own message.
    const cagd::methods::Method* m = nullptr;
    try {
        m = cagd::methods::find_configuration(method).method;
    } catch (const cagd::InvalidInput&) {}
    cagd::methods::ParameterText text;
    for (const auto& [k, v] : params) {
        std::string name = py::str(k);
        std::replace(name.begin(), name.end(), '_', '-');  // keyword arguments cannot hold '-'
        const cagd::methods::Parameter* declared = nullptr;
        if (m)
            for (const cagd::methods::Parameter& p : m->parameters)
                if (p.name == name) declared = &p;
        text[name] = parameter_text(std::string(py::str(k)), declared, v);
    }
    return text;
}

struct Interpolation {
    std::string status, message;
    std::optional<PyCurve> curve;
    std::vector<std::pair<std::string, std::string>> report;
    std::vector<std::pair<std::string, double>> quantities;
    std::vector<double> dtau_du;
};

Interpolation interpolate_result(const Array& points, const std::string& method, bool closed,
                                 const py::kwargs& params) {
    const Eigen::MatrixXd p = to_matrix(points, "interpolate: points");
    const cagd::methods::ParameterText text = parameter_texts(method, params);
    cagd::methods::InterpolationResult r;
    {
        py::gil_scoped_release release;
        r = cagd::methods::interpolate(method, p, closed, text);
    }
    Interpolation out;
    out.status = status_name(r.outcome.status);
    out.message = r.outcome.message;
    out.report = r.report;
    out.quantities = r.quantities;
    if (r.outcome.ok() && r.interpolant) {
        py::dict kwargs(params);
        kwargs["method"] = method;
        kwargs["closed"] = closed;
        // Evaluated in the method's own parameter (chord length, arc length, …: MethodClaims::parameter).
        auto in_tau = std::make_shared<const cagd::methods::MethodParameterCurve>(*r.interpolant);
        out.curve = with_recipe(wrap(in_tau, method, in_tau->node_parameters()), "interpolate",
                                py::make_tuple(from_matrix(p)), kwargs);
        out.curve->points = static_cast<int>(p.rows());
        out.curve->closed = closed;
        out.curve->in_tau = in_tau;
        // The method behind a preset name, with every parameter value (the preset's, the given, the defaults).
        const cagd::methods::Configuration conf = cagd::methods::find_configuration(method);
        cagd::methods::ParameterText all = conf.values.as_text();
        for (const auto& [name, value] : text) all[name] = value;
        const cagd::methods::ParameterValues values =
            cagd::methods::parse_parameter_values(conf.method->name, conf.method->parameters, all);
        out.curve->provenance = std::make_shared<const cagd::exports::CurveProvenance>(
            cagd::methods::method_provenance(*conf.method, values, p, closed));
        out.dtau_du = r.interpolant->dtau_du;
    }
    return out;
}

}  // namespace

void bind_methods(py::module_& m) {
    py::class_<Interpolation>(m, "Interpolation",
                              "The whole result of an interpolation: status, message, the curve when ok, and what the "
                              "method reported (interpolate_result).\n\n"
                              ">>> import numpy as np, cagd\n"
                              ">>> r = cagd.interpolate_result(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, "
                              "1.0]]), \"curvature-profile\")\n"
                              ">>> r.ok, r.status, r.dtau_du  # arc length is the curve's own parameter\n"
                              "(True, 'ok', array([1., 1., 1.]))\n")
        .def_readonly("status", &Interpolation::status,
                      "\"ok\", or the numerical outcome: \"no_solution\", \"no_convergence\"")
        .def_readonly("message", &Interpolation::message, "why there is no curve (empty when ok)")
        .def_readonly("curve", &Interpolation::curve, "the Curve when ok, else None")
        .def_property_readonly(
            "ok", [](const Interpolation& r) { return r.curve.has_value(); }, "whether there is a curve")
        .def_property_readonly(
            "report", [](const Interpolation& r) { return r.report; },
            "what the method reports, as (quantity, text) pairs (the Newton history)")
        .def_property_readonly(
            "quantities",
            [](const Interpolation& r) {
                py::dict d;
                for (const auto& [k, v] : r.quantities) d[py::str(k)] = v;
                return d;
            },
            "quantities the method computes along the way, by name (the pseudo-spline's table length and area)")
        .def_property_readonly(
            "dtau_du", [](const Interpolation& r) { return from_vector(r.dtau_du); },
            "per span, dτ/du: the method's parameter τ against the span index u");

    m.def("_interpolate_result", &interpolate_result, py::arg("points"), py::arg("method"), py::arg("closed") = false);

    m.def("_methods", []() {
        py::list out;
        for (const cagd::methods::Method& method : cagd::methods::registry()) {
            py::dict d;
            d["name"] = method.name;
            d["aliases"] = method.aliases;
            d["paper"] = method.paper;
            d["source"] = method.source;
            d["summary"] = method.summary;
            py::list params;
            for (const cagd::methods::Parameter& p : method.parameters) {
                py::dict q;
                q["name"] = p.name;
                q["type"] = cagd::methods::to_string(p.type);
                q["default"] = p.default_text;
                q["domain"] = p.domain();
                q["help"] = p.help;
                params.append(q);
            }
            d["parameters"] = params;
            std::vector<std::string> presets;
            for (const auto& pr : method.presets) presets.push_back(pr.name);
            d["presets"] = presets;
            const cagd::methods::MethodClaims c =
                method.claims(cagd::methods::parse_parameter_values(method.name, method.parameters, {}));
            py::dict claims;
            claims["parametric_continuity"] = c.parametric_continuity;
            claims["geometric_continuity"] = c.geometric_continuity;
            claims["parameter"] = c.parameter;
            claims["invariance"] = cagd::methods::to_string(c.invariance);
            claims["supports_closed"] = c.supports_closed;
            claims["min_points"] = c.min_points;
            claims["min_points_closed"] = c.min_points_closed;
            claims["max_points"] = c.max_points;
            claims["max_dimension"] = c.max_dimension;
            claims["always_solves"] = c.always_solves;
            d["claims"] = claims;
            out.append(d);
        }
        return out;
    });
}

}  // namespace cagd_python
