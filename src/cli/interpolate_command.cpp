// `cagd interpolate --method M [method options] [--closed] [--samples N] [--parameter method|span] --in P.csv --out C.csv`:
// any registered method (methods/method_registry.hpp) on the user's points; `--list-methods`
// describes them. Writes the curve CSV (cli/curve_output.hpp; `-` for stdout). What the method
// reports (the curvature-profile Newton history) goes to the file --report names, or to stderr
// unless --quiet: never onto standard output beside data. Exit 1 with the outcome, and no output,
// when no curve exists.
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/curve_output.hpp"
#include "cli/method_options.hpp"
#include "cli/output.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::cli {

namespace {

struct InterpolateArgs {
    std::string method = "s-spline", in, out, report, parameter = "method";
    MethodOptions options;
    bool closed = false, list = false, markdown = false;
    int samples = 16;
};

int run_interpolate(const InterpolateArgs& a) {
    const char* who = "cagd interpolate";
    if (a.list) {
        print_standard_output(a.markdown ? methods::registry_markdown() : methods::registry_listing());
        return 0;
    }
    if (a.in.empty() || a.out.empty()) fail_input(who, "--in and --out are required (or --list-methods)");
    const methods::Method& method = methods::find_method(a.method);
    const methods::ParameterValues values = methods::parse_parameter_values(method.name, method.parameters, given_parameters(a.options));
    const PointList points = read_points_csv(a.in);
    OutputFile out(a.out);  // checked before the work
    std::unique_ptr<OutputFile> report;
    if (!a.report.empty()) report = std::make_unique<OutputFile>(a.report, "--report");
    const methods::InterpolationResult r = methods::interpolate(method, points, a.closed, values);
    if (!r.outcome.ok() || !r.interpolant) throw NoResult(r.outcome.message);
    // The method's own parameter (t: chord length, arc length, … as the registry states), or the span index u.
    if (a.parameter == "span")
        write_curve(*r.interpolant->curve, a.samples, out, "u");
    else
        write_curve(methods::MethodParameterCurve(*r.interpolant), a.samples, out, "t");
    // What the method reports (the Newton history): "quantity,value" lines, into --report's file,
    // or on stderr unless --quiet.
    std::string text;
    if (!r.report.empty()) {
        text = "quantity,value\n";
        for (const auto& [name, value] : r.report) text += csv_field(name) + ',' + csv_field(value) + '\n';
    }
    if (report) report->stream() << text;
    out.commit();
    if (report) report->commit();
    else if (!text.empty() && !quiet()) std::cerr << text;
    return 0;
}

}  // namespace

Command add_interpolate_command(CLI::App& app) {
    auto a = std::make_shared<InterpolateArgs>();
    CLI::App* c = app.add_subcommand("interpolate", "Interpolate points with any registered method (--list-methods): a curve CSV of samples with derivatives");
    add_method_options(c, a->method, a->options);
    c->add_flag("--list-methods", a->list, "describe every method: paper, equations, claims, parameters with defaults and ranges");
    c->add_flag("--markdown", a->markdown, "with --list-methods: the Markdown table of docs/methods.md");
    c->add_flag("--closed", a->closed, "closed curve");
    c->add_option("--samples", a->samples, "samples per curve piece in the output (samples x pieces <= 10^7 rows)")->check(CLI::Range(1, 100000));
    c->add_option("--in", a->in, "points CSV: x,y[,z] per line, optional header of names; - for stdin");
    c->add_option("--out", a->out, "curve CSV: t, position, 1st and 2nd derivative with respect to t; - for stdout");
    c->add_option("--parameter", a->parameter,
                  "method: t is the method's own parameter (chord length, arc length or uniform, as --list-methods states); span: u, the span index "
                  "(u = k at point k)")
        ->check(CLI::IsMember({"method", "span"}))
        ->capture_default_str();
    c->add_option("--report", a->report, "file for what the method reports (the curvature-profile Newton history, as quantity,value lines); default: stderr unless --quiet");
    return {c, [a] { return run_interpolate(*a); }};
}

}  // namespace cagd::cli
