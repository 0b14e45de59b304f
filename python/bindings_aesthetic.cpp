// aesthetic/: log-aesthetic curves and typical Bézier curves (typical_curves).
#include "bindings.hpp"

namespace cagd_python {

namespace {

py::dict typical_dict(const cagd::aesthetic::TypicalPolygon& p, py::tuple args) {
    py::dict d;
    d["curve"] = with_recipe(wrap(std::make_shared<cagd::BezierCurve>(p.points), "typical"), "typical_curve", std::move(args), py::dict(), py::str("curve"));
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

void bind_aesthetic(py::module_& m) {
    m.def(
        "normalized_log_aesthetic_curve",
        [](double alpha, double length) {
            return with_recipe(wrap(std::make_shared<cagd::aesthetic::LogAestheticCurve>(cagd::aesthetic::normalized_log_aesthetic_curve(alpha, length)), "log-aesthetic"),
                               "normalized_log_aesthetic_curve", py::make_tuple(alpha, length));
        },
        py::arg("alpha"), py::arg("length"), "The normalised log-aesthetic curve of typical_curves eq (15).");
    m.def(
        "log_aesthetic_space_curve",
        [](double alpha, double beta, double length, double start) {
            return with_recipe(wrap(std::make_shared<cagd::aesthetic::LogAestheticSpaceCurve>(cagd::aesthetic::normalized_log_aesthetic_space_parameters(alpha, beta, length, start)),
                                    "log-aesthetic-space"),
                               "log_aesthetic_space_curve", py::make_tuple(alpha, beta, length, start));
        },
        py::arg("alpha"), py::arg("beta"), py::arg("length"), py::arg("start") = 0.0, "The normalised log-aesthetic space curve (typical_curves section 5, eq 33–35).");
    m.def(
        "typical_curve",
        [](double alpha, double length, int degree, const std::string& kind) {
            const py::tuple args = py::make_tuple(alpha, length, degree, kind);
            if (kind == "scale-one") return typical_dict(cagd::aesthetic::scale_one_typical_polygon(alpha, length, degree), args);
            if (kind == "constant-rotation") return typical_dict(cagd::aesthetic::constant_rotation_typical_polygon(alpha, length, degree), args);
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
            d["curve"] = with_recipe(wrap(std::make_shared<cagd::BezierCurve>(p.points), "space-typical"), "space_typical_curve",
                                     py::make_tuple(alpha, beta, length, degree, start, composition), py::dict(), py::str("curve"));
            d["control_points"] = from_matrix(p.points);
            d["curvature_rotations"] = from_vector(p.curvature_rotations);
            d["torsion_rotations"] = from_vector(p.torsion_rotations);
            d["edge_length"] = p.edge_length;
            return d;
        },
        py::arg("alpha"), py::arg("beta"), py::arg("length"), py::arg("degree"), py::arg("start") = 0.0, py::arg("composition") = "alexa",
        "The space typical Bézier curve (typical_curves section 5, eq 36) of the normalised log-aesthetic space curve.");
}

}  // namespace cagd_python
