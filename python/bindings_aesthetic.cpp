// aesthetic/: log-aesthetic curves and typical Bézier curves (typical_curves).
#include "bindings.hpp"

namespace cagd_python {

namespace {

py::dict typical_dict(const cagd::aesthetic::TypicalPolygon& p, py::tuple args) {
    py::dict d;
    d["curve"] = with_recipe(wrap(std::make_shared<cagd::BezierCurve>(p.points), "typical"), "typical_curve",
                             std::move(args), py::dict(), py::str("curve"));
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
            return with_recipe(wrap(std::make_shared<cagd::aesthetic::LogAestheticCurve>(
                                        cagd::aesthetic::normalized_log_aesthetic_curve(alpha, length)),
                                    "log-aesthetic"),
                               "normalized_log_aesthetic_curve", py::make_tuple(alpha, length));
        },
        py::arg("alpha"), py::arg("length"),
        "The normalised log-aesthetic curve of typical_curves eq (15): θ(s) = α s^((α−1)/α), κ = (α − 1) s^(−1/α), for "
        "α < 0 or α > 1 (α the "
        "slope of its logarithmic curvature graph), arc length `length`, parameter s = arc length, starting at the "
        "origin along the x axis.\n\n"
        ">>> import cagd\n"
        ">>> c = cagd.normalized_log_aesthetic_curve(-0.5, 1.0)  # κ = −1.5 s²\n"
        ">>> c, round(c.arc_length(), 9), round(c.curvature(0.5), 9), round(c.curvature(1.0), 9)\n"
        "(<cagd.Curve log-aesthetic, dim=2, t=[0, 1]>, 1.0, -0.375, -1.5)\n");
    m.def(
        "log_aesthetic_space_curve",
        [](double alpha, double beta, double length, double start) {
            return with_recipe(
                wrap(std::make_shared<cagd::aesthetic::LogAestheticSpaceCurve>(
                         cagd::aesthetic::normalized_log_aesthetic_space_parameters(alpha, beta, length, start)),
                     "log-aesthetic-space"),
                "log_aesthetic_space_curve", py::make_tuple(alpha, beta, length, start));
        },
        py::arg("alpha"), py::arg("beta"), py::arg("length"), py::arg("start") = 0.0,
        "The normalised log-aesthetic space curve (typical_curves section 5, eq 33–35): curvature and torsion laws "
        "with slopes alpha and beta, arc "
        "length `length`, the laws started at s0 = start; parameter s = arc length.\n\n"
        ">>> import cagd\n"
        ">>> c = cagd.log_aesthetic_space_curve(1.5, 1.2, 1.0, start=0.1)\n"
        ">>> c.dimension, round(c.arc_length(), 9), round(c.torsion(0.5), 6)\n"
        "(3, 1.0, 0.306129)\n");
    m.def(
        "typical_curve",
        [](double alpha, double length, int degree, const std::string& kind) {
            const py::tuple args = py::make_tuple(alpha, length, degree, kind);
            if (kind == "scale-one")
                return typical_dict(cagd::aesthetic::scale_one_typical_polygon(alpha, length, degree), args);
            if (kind == "constant-rotation")
                return typical_dict(cagd::aesthetic::constant_rotation_typical_polygon(alpha, length, degree), args);
            throw cagd::InvalidInput("kind = '" + kind + "'; allowed scale-one | constant-rotation");
        },
        py::arg("alpha"), py::arg("length"), py::arg("degree"), py::arg("kind") = "constant-rotation",
        "The typical Bézier curve of degree n (typical_curves section 3): its control polygon and the curve, as a dict "
        "(curve, control_points "
        "(degree + 1, 2), edge_lengths, rotations, scales). kind: constant-rotation or scale-one.\n\n"
        ">>> import cagd\n"
        ">>> t = cagd.typical_curve(-0.5, 1.0, 6)\n"
        ">>> sorted(t), t[\"control_points\"].shape\n"
        "(['control_points', 'curve', 'edge_lengths', 'rotations', 'scales'], (7, 2))\n");
    m.def(
        "space_typical_curve",
        [](double alpha, double beta, double length, int degree, double start, const std::string& composition) {
            const cagd::aesthetic::SpaceTypicalPolygon p = cagd::aesthetic::space_typical_polygon(
                cagd::aesthetic::normalized_log_aesthetic_space_parameters(alpha, beta, length, start), degree,
                frenet_composition(composition));
            py::dict d;
            d["curve"] = with_recipe(
                wrap(std::make_shared<cagd::BezierCurve>(p.points), "space-typical"), "space_typical_curve",
                py::make_tuple(alpha, beta, length, degree, start, composition), py::dict(), py::str("curve"));
            d["control_points"] = from_matrix(p.points);
            d["curvature_rotations"] = from_vector(p.curvature_rotations);
            d["torsion_rotations"] = from_vector(p.torsion_rotations);
            d["edge_length"] = p.edge_length;
            return d;
        },
        py::arg("alpha"), py::arg("beta"), py::arg("length"), py::arg("degree"), py::arg("start") = 0.0,
        py::arg("composition") = "alexa",
        "The space typical Bézier curve (typical_curves section 5, eq 36) of the normalised log-aesthetic space curve, "
        "as a dict (curve, "
        "control_points (degree + 1, 3), curvature_rotations, torsion_rotations, edge_length). composition: alexa, "
        "kappa_then_tau or tau_then_kappa.\n\n"
        ">>> import cagd\n"
        ">>> t = cagd.space_typical_curve(1.5, 1.2, 1.0, 9, start=0.1)\n"
        ">>> t[\"control_points\"].shape, t[\"curve\"].dimension\n"
        "((10, 3), 3)\n");
}

}  // namespace cagd_python
