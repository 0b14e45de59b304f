// `cagd analyze CURVE.csv`: sampled measures of a curve CSV (analysis/sampled_curve_measures.hpp).
// `cagd analyze --in P.csv --method M [method options] [--closed]`: the curve of any registered
// method through the points, integrated: the arc length by adaptive Gauss–Kronrod to rel 1e-12 with
// its error estimate (analysis::accurate_arc_length), the exact polynomial area
// (closed by the chord from the last point to the first), and what the method computes itself
// (the pseudo-spline's length, area and pseudo-energy from its tables, eq 16–21).
// `cagd analyze --in curve.json`: a curve document (export/curve_json.hpp) measured the same way.
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/analysis/sampled_curve_measures.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/export/bspline_form.hpp"
#include "cagd/export/curve_formats.hpp"
#include "cagd/export/curve_json.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"
#include "cli/commands.hpp"
#include "cli/method_options.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

struct AnalyzeArgs {
    std::string curve, in, method;
    MethodOptions options;
    bool closed = false;
};

int analyze_samples(const std::string& path) {
    const NumericTable t = read_numeric_table(path);
    const int x = t.column("x"), y = t.column("y"), z = t.column("z");
    if (x < 0 || y < 0) fail_input("cagd analyze", path + ": needs columns x and y (as written by cagd interpolate)");
    const std::vector<int> position = z >= 0 ? std::vector<int>{x, y, z} : std::vector<int>{x, y};
    const auto columns = [&](const char* prefix) {
        std::vector<int> c;
        for (const char* n : {"x", "y", "z"})
            if (c.size() < position.size()) c.push_back(t.column(std::string(prefix) + n));
        return c;
    };
    const auto matrix = [&](const std::vector<int>& cols) {
        Eigen::MatrixXd m(static_cast<Eigen::Index>(t.rows.size()), static_cast<Eigen::Index>(cols.size()));
        for (std::size_t i = 0; i < t.rows.size(); ++i)
            for (std::size_t k = 0; k < cols.size(); ++k)
                m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) =
                    t.rows[i][static_cast<std::size_t>(cols[k])];
        return m;
    };
    analysis::CurveSamples s;
    s.position = matrix(position);
    const std::vector<int> d1 = columns("d"), d2 = columns("dd");
    const auto present = [](const std::vector<int>& c) {
        for (int i : c)
            if (i < 0) return false;
        return true;
    };
    if (present(d1) && present(d2)) {
        s.first = matrix(d1);
        s.second = matrix(d2);
    }
    // The parameter column: t (the method's own, cagd interpolate's default) or u (--parameter span).
    // Where the extremes are is named as the file names it: at_t, at_u, or at_sample (0-based index).
    const std::string parameter = t.column("t") >= 0 ? "t" : t.column("u") >= 0 ? "u" : "sample";
    if (parameter != "sample")
        for (const auto& r : t.rows) s.parameter.push_back(r[static_cast<std::size_t>(t.column(parameter))]);
    const analysis::SampledCurveMeasures m = analysis::sampled_curve_measures(s);
    Quantities q;
    q.add("samples", m.samples);
    q.add("polyline_length", m.polyline_length);
    if (m.enclosed_area) q.add("enclosed_area", *m.enclosed_area);
    if (m.has_curvature) {
        q.add("curvature_min", m.curvature_min);
        q.add("curvature_min_at_" + parameter, m.curvature_min_at);
        q.add("curvature_max", m.curvature_max);
        q.add("curvature_max_at_" + parameter, m.curvature_max_at);
        q.add("bending_energy", m.bending_energy);
    }
    q.commit();
    std::cerr << "cagd analyze: sample-based (polyline length, trapezoid energy); accuracy grows with the samples of "
                 "cagd interpolate --samples\n";
    return 0;
}

// The integrated measures of a curve (see the file comment).
void add_curve_measures(Quantities& q, const Curve& c) {
    const analysis::ArcLength length = analysis::accurate_arc_length(c);
    q.add("length_integrated", length.value);
    q.add("length_error_estimate", length.error_estimate, 3);
    if (c.dimension() == 2) q.add("area_integrated", analysis::area_closed_by_chord(c));
    const analysis::CurvatureTorsionExtremes e = analysis::curvature_torsion_extremes(c);
    q.add("max_abs_curvature_sampled", e.max_abs_curvature);
    if (c.dimension() == 3) q.add("max_abs_torsion_sampled", e.max_abs_torsion);
}

