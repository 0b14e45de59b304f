// The viewer's WebAssembly module (embind): the registry, the comparison of the chosen
// configurations on the page's points with its figure data and measures, how far each span moved
// since a drag began, and the curve exports. Every number comes from the library (compare/,
// export/); this file only converts between JavaScript values and the library's types.
//
// JavaScript API (web/site/viewer.js is its one caller; tests/web checks it against the native build):
//   registry()                     -> {methods: [...], configurations: [...], formats: [...]}
//   compare(request)               -> {ok, message, diagonal, combScale, header, rows, results: [...]}
//     request: {points: [x0, y0, x1, y1, …], closed, configurations: [{name, parameters: {p: "v"}}],
//               perSpan, measures, figure, anchor, motion, continuation}
//     measures: also compare's measures table (header, rows; tens of ms per method at 100 points,
//     so the page computes them in a worker); figure (default true): the curves, κ(s) and combs.
//     anchor: keep these curves as the start of a drag; motion: per span, how far each curve moved
//     since the anchor (compare::span_displacements), divided by the data diagonal. continuation:
//     a drag frame; the iterative methods start from the last comparison's solutions when it had
//     as many points (methods::interpolate_from), else solve anew.
//     peers: [{name: "peer:configuration", pieces: [x0, y0, …, x3, y3, …], error}]: curves the page's
//     JavaScript peers drew (web/site/peers.mjs: d3-shape, paper.js, three.js, as their users call
//     them), eight numbers per cubic piece (breaks 0, 1, …) or the peer's error; measured and drawn
//     as compare measures a peer (compare::peer_drawn_curve), rows after the configurations'.
//   readPoints(text, source)       -> {ok, message, points: [[x, y], …]}: the command's CSV reader
//   exportCurve(request)           -> {ok, message, text}
//     request: {points, closed, name, parameters, format: "svg" | "dxf" | "json" | "csv", comb, samples}
//     (a peer's curve: name "peer:configuration" and its pieces, as in compare's peers)
// Bad input never throws into JavaScript: {ok: false, message} names it, as the command's messages.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <chrono>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cagd/compare/comparison_figure.hpp"
#include "cagd/compare/comparison_tables.hpp"
#include "cagd/compare/curve_subject.hpp"
#include "cagd/compare/locality_footprint.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/core/points.hpp"
#include "cagd/core/version.hpp"
#include "cagd/export/curve_formats.hpp"
#include "cagd/methods/curve_provenance.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"

namespace {

using emscripten::val;

// The most points the page sends (a drawing, not a data set: the command takes larger inputs).
constexpr long kMaxViewerPoints = 100'000;
// The most samples per span the page asks for.
constexpr int kMaxPerSpan = 256;

val float64_array(const std::vector<double>& v) {
    val out = val::global("Float64Array").new_(v.size());
    out.call<void>("set", val(emscripten::typed_memory_view(v.size(), v.data())));
    return out;
}

template <class T>
val js_array(const std::vector<T>& v) {
    val out = val::array();
    for (const T& x : v) out.call<void>("push", val(x));
    return out;
}

cagd::PointList points_of(const val& request) {
    const val p = request["points"];
    if (p.isUndefined() || p.isNull()) cagd::fail_input("viewer", "the request has no points");
    const std::vector<double> flat = emscripten::convertJSArrayToNumberVector<double>(p);
    if (flat.size() % 2 != 0)
        cagd::fail_input("viewer",
                         "points needs an even count of coordinates (x, y pairs), got " + std::to_string(flat.size()));
    const long n = static_cast<long>(flat.size() / 2);
    if (n > kMaxViewerPoints)
        cagd::fail_input("viewer",
                         std::to_string(n) + " points; the viewer takes at most " + std::to_string(kMaxViewerPoints));
    cagd::PointList points(n, 2);
    for (long i = 0; i < n; ++i)
        points.row(i) << flat[static_cast<std::size_t>(2 * i)], flat[static_cast<std::size_t>(2 * i + 1)];
    return points;
}

bool flag(const val& request, const char* name) {
    const val v = request[name];
    return !v.isUndefined() && !v.isNull() && v.as<bool>();
}

cagd::methods::ParameterText parameters_of(const val& object) {
    cagd::methods::ParameterText text;
    if (object.isUndefined() || object.isNull()) return text;
    const std::vector<std::string> keys =
        emscripten::vecFromJSArray<std::string>(val::global("Object").call<val>("keys", object));
    // As text whatever JavaScript type it has (a number typed into the console, a string from the page).
    for (const std::string& k : keys) text[k] = val::global("String")(object[k]).as<std::string>();
    return text;
}

val failure(const std::string& message) {
    val out = val::object();
    out.set("ok", false);
    out.set("message", message);
    return out;
}

// A JavaScript peer's curve as the page drew it ({name, pieces, error}; see compare above), through
// `points`; `name` receives its name.
cagd::compare::DrawnCurve peer_curve_of(const val& entry, const cagd::PointList& points, bool closed,
                                        std::string& name) {
    name = val::global("String")(entry["name"]).as<std::string>();
    const std::size_t colon = name.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == name.size())
        cagd::fail_input("viewer", "peer \"" + name + "\" is not peer:configuration");
    cagd::compare::PeerAnswer answer;
    if (const val error = entry["error"]; !error.isUndefined() && !error.isNull()) {
        answer.error = val::global("String")(error).as<std::string>();
    } else {
        const std::vector<double> flat = emscripten::convertJSArrayToNumberVector<double>(entry["pieces"]);
        const std::size_t pieces = flat.size() / 8;
        if (pieces == 0 || flat.size() % 8 != 0 || pieces > static_cast<std::size_t>(kMaxViewerPoints))
            cagd::fail_input("viewer", name + ": pieces needs 8 numbers per cubic piece, at most " +
                                           std::to_string(kMaxViewerPoints) + " pieces; got " +
                                           std::to_string(flat.size()) + " numbers");
        cagd::exports::CurveDocument d;
        d.provenance.method = name;
        d.provenance.parameter = "uniform (span index)";
        d.provenance.closed = closed;
        d.provenance.points = points;
        d.form.exact = true;
        d.form.pieces.degree = 3;
        d.form.pieces.control.resize(static_cast<Eigen::Index>(4 * pieces), 2);
        for (Eigen::Index i = 0; i < d.form.pieces.control.rows(); ++i)
            d.form.pieces.control.row(i) << flat[static_cast<std::size_t>(2 * i)],
                flat[static_cast<std::size_t>(2 * i + 1)];
        for (std::size_t k = 0; k <= pieces; ++k) d.form.pieces.breaks.push_back(static_cast<double>(k));
        answer.curve = std::move(d);
    }
    return cagd::compare::peer_drawn_curve(answer, name.substr(0, colon), points, closed);
}

