// `cagd lac3d --alpha A --beta B --degree N [--length L] [--start S0] [--composition C] [--slopes]
// --out C.csv`: the typical Bezier space curve approximating a log-aesthetic space curve, frames
// turned by R_kappa (x) R_tau (typical_curves section 4), with curvature, torsion and slopes.
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>

#include "cagd/aesthetic/space_typical_bezier.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/spline/bezier.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

struct Lac3dArgs {
    double alpha = 0.0, beta = 0.0, length = 1.0, start = 0.1;
    int degree = 0, samples = 200;
    aesthetic::FrenetComposition composition = aesthetic::FrenetComposition::alexa;
    std::string out;
    bool slopes = false;
};

int run_lac3d(const Lac3dArgs& a) {
    if (static_cast<double>(a.degree) * a.samples > kMaxDegreeTimesSamples)
        fail_input("cagd lac3d", "--degree " + std::to_string(a.degree) + " x --samples " + std::to_string(a.samples) +
                                     " exceeds 2e8 evaluations (seconds of work); lower one");
    OutputFile file(a.out);
    const aesthetic::LogAestheticSpaceParameters p =
        aesthetic::normalized_log_aesthetic_space_parameters(a.alpha, a.beta, a.length, a.start);
    const aesthetic::SpaceTypicalPolygon poly = aesthetic::space_typical_polygon(p, a.degree, a.composition);
    const BezierCurve curve(poly.points, 0.0, 1.0,
                            a.degree > 60 ? BezierEvaluation::bernstein : BezierEvaluation::de_casteljau);
    CsvOutput out(file, {"kind", "t", "x", "y", "z", "curvature", "torsion"});
    for (Eigen::Index i = 0; i < poly.points.rows(); ++i)
        out.row_text({"control", std::to_string(i), finite_field(poly.points(i, 0), 15, "control point x"),
                      finite_field(poly.points(i, 1), 15, "control point y"),
                      finite_field(poly.points(i, 2), 15, "control point z"), "", ""});
    for (int k = 0; k < a.samples; ++k) {
        const double t = static_cast<double>(k) / (a.samples - 1);
        const Eigen::VectorXd q = curve.point(t);
        const std::string at = " at t = " + format_number(t);
        out.row_text({"curve", format_number(t, 15), finite_field(q(0), 15, "x" + at), finite_field(q(1), 15, "y" + at),
                      finite_field(q(2), 15, "z" + at),
                      finite_field(analysis::curvature(curve, t), 15, "curvature" + at),
                      finite_field(analysis::torsion(curve, t), 15, "torsion" + at)});
    }
    Quantities slopes;
    if (a.slopes) {
        const analysis::LineFit k = analysis::lcg_slope(curve, 0.0, 1.0, 400),
                                t = analysis::ltg_slope(curve, 0.0, 1.0, 400);
        slopes.add("lcg_slope", k.slope, 8);
        slopes.add("ltg_slope", t.slope, 8);
        slopes.add("lcg_max_residual", k.max_residual, 4);
        slopes.add("ltg_max_residual", t.max_residual, 4);
    }
    out.commit();
    if (a.slopes) slopes.commit();
    return 0;
}

}  // namespace

Command add_lac3d_command(CLI::App& app) {
    auto a = std::make_shared<Lac3dArgs>();
    auto* c = app.add_subcommand("lac3d",
                                 "Typical Bezier space curve approximating a log-aesthetic space curve, frames turned "
                                 "by R_kappa (x) R_tau (typical_curves section 4)");
    c->add_option("--alpha", a->alpha, "LCG slope alpha (not 0 or 1; < 0 or > 1 when --start 0)")->required();
    c->add_option("--beta", a->beta, "LTG slope beta (not 0 or 1; < 0 or > 1 when --start 0)")->required();
    c->add_option("--degree", a->degree,
                  "Bezier degree n >= 3 (torsion needs four control points; degree x samples <= 2e8)")
        ->required()
        ->check(CLI::Range(3, 100000));
    c->add_option("--length", a->length, "arc length L of the target piece (> 0)");
    c->add_option(
        "--start", a->start,
        "the piece starts at sigma = s0 of kappa = |alpha-1| sigma^(-1/alpha), tau = |beta-1| sigma^(-1/beta) (>= 0)");
    add_enum_option(c, "--composition", a->composition,
                    {{"alexa", aesthetic::FrenetComposition::alexa},
                     {"kappa_then_tau", aesthetic::FrenetComposition::kappa_then_tau},
                     {"tau_then_kappa", aesthetic::FrenetComposition::tau_then_kappa}},
                    "alexa (eq 37) | kappa_then_tau | tau_then_kappa");
    c->add_option("--samples", a->samples, "curve samples in the output")->check(CLI::Range(2, 1000000));
    c->add_option("--out", a->out, "CSV: kind (control|curve), t, x, y, z, curvature, torsion; - for stdout")
        ->required();
    c->add_flag("--slopes", a->slopes,
                "print the LCG and LTG slopes (least squares over t in [0, 1], 400 samples) on stdout");
    return {c, [a] { return run_lac3d(*a); }};
}

}  // namespace cagd::cli
