// sb2_locality, section 2 (eq 1–8, Fig. 2): the B2 and S basis functions, the relations
// (3)/(7), the blending functions g, h, ĝ, ĥ and their supports.
// Our values come from the library's B-spline basis (Cox–de Boor via cagd::BSplineCurve);
// the printed polynomials are only in the reference file.
#include <Eigen/Dense>
#include <cmath>
#include <functional>

#include "cagd/locality/locality_spline.hpp"
#include "cagd/numeric/gauss_legendre.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::locality;

namespace {
using Fn = std::function<double(double, int)>;

// Taylor coefficients in t of f(u0 + scale·t) on its piece: c_k = f^(k)(u0+) scale^k / k!.
Eigen::VectorXd taylor(const Fn& f, double u0, double scale, int degree) {
    Eigen::VectorXd c(degree + 1);
    double fact = 1.0;
    for (int k = 0; k <= degree; ++k) {
        if (k > 0) fact *= k;
        c(k) = f(u0, k) * std::pow(scale, k) / fact;
    }
    return c;
}
// Independent: interpolate the piece at degree+1 interior points (Vandermonde solve).
Eigen::VectorXd fitted(const Fn& f, double u0, double scale, int degree) {
    Eigen::MatrixXd V(degree + 1, degree + 1);
    Eigen::VectorXd y(degree + 1);
    for (int i = 0; i <= degree; ++i) {
        const double t = (i + 0.5) / (degree + 1);
        for (int k = 0; k <= degree; ++k) V(i, k) = std::pow(t, k);
        y(i) = f(u0 + scale * t, 0);
    }
    return V.fullPivLu().solve(y);
}

double l1_norm(const std::function<double(double)>& f) {
    std::vector<double> br;
    for (int k = -192; k <= 192; ++k) br.push_back(k / 64.0);
    return numeric::GaussLegendreRule(8).integrate_piecewise([&](double u) { return std::abs(f(u)); }, br);
}
}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run("sb2_locality", "basis", "2",
                           "Basis and blending functions of the B2- and S-spline (eq 1–8, Fig. 2)", argc, argv);
    const Fn e = [](double u, int k) { return basis_e(u, k); };
    const Fn eh = [](double u, int k) { return basis_e_hat(u, k); };
    const Fn fh = [](double u, int k) { return basis_f_hat(u, k); };
    struct Piece {
        const char* id;
        Fn f;
        double u0, scale;
        int degree;
    };
    const Piece pieces[] = {{"eq4.e_piece1", e, 0.5, 0.5, 3},     {"eq4.e_piece2", e, 0.0, 0.5, 3},
                            {"eq4.e_piece3", e, -0.5, 0.5, 3},    {"eq4.e_piece4", e, -1.0, 0.5, 3},
                            {"eq8.fhat_piece1", fh, 1.0, 1.0, 4}, {"eq8.ehat_piece1", eh, 0.0, 1.0, 4},
                            {"eq8.fhat_piece2", fh, 0.0, 1.0, 4}, {"eq8.ehat_piece2", eh, -1.0, 1.0, 4},
                            {"eq8.fhat_piece3", fh, -1.0, 1.0, 4}};
    for (const auto& p : pieces) {
        const Eigen::VectorXd c = taylor(p.f, p.u0, p.scale, p.degree);
        for (int k = 0; k <= p.degree; ++k) run.check(std::string(p.id) + ".c" + std::to_string(k), c(k));
        run.validate(std::string(p.id) + ".fit",
                     "Taylor coefficients vs polynomial interpolation of the same piece (max |Δ|)",
                     (c - fitted(p.f, p.u0, p.scale, p.degree)).cwiseAbs().maxCoeff(), 0.0, 1e-12,
                     "Vandermonde solve, condition ~1e3");
    }
    const KnotRelation b2 = knot_relation(SplineForm::b2_spline), s = knot_relation(SplineForm::s_spline);
    run.check("eq3.side", b2.side);
    run.check("eq3.centre", b2.centre);
    run.check("eq7.side", s.side);
    run.check("eq7.centre", s.centre);
    run.check("eq4.g_factor", blending_g(SplineForm::b2_spline, 0.0) / basis_e(0.0));
    // Coefficient of e(u) in h (of ê(u) in ĥ): at u < 0 the e(u−1) (ê(u−1)) term vanishes.
    run.check("eq4.h_side", (blending_h(SplineForm::b2_spline, -0.5) - basis_e(-1.0)) / basis_e(-0.5));
    run.check("eq8.g_factor", blending_g(SplineForm::s_spline, 0.0) / basis_e_hat(0.0));
    run.check("eq8.h_side", (blending_h(SplineForm::s_spline, -0.75) - basis_f_hat(-0.75)) / basis_e_hat(-0.75));

    // Supports, signs and sizes from the sampled functions; Fig. 2 data.
    auto fig = run.table("fig2.csv", {"u", "g", "h", "g_hat", "h_hat"});
    struct Range {
        double lo = 1e9, hi = -1e9, min = 0.0;
    };
    Range r[4];
    for (int k = -192; k <= 192; ++k) {
        const double u = k / 64.0;
        const double v[4] = {blending_g(SplineForm::b2_spline, u), blending_h(SplineForm::b2_spline, u),
                             blending_g(SplineForm::s_spline, u), blending_h(SplineForm::s_spline, u)};
        if (u >= -1.5 && u <= 2.5) fig.row({u, v[0], v[1], v[2], v[3]});
        for (int j = 0; j < 4; ++j) {
            r[j].min = std::min(r[j].min, v[j]);
            if (std::abs(v[j]) > 1e-14) {
                r[j].lo = std::min(r[j].lo, u);
                r[j].hi = std::max(r[j].hi, u);
            }
        }
    }
    const double spacing[4] = {0.5, 0.5, 1.0, 1.0};
    const char* ids[4] = {"sec23.support_g", "sec23.support_h", "sec23.support_ghat", "sec23.support_hhat"};
    for (int j = 0; j < 4; ++j) run.check(ids[j], (std::ceil(r[j].hi / spacing[j]) - std::floor(r[j].lo / spacing[j])));
    run.check("sec23.g_nonnegative", (r[0].min >= 0.0 && r[2].min >= 0.0) ? 1.0 : 0.0);
    run.check("sec23.h_negative", (r[1].min < 0.0 && r[3].min < 0.0) ? 1.0 : 0.0);
    const auto norm = [](SplineForm f, bool g) {
        return l1_norm([=](double u) { return g ? blending_g(f, u) : blending_h(f, u); });
    };
    run.check("sec23.s_h_smaller", norm(SplineForm::s_spline, false) < norm(SplineForm::b2_spline, false) ? 1.0 : 0.0);
    run.check("sec23.s_g_larger", norm(SplineForm::s_spline, true) > norm(SplineForm::b2_spline, true) ? 1.0 : 0.0);
    run.note("L1 norms: |g| = " + format_number(norm(SplineForm::b2_spline, true), 6) +
             ", |ĝ| = " + format_number(norm(SplineForm::s_spline, true), 6) +
             ", |h| = " + format_number(norm(SplineForm::b2_spline, false), 6) +
             ", |ĥ| = " + format_number(norm(SplineForm::s_spline, false), 6) + ".");
    run.figure("fig2", "Fig. 2 — blending functions g, h (B2-spline) and ĝ, ĥ (S-spline)");
    return run.finish();
}
