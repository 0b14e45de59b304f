// fairness/: the pseudo-energy of a segment, its minimum and the lookup table (pseudo_energy).
#include "bindings.hpp"

namespace cagd_python {

namespace {

// The quantities a table node and a table lookup share (pseudo_energy eq 8, 16–21).
py::dict segment_dict(double pseudo_energy, double r0, double r1, double length, double area,
                      cagd::fairness::SegmentType type) {
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

}  // namespace

void bind_fairness(py::module_& m) {
    m.def(
        "pseudo_energy",
        [](double theta0, double theta1, const std::string& method) {
            cagd::fairness::PseudoEnergyMinimum r;
            {
                py::gil_scoped_release release;
                switch (table_method(method)) {
                    case cagd::fairness::TableMethod::fast:
                        r = cagd::fairness::minimize_pseudo_energy(theta0, theta1);
                        break;
                    case cagd::fairness::TableMethod::reference:
                        r = cagd::fairness::minimize_pseudo_energy_reference(theta0, theta1);
                        break;
                    case cagd::fairness::TableMethod::nlopt:
                        r = cagd::fairness::minimize_pseudo_energy_nlopt(theta0, theta1);
                        break;
                }
            }
            require_ok(r.outcome);
            return minimum_dict(r);
        },
        py::arg("theta0"), py::arg("theta1"), py::arg("method") = "fast",
        "The minimum pseudo-energy J(θ0, θ1) = min over r0, r1 of L²E (pseudo_energy eq 8) with its minimiser and "
        "measures, as a dict. method: fast | reference (Romberg + "
        "Ceres CG) | nlopt. ValueError for angles outside [−π, π]; NoSolution at an undefined node.\n\n"
        ">>> import cagd\n"
        ">>> m = cagd.pseudo_energy(0.3, 0.7)\n"
        ">>> round(m['pseudo_energy'], 6), round(m['r0'], 6), round(m['r1'], 6), m['type']\n"
        "(3.254064, 0.992474, 1.060921, 's')\n");
    m.def(
        "segment_measures",
        [](double theta0, double theta1, double r0, double r1) {
            const cagd::fairness::PseudoEnergyMinimum r = cagd::fairness::measure_segment(theta0, theta1, r0, r1);
            require_ok(r.outcome);
            return minimum_dict(r);
        },
        py::arg("theta0"), py::arg("theta1"), py::arg("r0"), py::arg("r1"),
        "The measures (J, L, S, E) of the unit-chord Hermite segment (θ0, θ1, r0, r1), not minimised. ValueError for "
        "angles outside [−π, π] "
        "or unless 0 < r0, r1 ≤ 1e60 (beyond, r⁴ in the strain integrand leaves double range).\n\n"
        ">>> import cagd\n"
        ">>> d = cagd.segment_measures(0.3, 0.7, 1.0, 1.0)\n"
        ">>> d['type'], d['pseudo_energy'] > cagd.pseudo_energy(0.3, 0.7)['pseudo_energy']\n"
        "('s', True)\n");

    py::class_<cagd::fairness::PseudoEnergyTable>(
        m, "PseudoEnergyTable",
        "The table of J(θ0, θ1) and its minimisers (pseudo_energy section 4.1), with the paper's lookup.\n\n"
        ">>> import cagd\n"
        ">>> t = cagd.PseudoEnergyTable.build(n=12, threads=1)  # 30° nodes\n"
        ">>> t.nodes.shape, t.node(2, 3)[\"type\"]\n"
        "((12,), 's')\n"
        ">>> round(t.lookup(0.3, -0.5)[\"pseudo_energy\"], 6), round(cagd.pseudo_energy(0.3, -0.5)[\"pseudo_energy\"], "
        "6)\n"
        "(1.147886, 0.778877)\n")
        .def_static(
            "build",
            [](int n, const std::string& placement, const std::string& method, int threads) {
                py::gil_scoped_release release;
                return cagd::fairness::PseudoEnergyTable::build(
                    cagd::fairness::AngleGrid{n, cagd::fairness::parse_node_placement(placement)}, table_method(method),
                    threads);
            },
            py::arg("n") = 36, py::arg("placement") = "periodic", py::arg("method") = "fast", py::arg("threads") = 2)
        .def_static("load", &cagd::fairness::PseudoEnergyTable::load, py::arg("path"))
        .def("save", py::overload_cast<const std::string&>(&cagd::fairness::PseudoEnergyTable::save, py::const_),
             py::arg("path"),
             "Writes the table (with its checksum line) to path, atomically: OSError naming the path when a write "
             "fails, the old file kept; "
             "ValueError for a directory or a loop of links.")
        .def_property_readonly(
            "nodes", [](const cagd::fairness::PseudoEnergyTable& t) { return from_vector(t.nodes()); },
            "the node angles in [−π, π), radians")
        .def(
            "node",
            [](const cagd::fairness::PseudoEnergyTable& t, int i, int j) {
                const int n = static_cast<int>(t.nodes().size());
                if (i < 0 || i >= n || j < 0 || j >= n)
                    throw cagd::InvalidInput("node (" + std::to_string(i) + ", " + std::to_string(j) +
                                             "): indices in [0, " + std::to_string(n - 1) + "]");
                return minimum_dict(t.node(i, j));
            },
            py::arg("i"), py::arg("j"),
            "The minimum at node (nodes[i], nodes[j]): J, r0, r1, length, area, type, local minima and the runner-up "
            "(a dict).")
        .def(
            "lookup",
            [](const cagd::fairness::PseudoEnergyTable& t, double theta0, double theta1, bool same_type_only) {
                const cagd::fairness::TableValue v = t.lookup(theta0, theta1, same_type_only);
                return segment_dict(v.pseudo_energy, v.r0, v.r1, v.length, v.area, v.type);
            },
            py::arg("theta0"), py::arg("theta1"), py::arg("same_type_only") = true,
            "The paper's lookup at (θ0, θ1) (radians): bilinear over the cell's corners of the nearest node's type "
            "(section 4.1), or over every "
            "defined corner with same_type_only=False; J, r0, r1, length, area and the type used (a dict).");

    m.def(
        "log_aesthetic_curve",
        [](double alpha, double c0, double c1, double length, int turn, double start_angle,
           const std::pair<double, double>& start) {
            cagd::aesthetic::LogAestheticParameters p;
            p.alpha = alpha;
            p.c0 = c0;
            p.c1 = c1;
            p.length = length;
            p.turn = turn;
            p.start_angle = start_angle;
            p.start = Eigen::Vector2d(start.first, start.second);
            return with_recipe(
                wrap(std::make_shared<cagd::aesthetic::LogAestheticCurve>(p), "log-aesthetic"), "log_aesthetic_curve",
                py::make_tuple(alpha, c0, c1, length, turn, start_angle, py::make_tuple(start.first, start.second)));
        },
        py::arg("alpha"), py::arg("c0") = 1.0, py::arg("c1") = 1.0, py::arg("length") = 1.0, py::arg("turn") = 1,
        py::arg("start_angle") = 0.0, py::arg("start") = std::pair<double, double>{0.0, 0.0},
        "The planar log-aesthetic curve ρ^α = c0 s + c1 (typical_curves eq 1–4), parameter s = arc length ∈ [0, "
        "length], starting at `start` in "
        "direction `start_angle` (radians), turning left (turn = 1) or right (turn = −1).\n\n"
        ">>> import cagd\n"
        ">>> c = cagd.log_aesthetic_curve(1.5)  # ρ^1.5 = s + 1\n"
        ">>> round(c.curvature(0.0), 6), round(c.curvature(1.0), 6)  # κ = (s + 1)^(−1/1.5)\n"
        "(1.0, 0.629961)\n");
}

}  // namespace cagd_python
