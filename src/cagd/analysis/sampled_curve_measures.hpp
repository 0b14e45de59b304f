#pragma once
/// @file
/// Measures of a curve known only by samples (a curve CSV as `cagd interpolate` writes it: u,
/// position, first and second derivative), for `cagd analyze CURVE.csv`:
///
///   polyline length   Σ |r_i − r_{i−1}|                                  (2-D or 3-D)
///   enclosed area     ½ Σ (x_{i−1} y_i − x_i y_{i−1}), planar and closed only (signed, CCW > 0)
///   curvature         κ_i, signed in the plane, |κ_i| in 3-D (frenet_jet, analysis/frenet_jet.hpp)
///   bending energy    trapezoid rule Σ ½(κ_{i−1}² + κ_i²) |r_i − r_{i−1}|
///
/// Accuracy: the chord sum and the trapezoid rule are O(h²) in the sample spacing h: sample the
/// curve finer for more digits (`cagd interpolate --samples`), or use `cagd analyze --in` for the
/// integrals of the curve itself. Closed: the last sample lies within
/// kClosedRelativeGap · (1 + length) of the first.
/// Bad input (InvalidInput): fewer than 2 samples, a non-finite value, derivative columns that do
/// not match the position's, zero speed at a sample where curvature is asked.
#include <Eigen/Dense>
#include <optional>
#include <vector>

namespace cagd::analysis {

/// Written curves carry 15 significant digits; an end gap below 1e-12 of the length is rounding.
constexpr double kClosedRelativeGap = 1e-12;

/// A curve given by samples (what `cagd interpolate` writes): positions, optionally derivatives.
struct CurveSamples {
    Eigen::MatrixXd position;               ///< one row per sample, 2 or 3 columns
    std::optional<Eigen::MatrixXd> first;   ///< r'(u), the same shape (with `second`)
    std::optional<Eigen::MatrixXd> second;  ///< r''(u)
    std::vector<double> parameter;          ///< u per sample; empty: the sample index
};

/// What sampled_curve_measures finds.
struct SampledCurveMeasures {
    int samples = 0;                      ///< samples read
    double polyline_length = 0.0;         ///< length of the polyline through the samples
    bool closed = false;                  ///< first and last sample within kClosedRelativeGap of the length
    std::optional<double> enclosed_area;  ///< planar closed curves
    bool has_curvature = false;           ///< derivatives given
    double curvature_min = 0.0;           ///< smallest (signed) curvature
    double curvature_min_at = 0.0;        ///< its parameter
    double curvature_max = 0.0;           ///< largest (signed) curvature
    double curvature_max_at = 0.0;        ///< its parameter
    double bending_energy = 0.0;  ///< ∫ κ² ds by the trapezoid rule over the polyline's arc length (derivatives given)
};

/// The measures of `cagd analyze` on sampled curves.
SampledCurveMeasures sampled_curve_measures(const CurveSamples& s);

}  // namespace cagd::analysis
