// spline/: Hosaka's explicit spline y(x) (the elastic line's result).
#include "bindings.hpp"

namespace cagd_python {

void bind_spline(py::module_& m) {
    py::class_<cagd::spline::ExplicitSpline>(
        m, "ExplicitSpline",
        "y(x): a piecewise cubic through values and slopes at abscissae (one column per value).\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> x = np.arange(4.0)\n"
        ">>> s, _ = cagd.elastic_line(x, x ** 2, 0.0)  # λ = 0: the natural spline through the values\n"
        ">>> s.evaluate(1.5), s.evaluate(1.5, 1), s.values.shape\n"
        "(array([2.2]), array([3.]), (4, 1))\n")
        .def_property_readonly(
            "x", [](const cagd::spline::ExplicitSpline& s) { return from_vector(s.x); }, "the abscissae, shape (n,)")
        .def_property_readonly(
            "values", [](const cagd::spline::ExplicitSpline& s) { return from_matrix(s.values); },
            "y at the abscissae, shape (n, columns)")
        .def_property_readonly(
            "slopes", [](const cagd::spline::ExplicitSpline& s) { return from_matrix(s.slopes); },
            "y' at the abscissae, shape (n, columns)")
        .def("bending_energy", &cagd::spline::ExplicitSpline::bending_energy,
             "∫ y''² dx over the abscissae, summed over the columns")
        .def(
            "evaluate",
            [](const cagd::spline::ExplicitSpline& s, const py::object& at, int k) -> py::array {
                const Array a = real_array(at, "x");
                if (a.ndim() > 1)
                    throw cagd::InvalidInput("x: expected a number or a 1-D array, got " + std::to_string(a.ndim()) +
                                             " dimensions");
                const std::vector<double> xs(a.data(), a.data() + a.size());
                Eigen::MatrixXd out(static_cast<Eigen::Index>(xs.size()), s.values.cols());
                for (std::size_t i = 0; i < xs.size(); ++i)
                    out.row(static_cast<Eigen::Index>(i)) = s.evaluate(xs[i], k);
                const py::array_t<double> rows = from_matrix(out);
                if (a.ndim() == 0) return rows[py::int_(0)];
                return rows;
            },
            py::arg("x"), py::arg("derivative") = 0,
            "The k-th derivative (k ≤ 3) at x: shape (columns,) for a number, (m, columns) for a 1-D array of m "
            "abscissae.");
}

}  // namespace cagd_python
