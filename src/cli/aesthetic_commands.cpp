#include "cli/aesthetic_commands.hpp"

#include <cmath>
#include <fstream>
#include <iostream>

#include "aesthetic/cubic_bspline_monotonicity.hpp"
#include "aesthetic/space_typical_bezier.hpp"
#include "aesthetic/typical_surface.hpp"
#include "analysis/surface_curvature.hpp"
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

CLI::App* add_lac3d_command(CLI::App& app, Lac3dArgs& a) {
    auto* c = app.add_subcommand("lac3d", "Typical Bezier space curve approximating a log-aesthetic space curve, frames turned by R_kappa (x) R_tau (typical_curves section 4)");
    c->add_option("--alpha", a.alpha, "LCG slope alpha (not 0 or 1; < 0 or > 1 when --start 0)")->required();
    c->add_option("--beta", a.beta, "LTG slope beta (not 0 or 1; < 0 or > 1 when --start 0)")->required();
    c->add_option("--degree", a.degree, "Bezier degree n >= 3 (torsion needs four control points)")->required();
    c->add_option("--length", a.length, "arc length L of the target piece (> 0, default 1)");
    c->add_option("--start", a.start, "the piece starts at sigma = s0 of kappa = |alpha-1| sigma^(-1/alpha), tau = |beta-1| sigma^(-1/beta) (>= 0, default 0.1)");
    c->add_option("--composition", a.composition, "alexa (eq 37, default) | kappa_then_tau | tau_then_kappa")->check(CLI::IsMember({"alexa", "kappa_then_tau", "tau_then_kappa"}));
    c->add_option("--samples", a.samples, "curve samples in the output")->check(CLI::Range(2, 1000000));
    c->add_option("--out", a.out, "CSV: kind (control|curve), t, x, y, z, curvature, torsion")->required();
    c->add_flag("--slopes", a.slopes, "print the LCG and LTG slopes (least squares over t in [0, 1], 400 samples) on stdout");
    return c;
}

CLI::App* add_typical_surface_command(CLI::App& app, TypicalSurfaceArgs& a) {
    auto* c = app.add_subcommand("typical-surface", "Nonstationary typical surface: net with fixed edges, polygons turned about their diagonals; Bezier patch with K and H (typical_curves section 5)");
    c->add_option("--n", a.n, "control points per direction (>= 3; the patch has bi-degree n - 1)")->required();
    c->add_option("--alpha-u", a.alpha_u, "alpha of the v = 0 boundary P(i,0) (< 0 or > 1)")->required();
    c->add_option("--alpha-v", a.alpha_v, "alpha of the u = 0 boundary P(0,j) (< 0 or > 1)")->required();
    c->add_option("--angle-deg", a.angle_deg, "rotation of every control polygon about its diagonal, degrees")->required();
    c->add_option("--length", a.length, "length of each boundary polygon (> 0, default 1)");
    c->add_option("--grid", a.grid, "parameter grid points per direction (default 51)")->check(CLI::Range(2, 100000));
    c->add_option("--out", a.out, "CSV: u, v, x, y, z, gaussian, mean")->required();
    c->add_option("--net-out", a.net_out, "optional CSV of the control net: i, j, x, y, z");
    return c;
}

