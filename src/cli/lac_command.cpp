// `cagd lac --alpha A --length L --degree N [--construction scale1|rotation] [--samples S] [--lcg]
// [--fit-from T0 --fit-to T1] --out C.csv`: the nonstationary typical Bezier curve approximating a
// log-aesthetic curve (typical_curves section 3, eq 15–21), its curvature, and its LCG slope.
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>

#include "cagd/aesthetic/typical_bezier.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/spline/bezier.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

enum class LacConstruction { scale1, rotation };

struct LacArgs {
    double alpha = 0.0, length = 1.0, fit_from = 0.05, fit_to = 0.95;
    int degree = 0, samples = 200;
    LacConstruction construction = LacConstruction::scale1;
    std::string out;
    bool lcg = false;
};

int run_lac(const LacArgs& a) {
    const char* who = "cagd lac";
    if (static_cast<double>(a.degree) * a.samples > kMaxDegreeTimesSamples)
        fail_input(who, "--degree " + std::to_string(a.degree) + " x --samples " + std::to_string(a.samples) +
                            " exceeds 2e8 evaluations (seconds of work); lower one");
    if (a.lcg) {
        if (a.degree < 3) fail_input(who, "--lcg needs --degree >= 3 (the LCG uses the third derivative)");
        if (!(a.fit_from >= 0.0 && a.fit_to <= 1.0 && a.fit_from < a.fit_to))
            fail_input(who, "fit range [" + full_precision(a.fit_from) + ", " + full_precision(a.fit_to) +
                                "] must lie in [0, 1] and be non-empty");
    }
    OutputFile file(a.out);
    const aesthetic::TypicalPolygon poly =
        a.construction == LacConstruction::rotation
            ? aesthetic::constant_rotation_typical_polygon(a.alpha, a.length, a.degree)
            : aesthetic::scale_one_typical_polygon(a.alpha, a.length, a.degree);
    // de Casteljau is O(n²) per point: the O(n) Bernstein evaluation above degree 60.
    const BezierCurve curve(poly.points, 0.0, 1.0,
                            a.degree > 60 ? BezierEvaluation::bernstein : BezierEvaluation::de_casteljau);
    CsvOutput out(file, {"kind", "t", "x", "y", "curvature"});
    for (Eigen::Index i = 0; i < poly.points.rows(); ++i)
        out.row_text({"control", std::to_string(i), finite_field(poly.points(i, 0), 15, "control point x"),
                      finite_field(poly.points(i, 1), 15, "control point y"), ""});
    for (int k = 0; k < a.samples; ++k) {
        const double t = static_cast<double>(k) / (a.samples - 1);
        const Eigen::VectorXd p = curve.point(t);
        const std::string kappa = a.degree >= 2 ? finite_field(analysis::signed_curvature(curve, t), 15,
                                                               "curvature at t = " + format_number(t))
                                                : "0";
        out.row_text({"curve", format_number(t, 15), finite_field(p(0), 15, "x at t = " + format_number(t)),
                      finite_field(p(1), 15, "y at t = " + format_number(t)), kappa});
    }
    Quantities q;
    if (a.lcg) {
        const analysis::LineFit f = analysis::lcg_slope(curve, a.fit_from, a.fit_to, 400);
        q.add("lcg_slope", f.slope, 8);
        q.add("lcg_max_residual", f.max_residual, 4);
        q.add("fit_points", f.points);
    }
    out.commit();
    if (a.lcg) q.commit();
    return 0;
}

}  // namespace

Command add_lac_command(CLI::App& app) {
    auto a = std::make_shared<LacArgs>();
    auto* c = app.add_subcommand("lac",
                                 "Nonstationary typical Bezier curve approximating the log-aesthetic curve of eq (15) "
                                 "(typical_curves section 3)");
    c->add_option("--alpha", a->alpha, "LCG slope alpha (scale1: alpha < 0 or alpha > 1; rotation: alpha not 0 or 1)")
        ->required();
    c->add_option("--length", a->length, "total length L of the control polygon (> 0)");
    c->add_option("--degree", a->degree, "Bezier degree n (n + 1 control points; degree x samples <= 2e8)")
        ->required()
        ->check(CLI::Range(1, 100000));
    add_enum_option(c, "--construction", a->construction,
                    {{"scale1", LacConstruction::scale1}, {"rotation", LacConstruction::rotation}},
                    "scale1 (eq 16, equal edges) | rotation (eq 21, equal rotations)");
    c->add_option("--samples", a->samples, "curve samples in the output")->check(CLI::Range(2, 1000000));
    c->add_option("--out", a->out, "CSV: kind (control|curve), t, x, y, curvature; - for stdout")->required();
    c->add_flag("--lcg", a->lcg, "print the fitted LCG slope on stdout");
    c->add_option("--fit-from", a->fit_from, "LCG fit range start in t");
    c->add_option("--fit-to", a->fit_to, "LCG fit range end in t");
    return {c, [a] { return run_lac(*a); }};
}

}  // namespace cagd::cli
