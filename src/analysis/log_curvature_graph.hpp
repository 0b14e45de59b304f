#pragma once
// The logarithmic curvature graph (LCG) of any Curve (typical_curves section 2.2, eq 5).
//
//   x = log ρ,   y = log |ρ ds/dρ|,   ρ = 1/κ the radius of curvature, s arc length.
// Since dρ/ds = −κ_s/κ², ρ ds/dρ = −κ/κ_s, so y = log |κ/κ_s| and x = −log |κ|: one jet of
// order 3 per sample. For a log-aesthetic curve ρ^α = c0 s + c1 (eq 8) the graph is the line
// y = α x + const, so its slope is α (the "LCG slope").
//   κ  = |c| / |r'|³,  c = r' × r''   (z-component in the plane; any dimension ≥ 2)
//   dκ/dt = (c·c')/(|c| |r'|³) − 3 |c| (r'·r'')/|r'|⁵,  c' = r' × r''',   κ_s = (dκ/dt)/|r'|.
// Samples where κ = 0 or κ_s = 0 (no finite LCG point) are skipped and counted, never NaN.
// lcg_slope: ordinary least squares of y on x over `samples` parameters uniform in [t0, t1]
// (the fit range is the caller's choice and changes the slope of a curve that is not exactly a
// log-aesthetic curve: typical_curves Fig. 1 reports it).
// Preconditions (InvalidInput): t_min ≤ t0 < t1 ≤ t_max, samples ≥ 2, regular curve (r' ≠ 0).
#include <vector>

#include "core/curve.hpp"

namespace cagd::analysis {

struct LcgPoint {
    double t;
    double log_radius;     // x = log ρ
    double log_gradient;   // y = log |ρ ds/dρ|
};

struct LcgSamples {
    std::vector<LcgPoint> points;
    int skipped = 0;   // samples with κ = 0 or κ_s = 0
};

// dκ/ds of the unsigned curvature κ = |r' × r''|/|r'|³ at t.
double curvature_arc_derivative(const Curve& c, double t);

LcgSamples log_curvature_graph(const Curve& c, double t0, double t1, int samples);

struct LineFit {
    double slope = 0.0, intercept = 0.0;
    double max_residual = 0.0;   // largest |y − (slope x + intercept)|
    int points = 0;
};
// Least-squares line through (x, y); at least two distinct x (InvalidInput otherwise).
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);
LineFit lcg_slope(const Curve& c, double t0, double t1, int samples);

}  // namespace cagd::analysis
