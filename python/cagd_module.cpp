// The compiled part of the Python module `cagd` (python/cagd/__init__.py documents the API).
// Only conversion lives here: NumPy arrays ↔ Eigen, parameters as the registry's text, the
// library's exceptions as Python's. Every computation is the C++ library's (the same functions as
// `cagd` and the experiments), so the module's values equal the library's bit for bit.
//
// Errors: cagd::InvalidInput → ValueError with the library's message; a numerical outcome (no
// solution, no convergence) → cagd.NoSolution (a RuntimeError) carrying the outcome's message.
// Vectorised evaluation releases the GIL and fills the result array in place.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cagd/aesthetic/log_aesthetic_curve.hpp"
#include "cagd/aesthetic/log_aesthetic_space_curve.hpp"
#include "cagd/aesthetic/space_typical_bezier.hpp"
#include "cagd/aesthetic/typical_bezier.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/curve.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"
#include "cagd/fairness/pseudo_energy_table.hpp"
#include "cagd/methods/method_registry.hpp"
#include "cagd/smoothing/elastic_line.hpp"
#include "cagd/smoothing/elastic_space_curve.hpp"
#include "cagd/spline/bezier.hpp"

namespace py = pybind11;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A numerical outcome for valid input, raised as cagd.NoSolution.
struct NoSolution : std::runtime_error {
    using std::runtime_error::runtime_error;
};

const char* status_name(cagd::Status s) {
    switch (s) {
        case cagd::Status::ok: return "ok";
        case cagd::Status::no_convergence: return "no_convergence";
        case cagd::Status::no_solution: return "no_solution";
        case cagd::Status::not_representable: return "not_representable";
    }
    return "unknown";
}

void require_ok(const cagd::Outcome& outcome) {
    if (!outcome.ok()) throw NoSolution(outcome.message);
}

// An (n, d) array of finite or non-finite doubles (the library checks the values) → n × d.
Eigen::MatrixXd to_matrix(const Array& a, const char* name) {
    if (a.ndim() != 2) throw cagd::InvalidInput(std::string(name) + ": expected a 2-D array (n, d), got " + std::to_string(a.ndim()) + " dimension(s)");
    Eigen::MatrixXd m(a.shape(0), a.shape(1));
    auto r = a.unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
        for (py::ssize_t j = 0; j < a.shape(1); ++j) m(i, j) = r(i, j);
    return m;
}

std::vector<double> to_vector(const Array& a, const char* name) {
    if (a.ndim() != 1) throw cagd::InvalidInput(std::string(name) + ": expected a 1-D array, got " + std::to_string(a.ndim()) + " dimension(s)");
    return std::vector<double>(a.data(), a.data() + a.shape(0));
}

