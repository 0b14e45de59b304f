#pragma once
/// @file
/// The logarithmic curvature graph (LCG) of any Curve (typical_curves section 2.2, eq 5) and the
/// logarithmic torsion graph (LTG) of a space curve (section 4).
///
///   x = log ρ,   y = log |ρ ds/dρ|,   ρ = 1/κ the radius of curvature, s arc length.
/// Since dρ/ds = −κ_s/κ², ρ ds/dρ = −κ/κ_s, so y = log |κ/κ_s| and x = −log |κ|: one jet of
/// order 3 per sample. For a log-aesthetic curve ρ^α = c0 s + c1 (eq 8) the graph is the line
/// y = α x + const, so its slope is α (the "LCG slope").
/// κ and κ_s = dκ/ds come from frenet_jet (analysis/frenet_jet.hpp, the one kernel).
/// Samples where κ = 0 or κ_s = 0 (no finite LCG point) are skipped and counted, never NaN.
/// lcg_slope: ordinary least squares of y on x over `samples` parameters uniform in [t0, t1]
/// (the fit range is the caller's choice and changes the slope of a curve that is not exactly a
/// log-aesthetic curve: typical_curves Fig. 1 reports it).
///
/// The logarithmic torsion graph (LTG, typical_curves section 4) of a space curve is the same with
/// the radius of torsion μ = 1/τ:  x = log μ = −log |τ|,  y = log |μ ds/dμ| = log |τ/τ_s|; for a
/// log-aesthetic space curve μ^β = g s + h (eq 32) it is a line of slope β. From one jet of order 4:
/// τ and τ_s = dτ/ds come from frenet_jet too.
/// Samples with τ = 0, τ_s = 0 or c = 0 (no osculating plane) are skipped and counted.
/// Preconditions (InvalidInput): t_min ≤ t0 < t1 ≤ t_max, samples ≥ 2, regular curve (r' ≠ 0);
/// torsion and LTG: 3-D curves.
#include <vector>

#include "cagd/analysis/frenet_jet.hpp"
#include "cagd/core/curve.hpp"

namespace cagd::analysis {

/// One point of a logarithmic curvature (or torsion) graph.
struct LcgPoint {
    double t;             ///< the curve parameter of the sample
    double log_radius;    ///< x = log ρ
    double log_gradient;  ///< y = log |ρ ds/dρ|
};

/// The samples of a logarithmic curvature (or torsion) graph.
struct LcgSamples {
    std::vector<LcgPoint> points;  ///< the usable samples
    int skipped = 0;               ///< samples with κ = 0 or κ_s = 0
};

/// dκ/ds of the unsigned curvature κ = |r' × r''|/|r'|³ at t.
double curvature_arc_derivative(const Curve& c, double t);

/// The LCG of c over [t0, t1] at `samples` equally spaced parameters.
LcgSamples log_curvature_graph(const Curve& c, double t0, double t1, int samples);

/// A least-squares line y = slope x + intercept.
struct LineFit {
    double slope = 0.0;         ///< the slope (the LCG slope α for a log-aesthetic curve)
    double intercept = 0.0;     ///< the intercept
    double max_residual = 0.0;  ///< largest |y − (slope x + intercept)|
    int points = 0;             ///< points fitted
};
/// Least-squares line through (x, y); at least two distinct x (InvalidInput otherwise).
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);
/// The least-squares slope of the LCG over [t0, t1] (α for a log-aesthetic curve).
LineFit lcg_slope(const Curve& c, double t0, double t1, int samples);

/// D of the flatness policy (analysis/frenet_jet.hpp) for a curve on its own: the diagonal of the bounding box of its
/// positions at its breakpoints (O(pieces)).
double curve_extent(const Curve& c);
/// Torsion τ(t) of a 3-D curve, NaN where the curve is straight by the flatness policy with the
/// length `extent` (see above).
double torsion(const Curve& c, double t, double extent);
/// The same with extent = curve_extent(c) (O(pieces) per call: give the extent in loops).
double torsion(const Curve& c, double t);
/// The largest |κ| and, for a space curve, the largest |τ| over samples_per_piece + 1 uniform
/// samples of every piece (τ counts only where it is defined: the flatness policy above).
/// Precondition: r'(t) ≠ 0 at the samples (InvalidInput names t).
struct CurvatureTorsionExtremes {
    double max_abs_curvature = 0.0;  ///< largest sampled |κ|
    double max_abs_torsion = 0.0;    ///< 0 for planar curves
};
/// The largest |κ| and |τ| over `samples_per_piece` samples of each piece.
CurvatureTorsionExtremes curvature_torsion_extremes(const Curve& c, int samples_per_piece = 32);
/// dτ/ds at t (space curves).
double torsion_arc_derivative(const Curve& c, double t);
/// LTG samples: log_radius = log μ, log_gradient = log |μ ds/dμ|.
LcgSamples log_torsion_graph(const Curve& c, double t0, double t1, int samples);
/// The least-squares slope of the logarithmic torsion graph over [t0, t1] (β for a log-aesthetic space curve).
LineFit ltg_slope(const Curve& c, double t0, double t1, int samples);

}  // namespace cagd::analysis
