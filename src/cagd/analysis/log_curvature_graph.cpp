#include "cagd/analysis/log_curvature_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/frenet_jet.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::analysis {

namespace {

struct CurvatureAndRate {
    double kappa, kappa_s;
};

// κ and dκ/ds (signed in the plane: the graph takes |κ| and |κ/κ_s|); 0 and 0 where r′ × r″ = 0.
CurvatureAndRate curvature_and_rate(const Curve& c, double t) {
    if (c.dimension() < 2 || c.dimension() > 3)
        fail_input("cagd::analysis::log_curvature_graph", "curve dimension must be 2 or 3");
    const Eigen::MatrixXd j = c.jet(t, 3);
    const FrenetJet f = frenet_jet(j.bottomRows(3));
    if (!f.regular) fail_input("cagd::analysis::log_curvature_graph", "r'(t) = 0 at t = " + full_precision(t));
    if (f.curvature == 0.0) return {0.0, 0.0};
    return {f.curvature, f.curvature_rate};
}

}  // namespace

double curvature_arc_derivative(const Curve& c, double t) { return curvature_and_rate(c, t).kappa_s; }

namespace {

// τ and dτ/ds of a 3-D curve (NaN where r′ × r″ = 0).
FrenetJet torsion_and_rate(const Curve& c, double t) {
    if (c.dimension() != 3)
        fail_input("cagd::analysis::torsion",
                   "torsion needs a 3-D curve, got dimension " + std::to_string(c.dimension()));
    const Eigen::MatrixXd j = c.jet(t, 4);
    const FrenetJet f = frenet_jet(j.bottomRows(4));
    if (!f.regular) fail_input("cagd::analysis::torsion", "r'(t) = 0 at t = " + full_precision(t));
    return f;
}

// Samples (x, y) = (−log|r|, log|r/r_s|) of a rate r (curvature or torsion) at `samples` parameters.
template <class RateAndDerivative>
LcgSamples log_rate_graph(const char* who, const Curve& c, double t0, double t1, int samples, RateAndDerivative rate) {
    if (!(t0 >= c.t_min() && t1 <= c.t_max() && t0 < t1))
        fail_input(who, "range [" + full_precision(t0) + ", " + full_precision(t1) + "] not inside [" +
                            full_precision(c.t_min()) + ", " + full_precision(c.t_max()) + "] or empty");
    if (samples < 2) fail_input(who, "samples = " + std::to_string(samples) + " < 2");
    LcgSamples out;
    for (int k = 0; k < samples; ++k) {
        const double t = t0 + (t1 - t0) * k / (samples - 1);
        const auto [r, r_s] = rate(t);
        if (r == 0.0 || r_s == 0.0 || !std::isfinite(r) || !std::isfinite(r_s)) {
            ++out.skipped;
            continue;
        }
        out.points.push_back({t, -std::log(std::abs(r)), std::log(std::abs(r / r_s))});
    }
    return out;
}

LineFit fit_graph(const char* who, const LcgSamples& g) {
    std::vector<double> x, y;
    for (const LcgPoint& p : g.points) {
        x.push_back(p.log_radius);
        y.push_back(p.log_gradient);
    }
    if (x.size() < 2) fail_input(who, "fewer than two samples with finite graph coordinates in the range");
    return fit_line(x, y);
}

}  // namespace

LcgSamples log_curvature_graph(const Curve& c, double t0, double t1, int samples) {
    return log_rate_graph("cagd::analysis::log_curvature_graph", c, t0, t1, samples, [&c](double t) {
        const CurvatureAndRate r = curvature_and_rate(c, t);
        return std::pair{r.kappa, r.kappa_s};
    });
}

double curve_extent(const Curve& c) {
    const std::vector<double> br = c.breakpoints();
    Eigen::VectorXd lo = c.point(br.front()), hi = lo;
    for (double t : br) {
        const Eigen::VectorXd p = c.point(t);
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return (hi - lo).norm();
}

double torsion(const Curve& c, double t, double extent) { return defined_torsion(torsion_and_rate(c, t), extent); }

double torsion(const Curve& c, double t) { return torsion(c, t, curve_extent(c)); }
double torsion_arc_derivative(const Curve& c, double t) { return torsion_and_rate(c, t).torsion_rate; }

CurvatureTorsionExtremes curvature_torsion_extremes(const Curve& c, int samples_per_piece) {
    if (samples_per_piece < 1)
        fail_input("cagd::analysis::curvature_torsion_extremes",
                   "samples_per_piece = " + std::to_string(samples_per_piece) + " < 1");
    // τ is measured where it is defined by the flatness policy (torsion(c, t, extent) not NaN).
    CurvatureTorsionExtremes e;
    const std::vector<double> br = c.breakpoints();
    const bool space = c.dimension() == 3;
    const double extent = space ? curve_extent(c) : 0.0;
    for (std::size_t p = 0; p + 1 < br.size(); ++p)
        for (int k = 0; k <= samples_per_piece; ++k) {
            const double t = br[p] + (br[p + 1] - br[p]) * k / samples_per_piece;
            const double kappa = curvature(c, t);
            e.max_abs_curvature = std::max(e.max_abs_curvature, kappa);
            if (space && !is_straight(kappa, extent))
                e.max_abs_torsion = std::max(e.max_abs_torsion, std::abs(torsion_and_rate(c, t).torsion));
        }
    return e;
}

LcgSamples log_torsion_graph(const Curve& c, double t0, double t1, int samples) {
    return log_rate_graph("cagd::analysis::log_torsion_graph", c, t0, t1, samples, [&c](double t) {
        const FrenetJet f = torsion_and_rate(c, t);
        return std::pair{f.torsion, f.torsion_rate};
    });
}

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size() || x.size() < 2)
        fail_input("cagd::analysis::fit_line", "needs at least two (x, y) pairs of equal count");
    const double n = static_cast<double>(x.size());
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        mx += x[i];
        my += y[i];
    }
    mx /= n;
    my /= n;
    double sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxx += (x[i] - mx) * (x[i] - mx);
        sxy += (x[i] - mx) * (y[i] - my);
    }
    if (!(sxx > 0.0)) fail_input("cagd::analysis::fit_line", "all x equal (" + full_precision(mx) + ")");
    LineFit f;
    f.slope = sxy / sxx;
    f.intercept = my - f.slope * mx;
    f.points = static_cast<int>(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        f.max_residual = std::max(f.max_residual, std::abs(y[i] - (f.slope * x[i] + f.intercept)));
    return f;
}

LineFit lcg_slope(const Curve& c, double t0, double t1, int samples) {
    return fit_graph("cagd::analysis::lcg_slope", log_curvature_graph(c, t0, t1, samples));
}

LineFit ltg_slope(const Curve& c, double t0, double t1, int samples) {
    return fit_graph("cagd::analysis::ltg_slope", log_torsion_graph(c, t0, t1, samples));
}

}  // namespace cagd::analysis
