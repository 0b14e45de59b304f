// `cagd compare --in P.csv [--closed] [--methods a,b,…] [--peers DIR [--programs DIR]] [--no-plot]
// --out DIR`: every configuration of the method registry on the user's points
// (compare/method_comparison), planar or in space; with --peers also every installed peer's
// configuration (peers/peers.csv, run by its adapter through peers/run), rows "peer:configuration"
// after the registry's; a peer not installed is skipped and named on stderr.
// Writes DIR/measures.csv and DIR/measures.md (one row per method), the figure data
// DIR/{points,curves,curvature,combs,methods}.csv, DIR/compare_panels.gp, and with gnuplot on the
// PATH the figures DIR/{curves,combs,curvature}.png (space points: DIR/{curves,curvature,torsion}.png,
// the curvature file holding τ too and combs.csv only its header). DIR is one output
// (io/output_file.hpp, OutputDirectory): checked before the work, every file (figures included)
// made in a staging directory beside it and published together, or not at all.
// Prints the Markdown table on stdout and one progress line per method on stderr.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cagd/compare/comparison_figure.hpp"
#include "cagd/compare/comparison_tables.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/export/curve_formats.hpp"
#include "cagd/methods/curve_provenance.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cli/benchmark_options.hpp"
#include "cli/commands.hpp"
#include "cli/compare_panels_script.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

struct CompareArgs {
    std::string in, out, methods, export_formats, peers, programs;
    bool closed = false, no_plot = false;
};

// A gnuplot string literal in single quotes ('' is a quote inside).
std::string gnuplot_quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
    return q + "'";
}

// A shell word in single quotes.
std::string shell_quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

