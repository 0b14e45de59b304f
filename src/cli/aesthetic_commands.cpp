#include "cli/aesthetic_commands.hpp"

#include <cmath>
#include <fstream>
#include <iostream>

#include "aesthetic/cubic_bspline_monotonicity.hpp"
#include "aesthetic/typical_bezier.hpp"
#include "analysis/curve_measures.hpp"
#include "analysis/log_curvature_graph.hpp"
#include "core/errors.hpp"
#include "core/point_csv.hpp"
#include "repro/csv.hpp"
#include "spline/bezier.hpp"

namespace cagd::cli {

CLI::App* add_lac_command(CLI::App& app, LacArgs& a) {
    auto* c = app.add_subcommand("lac", "Nonstationary typical Bezier curve approximating the log-aesthetic curve of eq (15) (typical_curves section 3)");
    c->add_option("--alpha", a.alpha, "LCG slope alpha (scale1: alpha < 0 or alpha > 1; rotation: alpha not 0 or 1)")->required();
    c->add_option("--length", a.length, "total length L of the control polygon (> 0)");
    c->add_option("--degree", a.degree, "Bezier degree n >= 1 (n + 1 control points)")->required();
    c->add_option("--construction", a.construction, "scale1 (eq 16, equal edges) | rotation (eq 21, equal rotations)")->check(CLI::IsMember({"scale1", "rotation"}));
    c->add_option("--samples", a.samples, "curve samples in the output")->check(CLI::Range(2, 1000000));
    c->add_option("--out", a.out, "CSV: kind (control|curve), t, x, y, curvature")->required();
    c->add_flag("--lcg", a.lcg, "print the fitted LCG slope on stdout");
    c->add_option("--fit-from", a.fit_from, "LCG fit range start in t (default 0.05)");
    c->add_option("--fit-to", a.fit_to, "LCG fit range end in t (default 0.95)");
    return c;
}

CLI::App* add_monotone_command(CLI::App& app, MonotoneArgs& a) {
    auto* c = app.add_subcommand("monotone", "Per-segment curvature monotonicity of a planar cubic B-spline (typical_curves section 3.4, appendix A)");
    c->add_option("--in", a.in, "control points CSV: x,y per line")->required();
    c->add_option("--knots", a.knots, "endpoint (endpoint-interpolating, default) | uniform")->check(CLI::IsMember({"endpoint", "uniform"}));
    return c;
}

int run_lac(const LacArgs& a) {
    if (a.degree < 1) fail_input("cagd lac", "--degree must be >= 1, got " + std::to_string(a.degree));
    const aesthetic::TypicalPolygon poly = a.construction == "rotation" ? aesthetic::constant_rotation_typical_polygon(a.alpha, a.length, a.degree)
                                                                        : aesthetic::scale_one_typical_polygon(a.alpha, a.length, a.degree);
    // de Casteljau is O(n²) per point: the O(n) Bernstein evaluation above degree 60.
    const BezierCurve curve(poly.points, 0.0, 1.0, a.degree > 60 ? BezierEvaluation::bernstein : BezierEvaluation::de_casteljau);
    std::ofstream out(a.out);
    if (!out) fail_input("cagd lac", "cannot write '" + a.out + "'");
    out << "kind,t,x,y,curvature\n";
    for (Eigen::Index i = 0; i < poly.points.rows(); ++i)
        out << "control," << i << ',' << repro::format_number(poly.points(i, 0), 15) << ',' << repro::format_number(poly.points(i, 1), 15) << ",\n";
    for (int k = 0; k < a.samples; ++k) {
        const double t = static_cast<double>(k) / (a.samples - 1);
        const Eigen::VectorXd p = curve.point(t);
        const std::string kappa = a.degree >= 2 ? repro::format_number(analysis::signed_curvature(curve, t), 15) : "0";
        out << "curve," << repro::format_number(t, 15) << ',' << repro::format_number(p(0), 15) << ',' << repro::format_number(p(1), 15) << ',' << kappa << '\n';
    }
    if (a.lcg) {
        if (a.degree < 3) fail_input("cagd lac", "--lcg needs --degree >= 3 (the LCG uses the third derivative)");
        if (!(a.fit_from >= 0.0 && a.fit_to <= 1.0 && a.fit_from < a.fit_to))
            fail_input("cagd lac", "fit range [" + full_precision(a.fit_from) + ", " + full_precision(a.fit_to) + "] must lie in [0, 1] and be non-empty");
        const analysis::LineFit f = analysis::lcg_slope(curve, a.fit_from, a.fit_to, 400);
        std::cout << "lcg_slope," << repro::format_number(f.slope, 8) << "\nlcg_max_residual," << repro::format_number(f.max_residual, 4) << "\nfit_points," << f.points << '\n';
    }
    return 0;
}

int run_monotone(const MonotoneArgs& a) {
    const PointList p = read_points_csv(a.in);
    if (p.cols() != 2) fail_input("cagd monotone", "control points must be planar (x,y), got " + std::to_string(p.cols()) + " columns");
    const BSplineCurve curve = a.knots == "uniform" ? aesthetic::uniform_cubic_bspline(p) : aesthetic::endpoint_interpolating_cubic_bspline(p);
    const aesthetic::MonotonicityReport r = aesthetic::cubic_bspline_curvature_monotonicity(curve);
    std::cout << "segment,turn0_deg,turn1_deg,equal_edges,condition29,bernstein,exact_trend\n";
    for (const aesthetic::SegmentVerdict& v : r.segments)
        std::cout << v.segment << ',' << repro::format_number(v.turn0 * 180 / M_PI, 8) << ',' << repro::format_number(v.turn1 * 180 / M_PI, 8) << ','
                  << (v.equal_edges ? "yes" : "no") << ',' << aesthetic::to_string(v.condition29_verdict) << ',' << aesthetic::to_string(v.bernstein_verdict) << ','
                  << analysis::to_string(v.exact) << '\n';
    std::cout << "whole_curve," << analysis::to_string(r.whole_curve) << '\n';
    return 0;
}

}  // namespace cagd::cli