py::array_t<double> from_matrix(const Eigen::MatrixXd& m) {
    py::array_t<double> out({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
    auto w = out.mutable_unchecked<2>();
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        for (Eigen::Index j = 0; j < m.cols(); ++j) w(i, j) = m(i, j);
    return out;
}

py::array_t<double> from_vector(const std::vector<double>& v) {
    py::array_t<double> out(static_cast<py::ssize_t>(v.size()));
    std::copy(v.begin(), v.end(), out.mutable_data());
    return out;
}

// A curve of the library with what its construction reported.
struct PyCurve {
    std::shared_ptr<const cagd::Curve> curve;
    std::vector<double> node_parameters;  // u of each data point (interpolants)
    std::string method;

    // Positions (derivatives = 0: shape (m, dim), or (dim,) for a scalar t) or jets (shape
    // (m, derivatives + 1, dim), or (derivatives + 1, dim)): rows are r, r', r'', … at each t.
    py::array evaluate(const py::object& t_in, int derivatives) const {
        if (derivatives < 0) throw cagd::InvalidInput("evaluate: derivatives = " + std::to_string(derivatives) + "; allowed 0 or more");
        const bool scalar = py::isinstance<py::float_>(t_in) || py::isinstance<py::int_>(t_in);
        const Array t = Array::ensure(t_in);
        if (!t) throw cagd::InvalidInput("evaluate: t must be a number or an array of numbers");
        if (t.ndim() > 1) throw cagd::InvalidInput("evaluate: t must be a number or a 1-D array");
        const py::ssize_t m = t.size(), rows = derivatives + 1, dim = curve->dimension();
        py::array_t<double> out(derivatives == 0 ? std::vector<py::ssize_t>{m, dim} : std::vector<py::ssize_t>{m, rows, dim});
        const double* ts = t.data();
        double* w = out.mutable_data();
        {
            py::gil_scoped_release release;
            if (rows <= cagd::kJetCapacity && dim <= 3) {
                cagd::JetMatrix jet;
                for (py::ssize_t k = 0; k < m; ++k) {
                    curve->jet_into(ts[k], derivatives, jet);
                    double* row = w + k * rows * dim;
                    for (py::ssize_t r = 0; r < rows; ++r)
                        for (py::ssize_t c = 0; c < dim; ++c) row[r * dim + c] = jet(r, c);
                }
            } else {
                for (py::ssize_t k = 0; k < m; ++k) {
                    const Eigen::MatrixXd jet = curve->jet(ts[k], derivatives);
                    double* row = w + k * rows * dim;
                    for (py::ssize_t r = 0; r < rows; ++r)
                        for (py::ssize_t c = 0; c < dim; ++c) row[r * dim + c] = jet(r, c);
                }
            }
        }
        if (scalar) return out[py::int_(0)];
        return out;
    }

    // A function of t, vectorised: a number for a number, an array for an array.
    template <class F>
    py::object map_parameters(const py::object& t_in, F f) const {
        const bool scalar = py::isinstance<py::float_>(t_in) || py::isinstance<py::int_>(t_in);
        const Array t = Array::ensure(t_in);
        if (!t || t.ndim() > 1) throw cagd::InvalidInput("t must be a number or a 1-D array of numbers");
        py::array_t<double> out(t.size());
        const double* ts = t.data();
        double* w = out.mutable_data();
        {
            py::gil_scoped_release release;
            for (py::ssize_t k = 0; k < t.size(); ++k) w[k] = f(ts[k]);
        }
        if (scalar) return py::float_(w[0]);
        return out;
    }
};

// λ: one number for every point, or one per point (the library checks the count and the values).
std::vector<double> lambda_values(const py::object& lambda, const char* name) {
    if (py::isinstance<py::float_>(lambda) || py::isinstance<py::int_>(lambda)) return {lambda.cast<double>()};
    const Array a = Array::ensure(lambda);
    if (!a) throw cagd::InvalidInput(std::string(name) + ": a number or a 1-D array of numbers");
    return to_vector(a, name);
}

PyCurve wrap(std::shared_ptr<const cagd::Curve> c, std::string method = {}, std::vector<double> nodes = {}) { return PyCurve{std::move(c), std::move(nodes), std::move(method)}; }

// Registry parameters arrive as Python values; the registry parses their text, so a value is
// checked and reported exactly as on the command line. Sequences become comma-separated numbers.
std::string parameter_text(const py::handle& v) {
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "1" : "0";
    if (py::isinstance<py::float_>(v)) return cagd::full_precision(v.cast<double>());
    if (py::isinstance<py::str>(v) || py::isinstance<py::int_>(v)) return py::str(v);
    if (py::isinstance<py::sequence>(v) || py::isinstance<py::array>(v)) {
        std::string s;
        for (const py::handle& x : py::iter(v)) {
            if (!s.empty()) s += ",";
            s += cagd::full_precision(x.cast<double>());
        }
        return s;
    }
    return py::str(v);
}

cagd::methods::ParameterText parameter_texts(const py::kwargs& params) {
    cagd::methods::ParameterText text;
    for (const auto& [k, v] : params) {
        std::string name = py::str(k);
        std::replace(name.begin(), name.end(), '_', '-');  // keyword arguments cannot hold '-'
        text[name] = parameter_text(v);
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

Interpolation interpolate_result(const Array& points, const std::string& method, bool closed, const py::kwargs& params) {
    const Eigen::MatrixXd p = to_matrix(points, "interpolate: points");
    const cagd::methods::ParameterText text = parameter_texts(params);
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
        out.curve = wrap(r.interpolant->curve, method, r.interpolant->node_parameters);
        out.dtau_du = r.interpolant->dtau_du;
    }
    return out;
}

// The quantities a table node and a table lookup share (pseudo_energy eq 8, 16–21).
py::dict segment_dict(double pseudo_energy, double r0, double r1, double length, double area, cagd::fairness::SegmentType type) {
    py::dict d;
    d["pseudo_energy"] = pseudo_energy;
    d["r0"] = r0;
    d["r1"] = r1;
    d["length"] = length;
    d["area"] = area;
    d["type"] = cagd::fairness::to_string(type);
    return d;
}

py::dict minimum_dict(const cagd::fairness::PseudoEnergyMinimum& m) {
    py::dict d = segment_dict(m.pseudo_energy, m.r0, m.r1, m.length, m.area, m.type);
    d["theta0"] = m.theta0;
    d["theta1"] = m.theta1;
    d["strain_energy"] = m.strain_energy;
    d["gradient_norm"] = m.gradient_norm;
    d["error_estimate"] = m.error_estimate;
    d["local_minima"] = m.local_minima;
    d["evaluations"] = m.evaluations;
    return d;
}

cagd::fairness::TableMethod table_method(const std::string& name) {
    if (name == "fast") return cagd::fairness::TableMethod::fast;
    if (name == "reference") return cagd::fairness::TableMethod::reference;
    if (name == "nlopt") return cagd::fairness::TableMethod::nlopt;
    throw cagd::InvalidInput("method = '" + name + "'; allowed fast | reference | nlopt");
}

py::dict comparison_dict(const std::vector<cagd::compare::MethodComparison>& rows, bool closed, int dimension) {
    const auto n = static_cast<py::ssize_t>(rows.size());
    std::vector<std::string> method, status, note;
    // Each measure with a validity mask (cagd.compare turns the pairs into masked arrays).
    const std::vector<std::string> names = {
        "length",    "area",  "pseudo_energy",      "bending_energy", "curvature_sign_changes", "max_abs_curvature", "max_abs_curvature_derivative",
        "overshoot", "spans", "locality_footprint", "seconds",        "max_abs_torsion"};
    std::vector<py::array_t<double>> values;
    std::vector<py::array_t<bool>> valid;
    for (std::size_t k = 0; k < names.size(); ++k) {
        values.emplace_back(n);
        valid.emplace_back(n);
    }
    for (py::ssize_t i = 0; i < n; ++i) {
        const auto& c = rows[static_cast<std::size_t>(i)];
        method.push_back(c.method);
        status.push_back(c.status);
        note.push_back(c.note);
        const bool built = c.interpolant.has_value();
        const bool measured = c.fairness.has_value();
        const std::optional<double> v[] = {
            built ? std::optional<double>(c.length) : std::nullopt,
            built && closed && dimension == 2 ? std::optional<double>(c.area) : std::nullopt,
            built ? std::optional<double>(c.pseudo_energy) : std::nullopt,
            measured ? std::optional<double>(c.fairness->bending_energy) : std::nullopt,
            measured && dimension == 2 ? std::optional<double>(c.fairness->curvature_sign_changes) : std::nullopt,
            measured ? std::optional<double>(c.fairness->max_abs_curvature) : std::nullopt,
            measured ? std::optional<double>(c.fairness->max_abs_curvature_derivative) : std::nullopt,
            measured ? std::optional<double>(c.fairness->overshoot) : std::nullopt,
            built ? std::optional<double>(c.spans) : std::nullopt,
            c.locality_footprint ? std::optional<double>(*c.locality_footprint) : std::nullopt,
            built ? std::optional<double>(c.seconds) : std::nullopt,
            measured && dimension == 3 ? std::optional<double>(c.fairness->max_abs_torsion) : std::nullopt,
        };
        for (std::size_t k = 0; k < names.size(); ++k) {
            values[k].mutable_data()[i] = v[k].value_or(0.0);
            valid[k].mutable_data()[i] = v[k].has_value();
        }
    }
    py::dict d;
    d["method"] = method;
    d["status"] = status;
    d["note"] = note;
    for (std::size_t k = 0; k < names.size(); ++k) d[py::str(names[k])] = py::make_tuple(values[k], valid[k]);
    return d;
}

py::dict typical_dict(const cagd::aesthetic::TypicalPolygon& p) {
    py::dict d;
    d["curve"] = wrap(std::make_shared<cagd::BezierCurve>(p.points), "typical");
    d["control_points"] = from_matrix(p.points);
    d["edge_lengths"] = from_vector(p.edge_lengths);
    d["rotations"] = from_vector(p.rotations);
    d["scales"] = from_vector(p.scales);
    return d;
}

cagd::aesthetic::FrenetComposition frenet_composition(const std::string& name) {
    if (name == "alexa") return cagd::aesthetic::FrenetComposition::alexa;
    if (name == "kappa_then_tau") return cagd::aesthetic::FrenetComposition::kappa_then_tau;
    if (name == "tau_then_kappa") return cagd::aesthetic::FrenetComposition::tau_then_kappa;
    throw cagd::InvalidInput("composition = '" + name + "'; allowed alexa | kappa_then_tau | tau_then_kappa");
}

}  // namespace

PYBIND11_MODULE(_cagd, m) {
    m.doc() = "cagd-repro: interpolating curves from five Japanese CAGD papers (compiled part; see cagd.__doc__)";
    static py::exception<NoSolution> no_solution(m, "NoSolution", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const cagd::InvalidInput& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const NoSolution& e) {
            no_solution(e.what());
        }
    });

    py::class_<PyCurve>(m, "Curve", "A curve of the library: position and derivatives at a parameter t in parameter_range.")
        .def_property_readonly("dimension", [](const PyCurve& c) { return c.curve->dimension(); })
        .def_property_readonly("parameter_range", [](const PyCurve& c) { return py::make_tuple(c.curve->t_min(), c.curve->t_max()); })
        .def_property_readonly(
            "node_parameters", [](const PyCurve& c) { return from_vector(c.node_parameters); }, "the parameter of each data point (interpolants; closed: n + 1 values)")
        .def_property_readonly("method", [](const PyCurve& c) { return c.method; })
        .def(
            "breakpoints", [](const PyCurve& c) { return from_vector(c.curve->breakpoints()); }, "parameters where the curve's pieces join")
        .def("evaluate", &PyCurve::evaluate, py::arg("t"), py::arg("derivatives") = 0,
             "Positions at t (shape (m, dim); (dim,) for a number), or with derivatives = k the jets r, r', …, r^(k) (shape (m, k + 1, dim)). ValueError outside parameter_range.")
        .def(
            "curvature",
            [](const PyCurve& c, const py::object& t) {
                return c.map_parameters(
                    t, [&](double u) { return c.curve->dimension() == 2 ? cagd::analysis::signed_curvature(*c.curve, u) : cagd::analysis::curvature(*c.curve, u); });
            },
            py::arg("t"), "Curvature at t: signed (counter-clockwise positive) for planar curves, |κ| for space curves. ValueError where the speed vanishes.")
        .def(
            "torsion", [](const PyCurve& c, const py::object& t) { return c.map_parameters(t, [&](double u) { return cagd::analysis::torsion(*c.curve, u); }); }, py::arg("t"),
            "Torsion at t (space curves).")
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
            py::arg("error_estimate") = false, "Arc length by adaptive Gauss–Kronrod to 1e-12 (as `cagd analyze --in`); with error_estimate=True the pair (length, estimate).")
        .def(
            "area", [](const PyCurve& c) { return cagd::analysis::area_closed_by_chord(*c.curve); },
            "Signed enclosed area (counter-clockwise positive; planar); an open curve is closed by the chord from its end to its start.")
        .def(
            "bending_energy", [](const PyCurve& c) { return cagd::analysis::bending_energy(*c.curve); }, "∫ κ² ds (Gauss–Legendre per piece)")
        .def("__repr__", [](const PyCurve& c) {
            std::ostringstream s;
            s << "<cagd.Curve" << (c.method.empty() ? "" : " " + c.method) << " dim=" << c.curve->dimension() << " t=[" << c.curve->t_min() << ", " << c.curve->t_max() << "]>";
            return s.str();
        });

    py::class_<Interpolation>(m, "Interpolation", "The whole result of an interpolation: status, message, the curve when ok, and what the method reported.")
        .def_readonly("status", &Interpolation::status)
        .def_readonly("message", &Interpolation::message)
        .def_readonly("curve", &Interpolation::curve)
        .def_property_readonly("ok", [](const Interpolation& r) { return r.curve.has_value(); })
        .def_property_readonly("report", [](const Interpolation& r) { return r.report; })
        .def_property_readonly("quantities",
                               [](const Interpolation& r) {
                                   py::dict d;
                                   for (const auto& [k, v] : r.quantities) d[py::str(k)] = v;
                                   return d;
                               })
        .def_property_readonly("dtau_du", [](const Interpolation& r) { return from_vector(r.dtau_du); });

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
            const cagd::methods::MethodClaims c = method.claims(cagd::methods::parse_parameter_values(method.name, method.parameters, {}));
            py::dict claims;
            claims["parametric_continuity"] = c.parametric_continuity;
            claims["geometric_continuity"] = c.geometric_continuity;
            claims["parameter"] = c.parameter;
            claims["invariance"] = cagd::methods::to_string(c.invariance);
            claims["supports_closed"] = c.supports_closed;
            claims["min_points"] = c.min_points;
            claims["min_points_closed"] = c.min_points_closed;
            claims["max_dimension"] = c.max_dimension;
            d["claims"] = claims;
            out.append(d);
        }
        return out;
    });

    m.def(
        "_compare",
        [](const Array& points, bool closed, const std::vector<std::string>& methods, bool locality, int threads) {
            const Eigen::MatrixXd p = to_matrix(points, "compare: points");
            cagd::compare::ComparisonOptions o;
            o.methods = methods;
            o.closed = closed;
            o.locality = locality;
            o.threads = threads;
            std::vector<cagd::compare::MethodComparison> rows;
            {
                py::gil_scoped_release release;
                rows = cagd::compare::compare_methods(p, o);
            }
            return comparison_dict(rows, closed, static_cast<int>(p.cols()));
        },
        py::arg("points"), py::arg("closed") = false, py::arg("methods") = std::vector<std::string>{}, py::arg("locality") = true, py::arg("threads") = 0);

    m.def(
        "pseudo_energy",
        [](double theta0, double theta1, const std::string& method) {
            cagd::fairness::PseudoEnergyMinimum r;
            {
                py::gil_scoped_release release;
                switch (table_method(method)) {
                    case cagd::fairness::TableMethod::fast: r = cagd::fairness::minimize_pseudo_energy(theta0, theta1); break;
                    case cagd::fairness::TableMethod::reference: r = cagd::fairness::minimize_pseudo_energy_reference(theta0, theta1); break;
                    case cagd::fairness::TableMethod::nlopt: r = cagd::fairness::minimize_pseudo_energy_nlopt(theta0, theta1); break;
                }
            }
            require_ok(r.outcome);
            return minimum_dict(r);
        },
        py::arg("theta0"), py::arg("theta1"), py::arg("method") = "fast",
        "The minimum pseudo-energy J(θ0, θ1) = min over r0, r1 of L²E (pseudo_energy eq 8) with its minimiser and measures, as a dict. method: fast | reference (Romberg + "
        "Ceres CG) | nlopt. ValueError for angles outside [−π, π]; NoSolution at an undefined node.");
    m.def(
        "segment_measures",
        [](double theta0, double theta1, double r0, double r1) {
            const cagd::fairness::PseudoEnergyMinimum r = cagd::fairness::measure_segment(theta0, theta1, r0, r1);
            require_ok(r.outcome);
            return minimum_dict(r);
        },
        py::arg("theta0"), py::arg("theta1"), py::arg("r0"), py::arg("r1"), "The measures (J, L, S, E) of the Hermite segment (θ0, θ1, r0, r1), not minimised.");

    py::class_<cagd::fairness::PseudoEnergyTable>(m, "PseudoEnergyTable", "The table of J(θ0, θ1) and its minimisers (pseudo_energy section 4.1), with the paper's lookup.")
        .def_static(
            "build",
            [](int n, const std::string& placement, const std::string& method, int threads) {
                py::gil_scoped_release release;
                return cagd::fairness::PseudoEnergyTable::build(cagd::fairness::AngleGrid{n, cagd::fairness::parse_node_placement(placement)}, table_method(method), threads);
            },
            py::arg("n") = 36, py::arg("placement") = "periodic", py::arg("method") = "fast", py::arg("threads") = 2)
        .def_static("load", &cagd::fairness::PseudoEnergyTable::load, py::arg("path"))
        .def("save", py::overload_cast<const std::string&>(&cagd::fairness::PseudoEnergyTable::save, py::const_), py::arg("path"))
        .def_property_readonly("nodes", [](const cagd::fairness::PseudoEnergyTable& t) { return from_vector(t.nodes()); })
        .def("node",
             [](const cagd::fairness::PseudoEnergyTable& t, int i, int j) {
                 const int n = static_cast<int>(t.nodes().size());
                 if (i < 0 || i >= n || j < 0 || j >= n)
                     throw cagd::InvalidInput("node (" + std::to_string(i) + ", " + std::to_string(j) + "): indices in [0, " + std::to_string(n - 1) + "]");
                 return minimum_dict(t.node(i, j));
             })
        .def(
            "lookup",
            [](const cagd::fairness::PseudoEnergyTable& t, double theta0, double theta1, bool same_type_only) {
                const cagd::fairness::TableValue v = t.lookup(theta0, theta1, same_type_only);
                return segment_dict(v.pseudo_energy, v.r0, v.r1, v.length, v.area, v.type);
            },
            py::arg("theta0"), py::arg("theta1"), py::arg("same_type_only") = true);

    m.def(
        "log_aesthetic_curve",
        [](double alpha, double c0, double c1, double length, int turn, double start_angle, const std::pair<double, double>& start) {
            cagd::aesthetic::LogAestheticParameters p;
            p.alpha = alpha;
            p.c0 = c0;
            p.c1 = c1;
            p.length = length;
            p.turn = turn;
            p.start_angle = start_angle;
            p.start = Eigen::Vector2d(start.first, start.second);
            return wrap(std::make_shared<cagd::aesthetic::LogAestheticCurve>(p), "log-aesthetic");
        },
        py::arg("alpha"), py::arg("c0") = 1.0, py::arg("c1") = 1.0, py::arg("length") = 1.0, py::arg("turn") = 1, py::arg("start_angle") = 0.0,
        py::arg("start") = std::pair<double, double>{0.0, 0.0}, "The planar log-aesthetic curve ρ^α = c0 s + c1 (typical_curves eq 1–4), parameter s = arc length.");
    m.def(
        "normalized_log_aesthetic_curve",
        [](double alpha, double length) {
            return wrap(std::make_shared<cagd::aesthetic::LogAestheticCurve>(cagd::aesthetic::normalized_log_aesthetic_curve(alpha, length)), "log-aesthetic");
        },
        py::arg("alpha"), py::arg("length"), "The normalised log-aesthetic curve of typical_curves eq (15).");
    m.def(
        "log_aesthetic_space_curve",
        [](double alpha, double beta, double length, double start) {
            return wrap(std::make_shared<cagd::aesthetic::LogAestheticSpaceCurve>(cagd::aesthetic::normalized_log_aesthetic_space_parameters(alpha, beta, length, start)),
                        "log-aesthetic-space");
        },
        py::arg("alpha"), py::arg("beta"), py::arg("length"), py::arg("start") = 0.0, "The normalised log-aesthetic space curve (typical_curves section 5, eq 33–35).");
    m.def(
        "typical_curve",
        [](double alpha, double length, int degree, const std::string& kind) {
            if (kind == "scale-one") return typical_dict(cagd::aesthetic::scale_one_typical_polygon(alpha, length, degree));
            if (kind == "constant-rotation") return typical_dict(cagd::aesthetic::constant_rotation_typical_polygon(alpha, length, degree));
            throw cagd::InvalidInput("kind = '" + kind + "'; allowed scale-one | constant-rotation");
        },
        py::arg("alpha"), py::arg("length"), py::arg("degree"), py::arg("kind") = "constant-rotation",
        "The typical Bézier curve of degree n (typical_curves section 3): its control polygon and the curve.");
    m.def(
        "space_typical_curve",
        [](double alpha, double beta, double length, int degree, double start, const std::string& composition) {
            const cagd::aesthetic::SpaceTypicalPolygon p = cagd::aesthetic::space_typical_polygon(
                cagd::aesthetic::normalized_log_aesthetic_space_parameters(alpha, beta, length, start), degree, frenet_composition(composition));
            py::dict d;
            d["curve"] = wrap(std::make_shared<cagd::BezierCurve>(p.points), "space-typical");
            d["control_points"] = from_matrix(p.points);
            d["curvature_rotations"] = from_vector(p.curvature_rotations);
            d["torsion_rotations"] = from_vector(p.torsion_rotations);
            d["edge_length"] = p.edge_length;
            return d;
        },
        py::arg("alpha"), py::arg("beta"), py::arg("length"), py::arg("degree"), py::arg("start") = 0.0, py::arg("composition") = "alexa",
        "The space typical Bézier curve (typical_curves section 5, eq 36) of the normalised log-aesthetic space curve.");

    py::class_<cagd::spline::ExplicitSpline>(m, "ExplicitSpline", "y(x): a piecewise cubic through values and slopes at abscissae (one column per value).")
        .def_property_readonly("x", [](const cagd::spline::ExplicitSpline& s) { return from_vector(s.x); })
        .def_property_readonly("values", [](const cagd::spline::ExplicitSpline& s) { return from_matrix(s.values); })
        .def_property_readonly("slopes", [](const cagd::spline::ExplicitSpline& s) { return from_matrix(s.slopes); })
        .def("bending_energy", &cagd::spline::ExplicitSpline::bending_energy)
        .def(
            "evaluate",
            [](const cagd::spline::ExplicitSpline& s, const Array& at, int k) {
                const std::vector<double> xs = to_vector(at, "evaluate: x");
                Eigen::MatrixXd out(static_cast<Eigen::Index>(xs.size()), s.values.cols());
                for (std::size_t i = 0; i < xs.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = s.evaluate(xs[i], k);
                return from_matrix(out);
            },
            py::arg("x"), py::arg("derivative") = 0, "The k-th derivative (k ≤ 3) at each x (1-D array): shape (m, columns).");

    m.def(
        "elastic_line",
        [](const Array& x, const Array& a, const py::object& lambda) {
            const std::vector<double> xs = to_vector(x, "elastic_line: x");
            Array a2 = a;
            if (a2.ndim() == 1) a2 = Array::ensure(a2.reshape({a2.shape(0), py::ssize_t{1}}));
            const Eigen::MatrixXd values = to_matrix(a2, "elastic_line: a");
            const std::vector<double> lam = lambda_values(lambda, "elastic_line: lam");
            const cagd::smoothing::ElasticLine line = cagd::smoothing::elastic_line(xs, values, lam);
            return py::make_tuple(line.curve, from_matrix(line.second_derivatives));
        },
        py::arg("x"), py::arg("a"), py::arg("lam"));
    m.def(
        "smooth_curve",
        [](const Array& points, const py::object& lambda) {
            const Eigen::MatrixXd p = to_matrix(points, "smooth_curve: points");
            const std::vector<double> lam = lambda_values(lambda, "smooth_curve: lam");
            return cagd::smoothing::elastic_line_parametric(p, lam).curve;
        },
        py::arg("points"), py::arg("lam"));
    m.def(
        "elastic_space_curve",
        [](const Array& x, const Array& a, const py::object& lambda, int subdivisions) {
            const std::vector<double> xs = to_vector(x, "elastic_space_curve: x");
            const Eigen::MatrixXd values = to_matrix(a, "elastic_space_curve: a");
            const std::vector<double> lam = lambda_values(lambda, "elastic_space_curve: lam");
            std::shared_ptr<cagd::smoothing::ElasticSpaceCurve> c;
            {
                py::gil_scoped_release release;
                c = std::make_shared<cagd::smoothing::ElasticSpaceCurve>(cagd::smoothing::elastic_space_curve(xs, values, lam, subdivisions));
            }
            require_ok(c->outcome);
            return py::make_tuple(wrap(c, "elastic-space-curve"), c->energy);
        },
        py::arg("x"), py::arg("a"), py::arg("lam"), py::arg("subdivisions") = 8);
}