int run_lac3d(const Lac3dArgs& a) {
    const aesthetic::LogAestheticSpaceParameters p = aesthetic::normalized_log_aesthetic_space_parameters(a.alpha, a.beta, a.length, a.start);
    const aesthetic::FrenetComposition comp = a.composition == "kappa_then_tau"   ? aesthetic::FrenetComposition::kappa_then_tau
                                              : a.composition == "tau_then_kappa" ? aesthetic::FrenetComposition::tau_then_kappa
                                                                                  : aesthetic::FrenetComposition::alexa;
    const aesthetic::SpaceTypicalPolygon poly = aesthetic::space_typical_polygon(p, a.degree, comp);
    const BezierCurve curve(poly.points, 0.0, 1.0, a.degree > 60 ? BezierEvaluation::bernstein : BezierEvaluation::de_casteljau);
    std::ofstream out(a.out);
    if (!out) fail_input("cagd lac3d", "cannot write '" + a.out + "'");
    out << "kind,t,x,y,z,curvature,torsion\n";
    for (Eigen::Index i = 0; i < poly.points.rows(); ++i)
        out << "control," << i << ',' << repro::format_number(poly.points(i, 0), 15) << ',' << repro::format_number(poly.points(i, 1), 15) << ',' << repro::format_number(poly.points(i, 2), 15) << ",,\n";
    for (int k = 0; k < a.samples; ++k) {
        const double t = static_cast<double>(k) / (a.samples - 1);
        const Eigen::VectorXd q = curve.point(t);
        out << "curve," << repro::format_number(t, 15) << ',' << repro::format_number(q(0), 15) << ',' << repro::format_number(q(1), 15) << ',' << repro::format_number(q(2), 15) << ','
            << repro::format_number(analysis::curvature(curve, t), 15) << ',' << repro::format_number(analysis::torsion(curve, t), 15) << '\n';
    }
    if (a.slopes) {
        const analysis::LineFit k = analysis::lcg_slope(curve, 0.0, 1.0, 400), t = analysis::ltg_slope(curve, 0.0, 1.0, 400);
        std::cout << "lcg_slope," << repro::format_number(k.slope, 8) << "\nltg_slope," << repro::format_number(t.slope, 8) << "\nlcg_max_residual," << repro::format_number(k.max_residual, 4)
                  << "\nltg_max_residual," << repro::format_number(t.max_residual, 4) << '\n';
    }
    return 0;
}

int run_typical_surface(const TypicalSurfaceArgs& a) {
    if (a.n < 3) fail_input("cagd typical-surface", "--n must be >= 3 (control points per direction), got " + std::to_string(a.n));
    if (!std::isfinite(a.angle_deg)) fail_input("cagd typical-surface", "--angle-deg = " + full_precision(a.angle_deg) + " is not finite");
    const surface::ControlNet net = aesthetic::log_aesthetic_typical_net(a.alpha_u, a.alpha_v, a.length, a.n - 1, a.angle_deg * M_PI / 180.0);
    const surface::BezierPatch patch(net);
    std::vector<double> ts;
    for (int k = 0; k < a.grid; ++k) ts.push_back(static_cast<double>(k) / (a.grid - 1));
    const surface::SurfaceGrid g = patch.evaluate_grid(ts, ts);
    std::ofstream out(a.out);
    if (!out) fail_input("cagd typical-surface", "cannot write '" + a.out + "'");
    out << "u,v,x,y,z,gaussian,mean\n";
    for (Eigen::Index i = 0; i < a.grid; ++i)
        for (Eigen::Index j = 0; j < a.grid; ++j) {
            const analysis::SurfaceJet2 jet = g.jet(i, j);
            const analysis::SurfaceCurvatures c = analysis::surface_curvatures(jet);
            out << repro::format_number(ts[static_cast<std::size_t>(i)], 15) << ',' << repro::format_number(ts[static_cast<std::size_t>(j)], 15) << ',' << repro::format_number(jet.s(0), 15) << ','
                << repro::format_number(jet.s(1), 15) << ',' << repro::format_number(jet.s(2), 15) << ',' << repro::format_number(c.gaussian, 15) << ',' << repro::format_number(c.mean, 15) << '\n';
        }
    if (!a.net_out.empty()) {
        std::ofstream nout(a.net_out);
        if (!nout) fail_input("cagd typical-surface", "cannot write '" + a.net_out + "'");
        nout << "i,j,x,y,z\n";
        for (Eigen::Index i = 0; i < net[0].rows(); ++i)
            for (Eigen::Index j = 0; j < net[0].cols(); ++j)
                nout << i << ',' << j << ',' << repro::format_number(net[0](i, j), 15) << ',' << repro::format_number(net[1](i, j), 15) << ',' << repro::format_number(net[2](i, j), 15) << '\n';
    }
    return 0;
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
