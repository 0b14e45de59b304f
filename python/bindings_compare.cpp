// compare/: every method on the same points (cagd.compare, as `cagd compare`).
#include "bindings.hpp"

namespace cagd_python {

namespace {

py::dict comparison_dict(const std::vector<cagd::compare::MethodComparison>& rows, bool closed, int dimension) {
    const auto n = static_cast<py::ssize_t>(rows.size());
    std::vector<std::string> method, status, note;
    // Each measure with a validity mask (cagd.compare turns the pairs into masked arrays).
    const std::vector<std::string> names = {"length",
                                            "area",
                                            "pseudo_energy",
                                            "bending_energy",
                                            "curvature_sign_changes",
                                            "max_abs_curvature",
                                            "max_abs_curvature_derivative",
                                            "overshoot",
                                            "spans",
                                            "locality_footprint",
                                            "seconds",
                                            "max_abs_torsion",
                                            "shared_seconds"};
    std::vector<py::array_t<double>> values;
    std::vector<py::array_t<bool>> valid;
    for (std::size_t k = 0; k < names.size(); ++k) {
        values.emplace_back(n);
        valid.emplace_back(n);
    }
    for (py::ssize_t i = 0; i < n; ++i) {
        const auto& c = rows[static_cast<std::size_t>(i)];
        method.push_back(c.method);
        status.push_back(cagd::compare::to_string(c.status));
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
            c.status != cagd::compare::AttemptStatus::not_applicable ? std::optional<double>(c.shared_seconds)
                                                                     : std::nullopt,
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

}  // namespace

void bind_compare(py::module_& m) {
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
        py::arg("points"), py::arg("closed") = false, py::arg("methods") = std::vector<std::string>{},
        py::arg("locality") = true, py::arg("threads") = 0);
}

}  // namespace cagd_python