val parameter_json(const cagd::methods::Parameter& p) {
    val out = val::object();
    out.set("name", p.name);
    out.set("type", std::string(cagd::methods::to_string(p.type)));
    out.set("default", p.default_text);
    out.set("lower", p.lower);
    out.set("upper", p.upper);
    out.set("choices", js_array(p.choices));
    out.set("help", p.help);
    out.set("spaceOnly", p.space_only);
    return out;
}

val claims_json(const cagd::methods::MethodClaims& c) {
    val out = val::object();
    out.set("parametricContinuity", c.parametric_continuity);
    out.set("geometricContinuity", c.geometric_continuity);
    out.set("parameter", c.parameter);
    out.set("invariance", std::string(cagd::methods::to_string(c.invariance)));
    out.set("supportsClosed", c.supports_closed);
    out.set("minPoints", c.min_points);
    out.set("minPointsClosed", c.min_points_closed);
    out.set("maxPoints", c.max_points);
    out.set("alwaysSolves", c.always_solves);
    return out;
}

val text_json(const cagd::methods::ParameterText& t) {
    val out = val::object();
    for (const auto& [k, v] : t) out.set(k, v);
    return out;
}

val registry() {
    val methods = val::array();
    for (const cagd::methods::Method& m : cagd::methods::registry()) {
        val o = val::object();
        o.set("name", m.name);
        o.set("paper", m.paper);
        o.set("source", m.source);
        o.set("summary", m.summary);
        val parameters = val::array();
        for (const auto& p : m.parameters) parameters.call<void>("push", parameter_json(p));
        o.set("parameters", parameters);
        methods.call<void>("push", o);
    }
    val configurations = val::array();
    for (const cagd::methods::Configuration& c : cagd::methods::configurations()) {
        val o = val::object();
        o.set("name", c.name);
        o.set("method", c.method->name);
        o.set("values", text_json(c.values.as_text()));
        o.set("claims", claims_json(c.claims));
        configurations.call<void>("push", o);
    }
    val formats = val::array();
    for (const auto& f : cagd::exports::curve_formats())
        if (f.format != cagd::exports::CurveFormat::step) formats.call<void>("push", std::string(f.name));
    val out = val::object();
    out.set("methods", methods);
    out.set("configurations", configurations);
    out.set("formats", formats);
    out.set("libraryVersion", std::string(cagd::library_version()));
    return out;
}

// The curves kept at the start of a drag, by configuration name, as the positions the motion of
// each frame compares (compare::span_samples): sampled once, not again in every frame.
constexpr int kMotionSamples = 8;
std::map<std::string, Eigen::MatrixXd>& anchors() {
    static std::map<std::string, Eigen::MatrixXd> a;
    return a;
}