// A curve document (export/curve_json.hpp): its pieces measured, and, when it names its method and
// points, the curve rebuilt and its distance from the document's pieces at the same parameters.
int analyze_document(const std::string& path) {
    const exports::CurveDocument d = exports::read_curve_json_file(path);
    const BSplineCurve c = exports::bezier_pieces_curve(d.form.pieces);
    Quantities q;
    q.add("pieces", d.form.pieces.pieces());
    q.add("degree", d.form.pieces.degree);
    q.add("exact", d.form.exact ? 1.0 : 0.0);
    q.add("max_distance_stated", d.form.max_distance, 3);
    add_curve_measures(q, c);
    if (!d.provenance.method.empty() && d.provenance.points.rows() > 0) {
        const methods::InterpolationResult r = methods::interpolate(d.provenance.method, d.provenance.points,
                                                                    d.provenance.closed, d.provenance.parameters);
        if (!r.outcome.ok() || !r.interpolant)
            throw NoResult("rebuilding " + d.provenance.method + ": " + r.outcome.message);
        const methods::MethodParameterCurve rebuilt(*r.interpolant);
        if (std::abs(rebuilt.t_max() - c.t_max()) > 1e-9 * std::max(1.0, std::abs(c.t_max())) ||
            rebuilt.dimension() != c.dimension())
            throw NoResult(path + ": the rebuilt " + d.provenance.method +
                           " curve has another parameter range or dimension than the document's pieces");
        q.add("rebuilt_max_distance", analysis::max_distance_same_parameter(rebuilt, c, 16), 3);
    }
    q.commit();
    std::cerr << "cagd analyze: " << path << ": the document's " << (d.form.exact ? "exact" : "approximating")
              << " pieces, measured by quadrature"
              << (d.provenance.method.empty() ? ""
                                              : "; rebuilt_max_distance compares them with " + d.provenance.method +
                                                    " rebuilt from the document's points")
              << '\n';
    return 0;
}

int analyze_method(const AnalyzeArgs& a) {
    if (exports::curve_format_of_path(a.in) == exports::CurveFormat::json) {
        if (!a.method.empty())
            fail_input("cagd analyze", "--in " + a.in + " is a curve document; it names its method (drop --method)");
        return analyze_document(a.in);
    }
    if (a.method.empty()) fail_input("cagd analyze", "--in needs --method (cagd interpolate --list-methods)");
    const methods::Method& method = methods::find_method(a.method);
    const methods::ParameterValues values =
        methods::parse_parameter_values(method.name, method.parameters, given_parameters(a.options));
    const PointList points = read_user_points(a.in, a.closed);
    const methods::InterpolationResult r = methods::interpolate(method, points, a.closed, values);
    if (!r.outcome.ok() || !r.interpolant) throw NoResult(r.outcome.message);
    const Curve& c = *r.interpolant->curve;
    Quantities q;
    q.add("spans", static_cast<double>(r.interpolant->node_parameters.size() - 1));
    add_curve_measures(q, c);
    for (const auto& [name, value] : r.quantities) q.add(name, value);
    // A closed planar curve: its turning number beside its polygon's, and a flag when it loops.
    std::string anomaly;
    if (a.closed && c.dimension() == 2) {
        q.add("turning_number", static_cast<double>(std::lround(analysis::tangent_turns(c))));
        q.add("polygon_turning_number", static_cast<double>(analysis::polygon_turning_number(points)));
        anomaly = analysis::closed_curve_anomaly(c, points, analysis::accurate_arc_length(c).value);
    }
    q.commit();
    if (!anomaly.empty())
        std::cerr << "cagd analyze: flagged: the closed curve loops where its points do not: " << anomaly << "\n";
    if (c.dimension() == 2)
        std::cerr << "cagd analyze: areas are signed (counter-clockwise positive); an open curve is closed by the line "
                     "from its last point to its first\n";
    return 0;
}

}  // namespace

Command add_analyze_command(CLI::App& app) {
    auto a = std::make_shared<AnalyzeArgs>();
    CLI::App* c = app.add_subcommand("analyze",
                                     "Length, enclosed area, curvature extrema and bending energy of a curve CSV, or "
                                     "of a method's curve through points");
    CLI::Option* curve = c->add_option("curve", a->curve,
                                       "curve CSV as written by cagd interpolate (sample-based measures); - for stdin");
    CLI::Option* in = c->add_option(
        "--in", a->in,
        "points CSV: build the curve with --method and integrate it; - for stdin; or a curve document (.json, cagd "
        "interpolate --out c.json): its pieces integrated, and compared with its method rebuilt");
    add_method_options(c, a->method, a->options);
    c->add_flag("--closed", a->closed, "closed curve (with --in)");
    curve->excludes(in);
    return {c, [a] {
                if (!a->in.empty()) return analyze_method(*a);
                if (a->curve.empty()) fail_input("cagd analyze", "give a curve CSV or --in POINTS [--method M]");
                return analyze_samples(a->curve);
            }};
}

}  // namespace cagd::cli
