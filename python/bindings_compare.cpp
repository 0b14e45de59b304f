// compare/: every method on the same points (cagd.compare, as `cagd compare`); a peer's curve
// (cagd.peer_curve, as `cagd peers` runs it).
#include <algorithm>
#include <filesystem>

#include "bindings.hpp"
#include "cagd/compare/curve_subject.hpp"
#include "cagd/compare/peer_curves.hpp"
#include "cagd/export/bspline_form.hpp"

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
            c.status != cagd::compare::AttemptStatus::not_applicable && !c.peer
                ? std::optional<double>(c.shared_seconds)
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

// The curve a peer's adapter draws through `points` (compare/peer_curves.hpp): its own exact pieces.
PyCurve peer_curve(const Array& points, const std::string& name, bool closed, const std::string& peers,
                   const std::string& programs) {
    const std::size_t colon = name.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == name.size())
        throw py::value_error("name: \"" + name + "\" is not PEER:CONFIGURATION (e.g. d3-shape:natural)");
    if (!std::filesystem::is_regular_file(std::filesystem::path(peers) / "run"))
        throw py::value_error("peers: \"" + peers + "\" holds no launcher run (the repository's peers/ folder)");
    const cagd::PointList p = to_matrix(points, "points");
    const cagd::compare::PeerLauncher launcher{.run = (std::filesystem::path(peers) / "run").string(),
                                               .programs = programs};
    cagd::compare::PeerRun run;
    {
        py::gil_scoped_release release;
        run = cagd::compare::run_peer(launcher, name.substr(0, colon),
                                      {{.configuration = name.substr(colon + 1), .points = p, .closed = closed}});
    }
    if (!run.installed) throw std::runtime_error(run.reason);
    const cagd::compare::PeerAnswer& answer = run.answers.at(0);
    if (!answer.curve) throw NoSolution(name + ": " + answer.error);
    cagd::BSplineCurve b = cagd::exports::bezier_pieces_curve(answer.curve->form.pieces);
    py::array_t<double> t = from_vector(b.knots()), c = from_matrix(b.control_points());
    const int k = b.degree();
    return with_recipe(wrap(std::make_shared<cagd::BSplineCurve>(std::move(b)), name), "_curve_from_bspline",
                       py::make_tuple(t, c, k));
}

void bind_compare(py::module_& m) {
    m.def("_peer_curve", &peer_curve, py::arg("points"), py::arg("name"), py::arg("closed") = false,
          py::arg("peers") = "peers", py::arg("programs") = "build/peers",
          "The curve another library draws through `points`, run as its users run it by its adapter under the "
          "repository's peers/ folder (docs/peers.md): `name` is PEER:CONFIGURATION (d3-shape:natural, "
          "gsl:cspline, metapost:hobby, …; `cagd peers --peers peers --list-markdown` lists them), `programs` "
          "where CMake built the C and C++ adapters. The curve is the peer's own exact pieces (a pickle keeps "
          "them); where the peer gives samples only (plotutils's tension splines), the adapter's approximation of "
          "its curve (docs/peers.md). ValueError for a name or folder that is not one; RuntimeError when the peer is "
          "not installed "
          "here; cagd.NoSolution when the peer refuses the points or fails on them, with its message.");
    m.def(
        "_compare",
        [](const Array& points, bool closed, const std::vector<std::string>& methods, bool locality, int threads,
           const std::string& peers, const std::string& programs) {
            const Eigen::MatrixXd p = to_matrix(points, "compare: points");
            cagd::compare::ComparisonOptions o;
            // Registry names, and peers' PEER:CONFIGURATION run by their adapters under `peers`.
            std::vector<std::string> peer_names;
            for (const std::string& name : methods)
                (name.find(':') == std::string::npos ? o.methods : peer_names).push_back(name);
            if (!peer_names.empty()) {
                if (!std::filesystem::is_regular_file(std::filesystem::path(peers) / "run"))
                    throw py::value_error("peers: \"" + peers +
                                          "\" holds no launcher run (the repository's peers/ folder)");
                const std::vector<cagd::compare::PeerConfiguration> manifest =
                    cagd::compare::read_peer_manifest((std::filesystem::path(peers) / "peers.csv").string());
                for (const std::string& name : peer_names)
                    if (std::none_of(manifest.begin(), manifest.end(), [&](const auto& c) { return c.name() == name; }))
                        throw py::value_error("methods: \"" + name + "\" is no peer configuration of " + peers +
                                              "/peers.csv");
                cagd::compare::InstalledPeers installed = cagd::compare::installed_peer_subjects(
                    {.run = (std::filesystem::path(peers) / "run").string(), .programs = programs}, manifest,
                    [&](const std::string& n) {
                        return std::find(peer_names.begin(), peer_names.end(), n) != peer_names.end();
                    });
                if (!installed.skipped.empty()) throw std::runtime_error(installed.skipped.front());
                o.peers = std::move(installed.subjects);
            }
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
        py::arg("locality") = true, py::arg("threads") = 0, py::arg("peers") = "peers",
        py::arg("programs") = "build/peers");
}

}  // namespace cagd_python