// The solver states of the last comparison, by configuration name, with its number of points and
// closedness: the starts of the next drag frame's iterative solves (continuation).
struct SolverStates {
    long points = -1;
    bool closed = false;
    std::map<std::string, Eigen::VectorXd> by_configuration;
};
SolverStates& last_solver_states() {
    static SolverStates s;
    return s;
}

val compare(const val& request) {
    try {
        const cagd::PointList points = points_of(request);
        cagd::compare::ComparisonOptions options;
        options.closed = flag(request, "closed");
        options.locality = false;
        options.measures = flag(request, "measures");
        options.threads = 1;
        const val list = request["configurations"], peers = request["peers"];
        const int count = list.isUndefined() ? 0 : list["length"].as<int>();
        const int peer_count = peers.isUndefined() ? 0 : peers["length"].as<int>();
        if (count + peer_count == 0) return failure("viewer: no configuration chosen");
        for (int i = 0; i < count; ++i)
            options.configurations.push_back(cagd::methods::find_configuration(
                val::global("String")(list[i]["name"]).as<std::string>(), parameters_of(list[i]["parameters"])));
        for (int i = 0; i < peer_count; ++i) {
            std::string name;
            const cagd::compare::DrawnCurve drawn = peer_curve_of(peers[i], points, options.closed, name);
            options.peers.push_back(cagd::compare::drawn_subject(name, {drawn}));
        }
        const int per_span = request["perSpan"].isUndefined() ? 16 : request["perSpan"].as<int>();
        if (per_span < 1 || per_span > kMaxPerSpan)
            return failure("viewer: perSpan = " + std::to_string(per_span) + "; allowed 1.." +
                           std::to_string(kMaxPerSpan));
        // A drag frame (continuation) starts the iterative methods from the last frame's solutions:
        // fewer Newton iterations, the same solution branch. Other frames (the drag's end, a new
        // state, a link) solve anew, as the native library does.
        SolverStates& states = last_solver_states();
        if (flag(request, "continuation") && states.points == points.rows() && states.closed == options.closed)
            options.starts = states.by_configuration;
        const auto start = std::chrono::steady_clock::now();
        const std::vector<cagd::compare::MethodComparison> rows = cagd::compare::compare_methods(points, options);
        states = {points.rows(), options.closed, {}};
        for (const auto& r : rows)
            if (r.solver_state.size() > 0) states.by_configuration.emplace(r.method, r.solver_state);
        const auto compared = std::chrono::steady_clock::now();
        const bool with_figure = request["figure"].isUndefined() || request["figure"].as<bool>();
        const cagd::compare::FigureData figure =
            with_figure ? cagd::compare::comparison_figure_data(
                              rows, points,
                              {.per_span = per_span,
                               .span_stride = 1,
                               .arc_length = cagd::compare::FigureSampling::ArcLength::trapezoid})
                        : cagd::compare::FigureData{};
        const auto drawn = std::chrono::steady_clock::now();
        const double diagonal = cagd::bounding_box_diagonal(points);
        if (flag(request, "anchor")) {
            anchors().clear();
            for (const auto& r : rows)
                if (r.interpolant)
                    anchors().emplace(r.method, cagd::compare::span_samples(*r.interpolant, kMotionSamples));
        }
        const bool motion = flag(request, "motion");
        // The figure data's rows, split by method index (column 0).
        std::vector<std::vector<double>> curves(rows.size()), profiles(rows.size()), combs(rows.size());
        for (const auto& r : figure.curves)
            curves[static_cast<std::size_t>(r[0])].insert(curves[static_cast<std::size_t>(r[0])].end(), r.begin() + 1,
                                                          r.end());
        for (const auto& r : figure.profiles)
            profiles[static_cast<std::size_t>(r[0])].insert(profiles[static_cast<std::size_t>(r[0])].end(),
                                                            r.begin() + 1, r.end());
        for (const auto& r : figure.combs)
            combs[static_cast<std::size_t>(r[0])].insert(combs[static_cast<std::size_t>(r[0])].end(), r.begin() + 1,
                                                         r.end());
        val results = val::array();
        double comb_scale = 0.0;
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const auto& r = rows[i];
            val o = val::object();
            o.set("name", r.method);
            o.set("status", std::string(cagd::compare::to_string(r.status)));
            o.set("note", r.note);
            o.set("seconds", r.seconds);
            o.set("spans", r.spans);
            o.set("curve", float64_array(curves[i]));
            o.set("profile", float64_array(profiles[i]));
            o.set("comb", float64_array(combs[i]));
            if (with_figure && figure.comb_scale[i] > 0) comb_scale = figure.comb_scale[i];
            if (motion && r.interpolant) {
                const auto a = anchors().find(r.method);
                const Eigen::Index sample_rows =
                    static_cast<Eigen::Index>(r.interpolant->node_parameters.size() - 1) * (kMotionSamples + 1);
                if (a != anchors().end() && a->second.rows() == sample_rows) {
                    std::vector<double> moved = cagd::compare::span_displacements(
                        a->second, cagd::compare::span_samples(*r.interpolant, kMotionSamples), kMotionSamples);
                    for (double& d : moved) d /= diagonal;
                    o.set("motion", float64_array(moved));
                }
            }
            results.call<void>("push", o);
        }
        val out = val::object();
        if (options.measures) {
            val table = val::array();
            for (const auto& row : cagd::compare::comparison_rows(rows, options.closed, false, 6))
                table.call<void>("push", js_array(row));
            out.set("header", js_array(cagd::compare::comparison_header(options.closed, false)));
            out.set("rows", table);
        }
        out.set("ok", true);
        out.set("diagonal", diagonal);
        out.set("combScale", comb_scale);
        out.set("results", results);
        out.set("compareSeconds", std::chrono::duration<double>(compared - start).count());
        out.set("figureSeconds", std::chrono::duration<double>(drawn - compared).count());
        return out;
    } catch (const std::exception& e) {
        return failure(cagd::in_user_terms(cagd::one_line(e.what())));
    }
}

