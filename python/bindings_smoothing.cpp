// smoothing/: the elastic line and its space and parametric forms (hosaka sections 6-7).
#include "bindings.hpp"

namespace cagd_python {

namespace {

// λ: one number for every point, or one per point (the library checks the count and the values).
std::vector<double> lambda_values(const py::object& lambda, const char* name) {
    if (py::isinstance<py::float_>(lambda) || py::isinstance<py::int_>(lambda)) return {lambda.cast<double>()};
    const Array a = Array::ensure(lambda);
    if (!a) throw cagd::InvalidInput(std::string(name) + ": a number or a 1-D array of numbers");
    return to_vector(a, name);
}

}  // namespace

void bind_smoothing(py::module_& m) {
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

}  // namespace cagd_python
