// `cagd monotone --in CONTROL.csv [--knots endpoint|uniform]`: per-segment curvature monotonicity
// of a planar cubic B-spline (typical_curves section 3.4, condition 29–30, appendix A).
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>
#include <sstream>

#include "cagd/aesthetic/cubic_bspline_monotonicity.hpp"
#include "cagd/analysis/curvature_monotonicity.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

enum class MonotoneKnots { endpoint, uniform };

struct MonotoneArgs {
    std::string in;
    MonotoneKnots knots = MonotoneKnots::endpoint;
};

int run_monotone(const MonotoneArgs& a) {
    const PointList p = read_data_points(a.in);
    if (p.cols() != 2)
        fail_input("cagd monotone",
                   "control points must be planar (x,y), got " + std::to_string(p.cols()) + " columns");
    const BSplineCurve curve = a.knots == MonotoneKnots::uniform ? aesthetic::uniform_cubic_bspline(p)
                                                                 : aesthetic::endpoint_interpolating_cubic_bspline(p);
    const aesthetic::MonotonicityReport r = aesthetic::cubic_bspline_curvature_monotonicity(curve);
    std::ostringstream table;  // printed after success only
    table << "segment,turn0_deg,turn1_deg,equal_edges,condition29,bernstein,exact_trend\n";
    for (const aesthetic::SegmentVerdict& v : r.segments)
        table << v.segment << ',' << finite_field(v.turn0 * 180 / std::numbers::pi, 8, "turn0") << ','
              << finite_field(v.turn1 * 180 / std::numbers::pi, 8, "turn1") << ',' << (v.equal_edges ? "yes" : "no")
              << ',' << aesthetic::to_string(v.condition29_verdict) << ',' << aesthetic::to_string(v.bernstein_verdict)
              << ',' << analysis::to_string(v.exact) << '\n';
    table << "whole_curve," << analysis::to_string(r.whole_curve) << '\n';
    print_standard_output(table.str());
    return 0;
}

}  // namespace

Command add_monotone_command(CLI::App& app) {
    auto a = std::make_shared<MonotoneArgs>();
    auto* c = app.add_subcommand(
        "monotone",
        "Per-segment curvature monotonicity of a planar cubic B-spline (typical_curves section 3.4, appendix A)");
    c->add_option("--in", a->in, "control points CSV: x,y per line; - for stdin")->required();
    add_enum_option(c, "--knots", a->knots,
                    {{"endpoint", MonotoneKnots::endpoint}, {"uniform", MonotoneKnots::uniform}},
                    "endpoint (endpoint-interpolating) | uniform");
    return {c, [a] { return run_monotone(*a); }};
}

}  // namespace cagd::cli
