// `cagd interpolate --method M [method options] [--closed] [--samples N] --in P.csv --out C.csv`:
// any registered method (methods/method_registry.hpp) on the user's points; `--list-methods`
// describes them. Writes the curve CSV (cli/curve_output.hpp; `-` for stdout), then what the method
// reports (the curvature-profile Newton history) on stdout (stderr when the curve goes to stdout);
// exit 1 with the outcome, and no output, when no curve exists.
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/curve_output.hpp"
#include "cli/method_options.hpp"
#include "cli/output.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::cli {

namespace {

struct InterpolateArgs {
    std::string method = "s-spline", in, out;
    MethodOptions options;
    bool closed = false, list = false, markdown = false;
    int samples = 16;
};

int run_interpolate(const InterpolateArgs& a) {
    const char* who = "cagd interpolate";
    if (a.list) {
        std::cout << (a.markdown ? methods::registry_markdown() : methods::registry_listing());
        return 0;
    }
    if (a.in.empty() || a.out.empty()) fail_input(who, "--in and --out are required (or --list-methods)");
    const methods::Method& method = methods::find_method(a.method);
    const methods::ParameterValues values = methods::parse_parameter_values(method.name, method.parameters, given_parameters(a.options));
    const PointList points = read_points_csv(a.in);
    OutputFile out(a.out);  // checked before the work
    const methods::InterpolationResult r = methods::interpolate(method, points, a.closed, values);
    if (!r.outcome.ok() || !r.interpolant) throw NoResult(r.outcome.message);
    write_curve(*r.interpolant->curve, a.samples, out);
    out.commit();
    // What the method reports (the Newton history), after the curve: "quantity,value" lines on
    // stdout, or on stderr when the curve is on stdout.
    if (!r.report.empty()) {
        std::ostream& report = a.out == "-" ? std::cerr : std::cout;
        report << "quantity,value\n";
        for (const auto& [name, value] : r.report) report << csv_field(name) << ',' << csv_field(value) << '\n';
    }
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
    c->add_option("--out", a->out, "curve CSV: u, position, 1st and 2nd derivative; - for stdout");
    return {c, [a] { return run_interpolate(*a); }};
}

}  // namespace cagd::cli
