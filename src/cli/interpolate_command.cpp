// `cagd interpolate --method M [method options] [--closed] [--samples N] [--parameter method|span] --in P.csv --out
// C.{csv,json,svg,dxf,step}`: any registered method (methods/method_registry.hpp) on the user's points;
// `--list-methods` describes them. Writes the curve in the format of --format or of the output's extension
// (export/curve_formats.hpp: one writer per format, an unknown extension is bad input; `-` for stdout). What the method
// reports (the curvature-profile Newton history) goes to the file --report names, or to stderr
// unless --quiet: never onto standard output beside data. Exit 1 with the outcome, and no output,
// when no curve exists.
#include <iostream>
#include <memory>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/export/curve_formats.hpp"
#include "cagd/methods/curve_provenance.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"
#include "cli/commands.hpp"
#include "cli/method_options.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

struct InterpolateArgs {
    std::string method = "s-spline", in, out, report, parameter = "method", format;
    MethodOptions options;
    bool closed = false, list = false, markdown = false, show_points = false, comb = false;
    int samples = 16, arc_length_samples = 0, approximation_degree = 3;
    double tolerance = 1e-6;
};

int run_interpolate(const InterpolateArgs& a) {
    const char* who = "cagd interpolate";
    if (a.list) {
        print_standard_output(a.markdown ? methods::registry_markdown() : methods::registry_listing());
        return 0;
    }
    if (a.in.empty() || a.out.empty()) fail_input(who, "--in and --out are required (or --list-methods)");
    const methods::Method& method = methods::find_method(a.method);
    const methods::ParameterValues values =
        methods::parse_parameter_values(method.name, method.parameters, given_parameters(a.options));
    const PointList points = read_user_points(a.in, a.closed);
    // The format, from --format or the extension, before any work (an unknown one is bad input).
    const exports::CurveFormat format =
        a.format.empty() ? exports::curve_format_of_path(a.out) : exports::curve_format_named(a.format);
    OutputFile out(a.out);  // checked before the work
    std::unique_ptr<OutputFile> report;
    if (!a.report.empty()) report = std::make_unique<OutputFile>(a.report, "--report");
    const methods::InterpolationResult r = methods::interpolate(method, points, a.closed, values);
    if (!r.outcome.ok() || !r.interpolant) throw NoResult(r.outcome.message);
    // The method's own parameter (t: chord length, arc length, … as the registry states), or the span index u.
    const methods::MethodParameterCurve in_method_parameter(*r.interpolant);
    const Curve& curve = a.parameter == "span" ? static_cast<const Curve&>(*r.interpolant->curve) : in_method_parameter;
    exports::CurveProvenance provenance = methods::method_provenance(method, values, points, a.closed);
    if (a.parameter == "span") provenance.parameter = "span index u";
    exports::ExportOptions options;
    options.approximation.relative_tolerance = a.tolerance;
    options.approximation.degree = a.approximation_degree;
    options.samples = {.per_piece = a.samples,
                       .arc_length_samples = a.arc_length_samples,
                       .parameter_column = a.parameter == "span" ? "u" : "t",
                       .max_rows = kMaxOutputRows};
    options.points = a.show_points;
    options.comb = a.comb;
    if (const Outcome written = exports::write_curve(out.stream(), format, curve, provenance, options); !written.ok())
        throw NoResult(written.message);
    // What the method reports (the Newton history): "quantity,value" lines, into --report's file,
    // or on stderr unless --quiet.
    std::string text;
    if (!r.report.empty()) {
        text = "quantity,value\n";
        for (const auto& [name, value] : r.report) text += csv_field(name) + ',' + csv_field(value) + '\n';
    }
    if (report) report->stream() << text;
    out.commit();
    if (report)
        report->commit();
    else if (!text.empty() && !quiet())
        std::cerr << text;
    return 0;
}

}  // namespace

Command add_interpolate_command(CLI::App& app) {
    auto a = std::make_shared<InterpolateArgs>();
    CLI::App* c = app.add_subcommand(
        "interpolate",
        "Interpolate points with any registered method (--list-methods): a curve CSV of samples with derivatives");
    add_method_options(c, a->method, a->options);
    c->add_flag("--list-methods", a->list,
                "describe every method: paper, equations, claims, parameters with defaults and ranges");
    c->add_flag("--markdown", a->markdown, "with --list-methods: the Markdown table of docs/methods.md");
    c->add_flag("--closed", a->closed, "closed curve");
    c->add_option("--samples", a->samples, "samples per curve piece in the output (samples x pieces <= 10^7 rows)")
        ->check(CLI::Range(1, 100000));
    c->add_option("--in", a->in, "points CSV: x,y[,z] per line, optional header of names; - for stdin");
    c->add_option("--out", a->out,
                  "the curve, in the format of its extension: .csv samples (t, position, 1st and 2nd derivative), "
                  ".json exact pieces, .svg cubic path, .dxf SPLINE, "
                  ".step/.stp B-spline; - for stdout (CSV unless --format)");
    c->add_option("--format", a->format, "output format, whatever the extension: csv | json | svg | dxf | step")
        ->check(CLI::IsMember({"csv", "json", "svg", "dxf", "step"}));
    c->add_option("--tolerance", a->tolerance,
                  "curves not exact in the format (transcendental; degree > 3 in SVG): largest distance of the "
                  "approximation, relative to the bounding-box diagonal")
        ->check(CLI::Range(1e-14, 0.1))
        ->capture_default_str();
    c->add_option(
         "--approximation-degree", a->approximation_degree,
         "degree of the approximating pieces in JSON, DXF and STEP: 3 (C1) or 5 (C2, curvature exact at the joins)")
        ->check(CLI::IsMember({3, 5}))
        ->capture_default_str();
    c->add_option("--arc-length-samples", a->arc_length_samples,
                  "CSV: N samples at equal arc length instead of --samples per piece (N >= 2)")
        ->check(CLI::Range(2, 10000000));
    c->add_flag("--show-points", a->show_points, "SVG and DXF: draw the input points too");
    c->add_flag("--comb", a->comb, "SVG: draw the curvature comb (its scale is written in the file)");
    c->add_option("--parameter", a->parameter,
                  "method: t is the method's own parameter (chord length, arc length or uniform, as --list-methods "
                  "states); span: u, the span index "
                  "(u = k at point k)")
        ->check(CLI::IsMember({"method", "span"}))
        ->capture_default_str();
    c->add_option("--report", a->report,
                  "file for what the method reports (the curvature-profile Newton history, as quantity,value lines); "
                  "default: stderr unless --quiet");
    return {c, [a] { return run_interpolate(*a); }};
}

}  // namespace cagd::cli