int run_compare(const CompareArgs& a) {
    const char* who = "cagd compare";
    const PointList points = read_user_points(a.in, a.closed);
    compare::ComparisonOptions options;
    options.closed = a.closed;
    // --methods: registry names, and peers' "peer:configuration" (with --peers); none: all of both.
    std::vector<std::string> peer_names;
    for (const std::string& m : a.methods.empty() ? std::vector<std::string>{} : split_csv_line(a.methods)) {
        if (m.find(':') == std::string::npos)
            options.methods.push_back(methods::find_configuration(m).name);
        else if (a.peers.empty())
            fail_input("--methods", m + ": a peer's configuration, and no --peers folder was given");
        else
            peer_names.push_back(m);
    }
    std::vector<std::string> skipped;
    if (!a.peers.empty()) {
        const std::vector<compare::PeerConfiguration> manifest = peer_manifest(a.peers);
        for (const std::string& m : peer_names)
            if (std::none_of(manifest.begin(), manifest.end(), [&](const auto& c) { return c.name() == m; }))
                fail_input("--methods", m + ": no such peer configuration in " + a.peers + "/peers.csv");
        // Named peers only when --methods names some; every peer when --methods is absent.
        if (a.methods.empty() || !peer_names.empty()) {
            compare::InstalledPeers installed = compare::installed_peer_subjects(
                peer_launcher(a.peers, a.programs), manifest, [&](const std::string& n) {
                    return peer_names.empty() || std::find(peer_names.begin(), peer_names.end(), n) != peer_names.end();
                });
            options.peers = std::move(installed.subjects);
            skipped = std::move(installed.skipped);
        }
        // No --methods: the registry's configurations beside the peers.
        if (a.methods.empty()) options.configurations = methods::configurations();
        if (!peer_names.empty() && options.methods.empty() && options.peers.empty())
            throw NoResult("none of the peers named in --methods is installed here: " + skipped.front());
    }
    if (points.cols() != 2 && points.cols() != 3)
        fail_input(who, a.in + ": compares planar or space curves, the points have " + std::to_string(points.cols()) +
                            " columns");
    const int dimension = static_cast<int>(points.cols());
    // --export: the formats of the per-method curve files, checked before the work.
    std::vector<exports::CurveFormat> export_formats;
    {
        std::stringstream ss(a.export_formats);
        std::string f;
        while (std::getline(ss, f, ',')) {
            export_formats.push_back(exports::curve_format_named(f));
            if (dimension == 3 && !exports::curve_format_info(export_formats.back()).space_curves)
                fail_input(who, "--export " + f + ": the format is planar, the points have 3 columns");
        }
    }
    OutputDirectory out(a.out);     // checked before the work
    OutputFile table_out("-", "");  // the Markdown table on standard output, checked too
    const bool progress = progress_enabled();
    for (const std::string& why : skipped) std::cerr << "cagd compare: skipped " << why << "\n";
    if (progress) {
        // As compare_methods chooses: the configurations given, else those named, else (no peers) all.
        const std::size_t registry = !options.configurations.empty() ? options.configurations.size()
                                     : !options.methods.empty()      ? options.methods.size()
                                     : options.peers.empty()         ? methods::configurations().size()
                                                                     : 0;
        std::cerr << "cagd compare: " << points.rows() << " points, " << registry << " methods, "
                  << options.peers.size() << " peers\n";
    }
    options.on_method = [progress](const compare::MethodComparison& r) {
        if (progress)
            std::cerr << "cagd compare: " << r.method << ": " << compare::to_string(r.status)
                      << (r.note.empty() ? "" : " (" + r.note + ")") << ", " << format_number(r.seconds, 3) << " s\n";
    };
    const std::vector<compare::MethodComparison> results = compare::compare_methods(points, options);

    const std::string md = compare::comparison_markdown(results, a.closed, true, 6, dimension);
    {
        OutputFile f(out.staged("measures.md"));
        f.stream() << md;
        f.commit();
    }

    // Figure data: at most about kFigureSamplesPerMethod samples per method whatever the input
    // length (drawing time grows with the samples: 10^5 points at 4·10^4 samples per method took
    // gnuplot 35 s; at 10^4, the three figures of 10^3 points took 3 CPU-s). A panel is a few hundred
    // pixels wide, so 4000 samples still put several on every pixel column.
    constexpr int kFigureSamplesPerMethod = 4000;
    const int spans = static_cast<int>(points.rows()) - (a.closed ? 0 : 1);
    const compare::FigureData fig = compare::comparison_figure_data(
        results, points, compare::figure_sampling(std::max(spans, 1), kFigureSamplesPerMethod));
    // The folder's tables (compare/comparison_tables.hpp) are independent: written in parallel (at
    // 10^5 points, 0.9 s one after another).
    const std::vector<compare::ComparisonTable> tables = compare::comparison_tables(
        results, fig, points, a.closed, {.timing = true, .measure_digits = 8, .figure_digits = 8, .point_digits = 17});
    std::vector<std::string> staged;
    for (const compare::ComparisonTable& t : tables) staged.push_back(out.staged(t.file));
    parallel_for(static_cast<long>(tables.size()), hardware_threads(), [&](long k) {
        const compare::ComparisonTable& t = tables[static_cast<std::size_t>(k)];
        CsvOutput w(staged[static_cast<std::size_t>(k)], t.header);
        for (const auto& row : t.text_rows) w.row_text(row);
        for (const auto& row : t.numbers()) w.row(row, t.significant);
        w.commit();
    });
    // Each method's curve in each --export format, curve_<configuration>.<extension>, in the method's
    // own parameter, with its configuration's parameters and the points (export/curve_formats.hpp).
    for (const compare::MethodComparison& r : results) {
        if (!r.interpolant) continue;
        const methods::MethodParameterCurve curve(*r.interpolant);
        // A peer's curve: its adapter's own provenance, with the points.
        exports::CurveProvenance provenance;
        if (r.provenance) {
            provenance = *r.provenance;
            provenance.points = points;
        } else {
            const methods::Configuration conf = methods::find_configuration(r.method);
            provenance = methods::method_provenance(*conf.method, conf.values, points, a.closed);
        }
        std::string file_name = "curve_" + r.method;  // a peer's "peer:configuration" as curve_peer_configuration
        std::replace(file_name.begin(), file_name.end(), ':', '_');
        exports::ExportOptions export_options;
        export_options.points = true;
        export_options.comb = dimension == 2;
        export_options.stands_within = r.approximation.value_or(0.0);
        for (const exports::CurveFormat format : export_formats) {
            OutputFile f(out.staged(file_name + exports::curve_format_info(format).extensions.front()));
            if (const Outcome written = exports::write_curve(f.stream(), format, curve, provenance, export_options);
                !written.ok())
                throw NoResult(r.method + " as " + exports::curve_format_info(format).name + ": " + written.message +
                               " (nothing was written)");
            f.commit();
        }
    }
    const std::string script = out.staged("compare_panels.gp");
    {
        OutputFile f(script);
        f.stream() << kComparePanelsScript;
        f.commit();
    }
    table_out.stream() << md;
    const bool plot = !a.no_plot && std::system("command -v gnuplot > /dev/null 2>&1") == 0;
    if (!a.no_plot && !plot)
        std::cerr << "cagd compare: gnuplot not found; the figure data and compare_panels.gp are in " << a.out << "\n";
    if (plot) {
        // The three figures are independent: one gnuplot each, as many at a time as there are cores,
        // drawn into the staging directory.
        const std::vector<std::string> figures =
            dimension == 2 ? std::vector<std::string>{"combs", "curvature", "curves"}
                           : std::vector<std::string>{"curvature", "torsion", "curves"};  // the slowest first
        std::vector<std::string> commands;
        for (const std::string& figure : figures) {
            out.staged(figure + ".png");
            const std::string settings =
                "datadir=" + gnuplot_quoted(out.staging()) +
                "; prefix=''; space=" + std::to_string(dimension == 3 ? 1 : 0) +
                "; heading=" + gnuplot_quoted(std::filesystem::path(a.in).filename().string()) +
                "; formats='png'; figures='" + figure + "'; point_every=" +
                std::to_string(std::max<Eigen::Index>(1, points.rows() / 5000)) +  // ≤ ~5000 dots in a figure's panel
                // ≤ ~1000 in each small panel of the combs figure: it draws the points once per method, and
                // cairo's dots were two thirds of that figure's time at 10^5 points (1.1 of 1.6 s)
                "; panel_point_every=" + std::to_string(std::max<Eigen::Index>(1, points.rows() / 1000));
            // gnuplot's messages (its warnings on few points, say) go to a scratch log: read only when
            // gnuplot fails, never published.
            commands.push_back("gnuplot -e " + shell_quoted(settings) + " " + shell_quoted(script) + " 2> " +
                               shell_quoted(out.scratch(figure + ".log")));
        }
        std::vector<int> status(commands.size(), 0);
        parallel_for(static_cast<long>(commands.size()), hardware_threads(),
                     [&](long k) {
                         status[static_cast<std::size_t>(k)] =
                             std::system(commands[static_cast<std::size_t>(k)].c_str());
                     },
                     {});
        for (std::size_t k = 0; k < commands.size(); ++k)
            if (status[k] != 0) {
                std::ifstream log(out.staging() + "/" + figures[k] + ".log");
                std::string line, reason;
                while (reason.empty() && std::getline(log, line))
                    if (line.find_first_not_of(" \t^") != std::string::npos)
                        reason = line.substr(line.find_first_not_of(" \t"));
                throw NoResult("gnuplot failed to draw the " + figures[k] + " figure" +
                               (reason.empty() ? "" : ": " + reason) + " (nothing was written)");
            }
    }
    out.commit();
    table_out.commit();
    if (progress && plot)
        std::cerr << "cagd compare: figures " << a.out
                  << (dimension == 2 ? "/{curves,combs,curvature}.png\n" : "/{curves,curvature,torsion}.png\n");
    return 0;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
    auto a = std::make_shared<CompareArgs>();
    CLI::App* c = app.add_subcommand(
        "compare", "Every interpolation method on the same points: fairness table (CSV, Markdown) and figures");
    c->add_option("--in", a->in, "points CSV: x,y or x,y,z per line, optional header")->required();
    c->add_option("--out", a->out, "output directory (created, or its files replaced, as a whole)")->required();
    c->add_flag("--closed", a->closed,
                "closed curves (methods that draw open curves only are listed as not applicable)");
    c->add_option("--methods", a->methods,
                  "comma-separated presets or methods (a method runs with its defaults), e.g. "
                  "pseudo-spline-exact,cubic-b,hosaka; with --peers also peers' configurations, e.g. gsl:cspline "
                  "(default: every preset, and every installed peer with --peers)");
    c->add_option("--peers", a->peers,
                  "the peers' folder (peers/): every installed peer's configuration is compared too, or those "
                  "named in --methods as peer:configuration (e.g. d3-shape:natural)");
    add_peer_programs_option(c, a->programs);
    c->add_flag("--no-plot", a->no_plot, "write the figure data and script but do not run gnuplot");
    c->add_option("--export", a->export_formats,
                  "also write each method's curve as curve_<method>.<ext> in these comma-separated formats: csv, json, "
                  "svg (planar), dxf, step (e.g. svg,dxf)");
    return {c, [a] { return run_compare(*a); }};
}

}  // namespace cagd::cli
