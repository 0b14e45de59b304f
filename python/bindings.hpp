#pragma once
// What the bindings files of the Python module share: NumPy arrays ↔ Eigen, the library's
// outcomes as cagd.NoSolution, and the Curve class every binding returns. One bindings_<folder>.cpp
// per library folder binds that folder's functions; cagd_module.cpp wires them into _cagd.
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
#include "cagd/core/parallel.hpp"
#include "cagd/export/curve_json.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"
#include "cagd/fairness/pseudo_energy_table.hpp"
#include "cagd/io/output_file.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"
#include "cagd/smoothing/elastic_line.hpp"
#include "cagd/smoothing/elastic_space_curve.hpp"
#include "cagd/spline/bezier.hpp"

namespace cagd_python {

namespace py = pybind11;

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A numerical outcome for valid input, raised as cagd.NoSolution.
struct NoSolution : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline const char* status_name(cagd::Status s) {
    switch (s) {
        case cagd::Status::ok: return "ok";
        case cagd::Status::no_convergence: return "no_convergence";
        case cagd::Status::no_solution: return "no_solution";
        case cagd::Status::not_representable: return "not_representable";
    }
    return "unknown";
}

inline void require_ok(const cagd::Outcome& outcome) {
    if (!outcome.ok()) throw NoSolution(outcome.message);
}

// An (n, d) array of finite or non-finite doubles (the library checks the values) → n × d.
inline Eigen::MatrixXd to_matrix(const Array& a, const char* name) {
    if (a.ndim() != 2)
        throw cagd::InvalidInput(std::string(name) + ": expected a 2-D array (n, d), got " + std::to_string(a.ndim()) +
                                 " dimension(s)");
    Eigen::MatrixXd m(a.shape(0), a.shape(1));
    auto r = a.unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
        for (py::ssize_t j = 0; j < a.shape(1); ++j) m(i, j) = r(i, j);
    return m;
}

inline std::vector<double> to_vector(const Array& a, const char* name) {
    if (a.ndim() != 1)
        throw cagd::InvalidInput(std::string(name) + ": expected a 1-D array, got " + std::to_string(a.ndim()) +
                                 " dimension(s)");
    return std::vector<double>(a.data(), a.data() + a.shape(0));
}

inline py::array_t<double> from_matrix(const Eigen::MatrixXd& m) {
    py::array_t<double> out({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
    auto w = out.mutable_unchecked<2>();
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        for (Eigen::Index j = 0; j < m.cols(); ++j) w(i, j) = m(i, j);
    return out;
}

inline py::array_t<double> from_vector(const std::vector<double>& v) {
    py::array_t<double> out(static_cast<py::ssize_t>(v.size()));
    std::copy(v.begin(), v.end(), out.mutable_data());
    return out;
}

// The argument `name` as a C-contiguous array of doubles of its own shape (0-d for a number, numpy
// scalars and 0-d arrays included). TypeError naming the argument for anything but real numbers:
// bool, complex, str, None and other objects are refused, never cast.
inline Array real_array(const py::object& value, const char* name) {
    py::array raw;
    try {
        raw = py::array::ensure(value);
    } catch (const py::error_already_set&) {
        raw = py::array();
    }
    const char kind = raw ? raw.dtype().kind() : 'O';
    if (kind != 'i' && kind != 'u' && kind != 'f')
        throw py::type_error(
            std::string(name) + ": expected real numbers, got " +
            std::string(py::str(py::type::of(value).attr("__name__"))) +
            (raw && raw.ndim() > 0 ? " of dtype " + std::string(py::str(raw.dtype())) : std::string()));
    return Array::ensure(raw);
}

// A whole number argument in [lo, hi]: TypeError naming it when it is not an integer (a bool, a
// float, a string), ValueError naming it and the range when it lies outside (also 2**40: never a
// cast error).
inline int int_argument(const py::handle& value, const char* name, int lo, int hi) {
    if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))
        throw py::type_error(std::string(name) + ": expected an integer, got " +
                             py::str(py::type::of(value).attr("__name__")).cast<std::string>());
    const py::object v = py::reinterpret_borrow<py::object>(value);
    if (v < py::int_(lo) || v > py::int_(hi))
        throw py::value_error(std::string(name) + " = " + py::repr(v).cast<std::string>() + " is outside [" +
                              std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v.cast<int>();
}

// The parameter argument t (real_array).
inline Array parameter_array(const py::object& t_in) { return real_array(t_in, "t"); }

// The most derivatives evaluate() returns: every curve of the library is piecewise polynomial of
// degree ≤ 7 or analytic with jets of order ≤ 4, so higher orders are zeros or refused.
inline constexpr int kMaxPythonDerivatives = 16;

// Arrays of at least this many parameters are evaluated on every core (cagd::parallel_for over
// kEvaluationChunks chunks, each a contiguous run of parameters): below it, starting the threads
// costs more than they save (≈ 50 µs against ≈ 40 ns per jet).
inline constexpr long kParallelEvaluationMinimum = 1L << 16;
inline constexpr long kEvaluationChunks = 16;

// body(begin, end) over [0, m) in contiguous chunks, on every core when m is large (above); the
// results are the same as one serial loop's, and so is the exception (that of the first bad index).
template <class Body>
void for_each_chunk(long m, const Body& body) {
    if (m < kParallelEvaluationMinimum || cagd::hardware_threads() < 2) {
        body(0L, m);
        return;
    }
    cagd::parallel_for(kEvaluationChunks, cagd::hardware_threads(),
                       [&](long c) { body(m * c / kEvaluationChunks, m * (c + 1) / kEvaluationChunks); });
}

// A curve of the library with what its construction reported.
struct PyCurve {
    std::shared_ptr<const cagd::Curve> curve;
    std::vector<double> node_parameters;  // u of each data point (interpolants)
    std::string method;
    // How to build it again, for pickling: (name of a cagd function, args, kwargs, key), the curve
    // being the call's result, or its item `key` (a dict key or a tuple index); None when unknown.
    py::object recipe = py::none();
    int points = 0;       // data points of an interpolant (0 otherwise)
    bool closed = false;  // an interpolant through closed data
    // An interpolant: `curve` is in the method's parameter τ (MethodParameterCurve), and this is the
    // same curve in the registry's span parameter u; null otherwise.
    std::shared_ptr<const cagd::methods::MethodParameterCurve> in_tau{};
    // What made an interpolant (method, all its parameter values, points): written into exported
    // files (Curve.write); null for other curves.
    std::shared_ptr<const cagd::exports::CurveProvenance> provenance{};

    // Positions (derivatives = 0: shape t.shape + (dim,)) or jets (t.shape + (derivatives + 1,
    // dim)): rows are r, r', r'', … at each t. A number (or 0-d array) gives (dim,) or (k + 1, dim).
    py::array evaluate(const py::object& t_in, int derivatives) const {
        if (derivatives < 0 || derivatives > kMaxPythonDerivatives)
            throw cagd::InvalidInput("derivatives = " + std::to_string(derivatives) + "; allowed 0.." +
                                     std::to_string(kMaxPythonDerivatives));
        const Array t = parameter_array(t_in);
        const py::ssize_t m = t.size(), rows = derivatives + 1, dim = curve->dimension();
        std::vector<py::ssize_t> shape(t.shape(), t.shape() + t.ndim());
        if (derivatives > 0) shape.push_back(rows);
        shape.push_back(dim);
        py::array_t<double> out(shape);
        const double* ts = t.data();
        double* w = out.mutable_data();
        {
            py::gil_scoped_release release;
            if (rows <= cagd::kJetCapacity && dim <= 3) {
                for_each_chunk(m, [&](long begin, long end) {
                    curve->jets_into(ts + begin, static_cast<std::size_t>(end - begin), derivatives,
                                     w + begin * rows * dim);
                });
            } else {
                for (py::ssize_t k = 0; k < m; ++k) {
                    const Eigen::MatrixXd jet = curve->jet(ts[k], derivatives);
                    double* row = w + k * rows * dim;
                    for (py::ssize_t r = 0; r < rows; ++r)
                        for (py::ssize_t c = 0; c < dim; ++c) row[r * dim + c] = jet(r, c);
                }
            }
        }
        return out;
    }

    // A function of t, vectorised: a float for a number (or 0-d array), an array of t's shape otherwise.
    template <class F>
    py::object map_parameters(const py::object& t_in, F f) const {
        const Array t = parameter_array(t_in);
        py::array_t<double> out(std::vector<py::ssize_t>(t.shape(), t.shape() + t.ndim()));
        const double* ts = t.data();
        double* w = out.mutable_data();
        {
            py::gil_scoped_release release;
            for_each_chunk(t.size(), [&](long begin, long end) {
                for (long k = begin; k < end; ++k) w[k] = f(ts[k]);
            });
        }
        if (t.ndim() == 0) return py::float_(w[0]);
        return out;
    }
};

inline PyCurve wrap(std::shared_ptr<const cagd::Curve> c, std::string method = {}, std::vector<double> nodes = {}) {
    return PyCurve{std::move(c), std::move(nodes), std::move(method)};
}

// The curve with the recipe of the cagd function `name` that built it (PyCurve::recipe).
inline PyCurve with_recipe(PyCurve c, const char* name, py::tuple args, py::dict kwargs = py::dict(),
                           py::object key = py::none()) {
    c.recipe = py::make_tuple(name, std::move(args), std::move(kwargs), std::move(key));
    return c;
}

void bind_core(py::module_& m);
void bind_methods(py::module_& m);
void bind_compare(py::module_& m);
void bind_fairness(py::module_& m);
void bind_aesthetic(py::module_& m);
void bind_spline(py::module_& m);
void bind_smoothing(py::module_& m);
void bind_surface(py::module_& m);
void bind_export(py::module_& m);

}  // namespace cagd_python
