// `cagd lac3d --alpha A --beta B --degree N [--length L] [--start S0] [--composition C] [--slopes]
// --out C.csv`: the typical Bezier space curve approximating a log-aesthetic space curve, frames
// turned by R_kappa (x) R_tau (typical_curves section 4), with curvature, torsion and slopes.
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>

#include "aesthetic/space_typical_bezier.hpp"
#include "analysis/curve_measures.hpp"
#include "analysis/log_curvature_graph.hpp"
#include "cli/commands.hpp"
#include "core/csv.hpp"
#include "core/errors.hpp"
#include "spline/bezier.hpp"

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
    const aesthetic::LogAestheticSpaceParameters p = aesthetic::normalized_log_aesthetic_space_parameters(a.alpha, a.beta, a.length, a.start);
    const aesthetic::SpaceTypicalPolygon poly = aesthetic::space_typical_polygon(p, a.degree, a.composition);
    const BezierCurve curve(poly.points, 0.0, 1.0, a.degree > 60 ? BezierEvaluation::bernstein : BezierEvaluation::de_casteljau);
    std::ofstream out(a.out);
    if (!out) fail_input("cagd lac3d", "cannot write '" + a.out + "'");
    out << "kind,t,x,y,z,curvature,torsion\n";
    for (Eigen::Index i = 0; i < poly.points.rows(); ++i)
        out << "control," << i << ',' << format_number(poly.points(i, 0), 15) << ',' << format_number(poly.points(i, 1), 15) << ',' << format_number(poly.points(i, 2), 15)
            << ",,\n";
    for (int k = 0; k < a.samples; ++k) {
        const double t = static_cast<double>(k) / (a.samples - 1);
        const Eigen::VectorXd q = curve.point(t);
        out << "curve," << format_number(t, 15) << ',' << format_number(q(0), 15) << ',' << format_number(q(1), 15) << ',' << format_number(q(2), 15) << ','
            << format_number(analysis::curvature(curve, t), 15) << ',' << format_number(analysis::torsion(curve, t), 15) << '\n';
    }
    if (a.slopes) {
        const analysis::LineFit k = analysis::lcg_slope(curve, 0.0, 1.0, 400), t = analysis::ltg_slope(curve, 0.0, 1.0, 400);
        std::cout << "lcg_slope," << format_number(k.slope, 8) << "\nltg_slope," << format_number(t.slope, 8) << "\nlcg_max_residual," << format_number(k.max_residual, 4)
                  << "\nltg_max_residual," << format_number(t.max_residual, 4) << '\n';
    }
    return 0;
}

}  // namespace

Command add_lac3d_command(CLI::App& app) {
    auto a = std::make_shared<Lac3dArgs>();
    auto* c = app.add_subcommand("lac3d", "Typical Bezier space curve approximating a log-aesthetic space curve, frames turned by R_kappa (x) R_tau (typical_curves section 4)");
    c->add_option("--alpha", a->alpha, "LCG slope alpha (not 0 or 1; < 0 or > 1 when --start 0)")->required();
    c->add_option("--beta", a->beta, "LTG slope beta (not 0 or 1; < 0 or > 1 when --start 0)")->required();
    c->add_option("--degree", a->degree, "Bezier degree n >= 3 (torsion needs four control points)")->required();
    c->add_option("--length", a->length, "arc length L of the target piece (> 0)");
    c->add_option("--start", a->start, "the piece starts at sigma = s0 of kappa = |alpha-1| sigma^(-1/alpha), tau = |beta-1| sigma^(-1/beta) (>= 0)");
    add_enum_option(c, "--composition", a->composition,
                    {{"alexa", aesthetic::FrenetComposition::alexa},
                     {"kappa_then_tau", aesthetic::FrenetComposition::kappa_then_tau},
                     {"tau_then_kappa", aesthetic::FrenetComposition::tau_then_kappa}},
                    "alexa (eq 37) | kappa_then_tau | tau_then_kappa");
    c->add_option("--samples", a->samples, "curve samples in the output")->check(CLI::Range(2, 1000000));
    c->add_option("--out", a->out, "CSV: kind (control|curve), t, x, y, z, curvature, torsion")->required();
    c->add_flag("--slopes", a->slopes, "print the LCG and LTG slopes (least squares over t in [0, 1], 400 samples) on stdout");
    return {c, [a] { return run_lac3d(*a); }};
}

}  // namespace cagd::cli