val export_curve(const val& request) {
    try {
        const cagd::PointList points = points_of(request);
        const bool closed = flag(request, "closed");
        const cagd::exports::CurveFormat format =
            cagd::exports::curve_format_named(val::global("String")(request["format"]).as<std::string>());
        // As `cagd interpolate` writes it: the curve in the method's own parameter, with its provenance
        // (a peer's: in its pieces' parameter, as `cagd compare --peers` writes it).
        std::optional<cagd::methods::Interpolant> interpolant;
        cagd::exports::CurveProvenance provenance;
        if (!request["pieces"].isUndefined()) {
            std::string name;
            cagd::compare::DrawnCurve drawn = peer_curve_of(request, points, closed, name);
            if (!drawn.interpolant) return failure(name + ": " + cagd::one_line(drawn.note));
            interpolant = std::move(drawn.interpolant);
            provenance = *drawn.provenance;
        } else {
            const cagd::methods::Configuration c = cagd::methods::find_configuration(
                val::global("String")(request["name"]).as<std::string>(), parameters_of(request["parameters"]));
            cagd::methods::InterpolationResult r = cagd::methods::interpolate(c, points, closed);
            if (!r.outcome.ok() || !r.interpolant) return failure(c.name + ": " + cagd::one_line(r.outcome.message));
            interpolant = std::move(r.interpolant);
            provenance = cagd::methods::method_provenance(*c.method, c.values, points, closed);
        }
        const cagd::methods::MethodParameterCurve curve(*interpolant);
        cagd::exports::ExportOptions options;
        options.points = true;
        options.comb = flag(request, "comb");
        if (!request["samples"].isUndefined()) options.samples.per_piece = request["samples"].as<int>();
        std::ostringstream text;
        if (const cagd::Outcome written = cagd::exports::write_curve(text, format, curve, provenance, options);
            !written.ok())
            return failure(cagd::one_line(written.message));
        val out = val::object();
        out.set("ok", true);
        out.set("text", text.str());
        return out;
    } catch (const std::exception& e) {
        return failure(cagd::in_user_terms(cagd::one_line(e.what())));
    }
}

val read_points(const std::string& text, const std::string& source) {
    try {
        std::istringstream in(text);
        const cagd::PointList p = cagd::read_points_csv(in, source);
        if (p.cols() != 2)
            return failure(source + ": the viewer is planar: needs 2 columns (x, y), got " + std::to_string(p.cols()));
        if (p.rows() > kMaxViewerPoints)
            return failure(source + ": " + std::to_string(p.rows()) + " points; the viewer takes at most " +
                           std::to_string(kMaxViewerPoints));
        val points = val::array();
        for (Eigen::Index i = 0; i < p.rows(); ++i) {
            val row = val::array();
            row.call<void>("push", p(i, 0));
            row.call<void>("push", p(i, 1));
            points.call<void>("push", row);
        }
        val out = val::object();
        out.set("ok", true);
        out.set("points", points);
        return out;
    } catch (const std::exception& e) {
        return failure(cagd::in_user_terms(cagd::one_line(e.what())));
    }
}

}  // namespace

EMSCRIPTEN_BINDINGS(cagd_viewer) {
    emscripten::function("registry", &registry);
    emscripten::function("compare", &compare);
    emscripten::function("exportCurve", &export_curve);
    emscripten::function("readPoints", &read_points);
}
