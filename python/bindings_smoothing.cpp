// smoothing/: the elastic line and its space and parametric forms (hosaka sections 6-7).
#include "bindings.hpp"

namespace cagd_python {

namespace {

// λ: one number for every point, or one per point (the library checks the count and the values).
std::vector<double> lambda_values(const py::object& lambda, const char* name) {
    const Array a = real_array(lambda, name);
    if (a.ndim() == 0) return {a.data()[0]};
    return to_vector(a, name);
}

}  // namespace

void bind_smoothing(py::module_& m) {
    m.def(
        "elastic_line",
        [](const py::object& x, const py::object& a, const py::object& lambda) {
            const std::vector<double> xs = to_vector(real_array(x, "x"), "x");
            Array a2 = real_array(a, "a");
            if (a2.ndim() == 1) a2 = Array::ensure(a2.reshape({a2.shape(0), py::ssize_t{1}}));
            const Eigen::MatrixXd values = to_matrix(a2, "a");
            const std::vector<double> lam = lambda_values(lambda, "lam");
            const cagd::smoothing::ElasticLine line = cagd::smoothing::elastic_line(xs, values, lam);
            return py::make_tuple(line.curve, from_matrix(line.second_derivatives));
        },
        py::arg("x"), py::arg("a"), py::arg("lam"),
        "Hosaka's elastic line (hosaka eq 44–51): y(x) minimising ½ Σ (y(x_i) − a_i)² / λ_i + ½ ∫ y''² dx.\n\n"
        "x: increasing abscissae, shape (n,); a: values, shape (n,) or (n, columns); lam: λ = EI/k ≥ 0, one number or "
        "one per point "
        "(0 interpolates). Returns (ExplicitSpline, y'' at the nodes, shape (n, columns)). ValueError for bad values, "
        "TypeError for non-real input.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> x = np.arange(6.0)\n"
        ">>> spline, second = cagd.elastic_line(x, np.sin(x), 0.1)\n"
        ">>> spline.values.shape, second.shape\n"
        "((6, 1), (6, 1))\n"
        ">>> spline.evaluate(2.5).round(6)\n"
        "array([0.545254])\n");
    m.def(
        "smooth_curve",
        [](const py::object& points, const py::object& lambda) {
            const Eigen::MatrixXd p = to_matrix(real_array(points, "points"), "points");
            const std::vector<double> lam = lambda_values(lambda, "lam");
            return cagd::smoothing::elastic_line_parametric(p, lam).curve;
        },
        py::arg("points"), py::arg("lam"),
        "The parametric elastic line (hosaka section 6): each coordinate of points (n, d) smoothed as elastic_line "
        "over the chord-length "
        "parameter, with lam as there. Returns the ExplicitSpline of the coordinates.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> p = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])\n"
        ">>> bool(np.allclose(cagd.smooth_curve(p, 0.0).values, p))  # lam = 0 interpolates\n"
        "True\n");
    m.def(
        "elastic_space_curve",
        [](const py::object& x, const py::object& a, const py::object& lambda, int subdivisions) {
            const std::vector<double> xs = to_vector(real_array(x, "x"), "x");
            const Eigen::MatrixXd values = to_matrix(real_array(a, "a"), "a");
            const std::vector<double> lam = lambda_values(lambda, "lam");
            std::shared_ptr<cagd::smoothing::ElasticSpaceCurve> c;
            {
                py::gil_scoped_release release;
                c = std::make_shared<cagd::smoothing::ElasticSpaceCurve>(
                    cagd::smoothing::elastic_space_curve(xs, values, lam, subdivisions));
            }
            require_ok(c->outcome);
            return py::make_tuple(
                with_recipe(wrap(c, "elastic-space-curve"), "elastic_space_curve",
                            py::make_tuple(from_vector(xs), from_matrix(values), from_vector(lam), subdivisions),
                            py::dict(), py::int_(0)),
                c->energy);
        },
        py::arg("x"), py::arg("a"), py::arg("lam"), py::arg("subdivisions") = 8,
        "The elastic line in space with the true bending energy ½ ∫ κ² ds (hosaka section 6, after Fig. 7), minimised "
        "by Ceres over C1 cubic "
        "pieces, `subdivisions` per data interval ((n − 1) · subdivisions ≤ 20000).\n\n"
        "x: increasing abscissae (n,); a: the values (y, z), shape (n, 2); lam > 0, one number or one per point. "
        "Returns (Curve r(x) = (x, y, z), "
        "energy). NoSolution when Ceres does not converge.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> x = np.arange(6.0)\n"
        ">>> curve, energy = cagd.elastic_space_curve(x, np.column_stack([np.sin(x), np.cos(x)]), 0.05)\n"
        ">>> curve\n"
        "<cagd.Curve elastic-space-curve, dim=3, t=[0, 5]>\n"
        ">>> round(energy, 6)\n"
        "0.747382\n");
}

}  // namespace cagd_python
