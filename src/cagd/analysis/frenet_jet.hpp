#pragma once
/// @file
/// Curvature, its arc-length rate and torsion from the derivatives of a curve at one parameter:
/// the one place these formulas are written. Every measure of the library (curve_measures, the
/// log-curvature graph, fairness_measures, compare's figures, the benchmark's shape measures, the
/// SVG comb, measures of sampled curves) calls it.
///
/// For a regular curve r(t) (|r′| > 0), with v = |r′|:
///   κ     = (x′y″ − y′x″) / v³            in the plane: signed, positive where the curve turns left
///   κ     = |r′ × r″| / v³                in space: κ ≥ 0
///   dκ/ds = [ (x′y‴ − y′x‴) v² − 3 (x′y″ − y′x″)(r′·r″) ] / v⁶                           (plane)
///   dκ/ds = [ (r′×r″)·(r′×r‴) / |r′×r″| − 3 |r′×r″| (r′·r″) / v² ] / v⁴                 (space)
///   τ     = (r′ × r″)·r‴ / |r′ × r″|²                                                    (space)
///   dτ/ds = [ ((r′×r″)·r⁗) |r′×r″|² − ((r′×r″)·r‴) · 2 (r′×r″)·(r′×r‴) ] / |r′×r″|⁴ / v (space)
/// (differentiate κ = |w|/v³ and τ = w·r‴/|w|² with w = r′ × r″, w′ = r′ × r‴, and divide by
/// ds/dt = v). They are evaluated on the jet reparametrised to unit speed (row k divided by v k + 1
/// times, v = |r′| without underflow), where v = 1: no power of v is formed, so a curve at any
/// representable scale, in any parameter, gives its curvature wherever that is representable
/// (v³ under- or overflowed at 1e±103: the SVG comb of points scaled by 1e-120 was NaN).
/// Each follows from the Frenet–Serret formulas; tests/analysis/frenet_jet_test.cpp
/// checks them on a circle, a helix and a clothoid, whose κ, dκ/ds and τ are known in closed form.
///
/// The flatness policy, stated once: a point of a curve is straight (its curvature 0 to rounding)
/// where |κ| · D ≤ kFlatCurvature, D a length of the whole curve (the diagonal of its data's, or its
/// own, bounding box, or its length). A straight point has no sign of curvature (curvature_sign
/// gives 0: it is neither an inflection nor a turn), and no torsion (defined_torsion gives NaN: τ is
/// a quotient of rounding noise there; at a natural end of a spline it came out as 1e15 or 0).
/// In space dκ/ds of κ = |r′ × r″| is not differentiable where r′ × r″ = 0; frenet_jet gives 0
/// there (the rate of a curve that stays straight).
#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <vector>

namespace cagd::analysis {

inline constexpr double kFlatCurvature = 1e-9;  ///< the flatness policy's bound on |κ| · D (above)

/// The local differential geometry at one parameter. Fields the derivatives given do not determine
/// are NaN (dκ/ds and τ need r‴, dτ/ds needs r⁗); at a point of zero speed (regular = false) every
/// field but speed is NaN.
struct FrenetJet {
    bool regular = false;                                              ///< |r′| > 0
    double speed = 0.0;                                                ///< v = |r′|
    double curvature = std::numeric_limits<double>::quiet_NaN();       ///< κ: signed in the plane, ≥ 0 in space
    double curvature_rate = std::numeric_limits<double>::quiet_NaN();  ///< dκ/ds
    double torsion = std::numeric_limits<double>::quiet_NaN();         ///< τ (space; NaN where r′ × r″ = 0)
    double torsion_rate = std::numeric_limits<double>::quiet_NaN();    ///< dτ/ds (space)
};

/// The geometry from `derivatives`, whose rows are r′, r″, r‴, r⁗ (as many as given, at least two;
/// 2 or 3 columns). Rows of a jet below its position: frenet_jet(jet.bottomRows(jet.rows() - 1)).
/// InvalidInput when there are fewer than two rows or the dimension is not 2 or 3.
FrenetJet frenet_jet(const Eigen::Ref<const Eigen::MatrixXd>& derivatives);

/// The flatness policy (above): |κ| · D ≤ kFlatCurvature.
inline bool is_straight(double curvature, double extent) { return std::abs(curvature) * extent <= kFlatCurvature; }
/// The sign of a planar curvature under the flatness policy: 0 where straight or not finite.
inline int curvature_sign(double curvature, double extent) {
    if (!std::isfinite(curvature) || is_straight(curvature, extent)) return 0;
    return curvature > 0.0 ? 1 : -1;
}
/// The sign of dκ/ds under the same policy, one power of D up: 0 where |dκ/ds| · D² ≤ kFlatCurvature
/// (a stretch of constant curvature has no extremum of it) or where the rate is not finite.
inline int curvature_rate_sign(double rate, double extent) {
    if (!std::isfinite(rate) || std::abs(rate) * extent * extent <= kFlatCurvature) return 0;
    return rate > 0.0 ? 1 : -1;
}
/// τ where it is defined: NaN at a straight point (flatness policy, D = extent) or a singular one.
inline double defined_torsion(const FrenetJet& f, double extent) {
    return f.regular && !is_straight(f.curvature, extent) ? f.torsion : std::numeric_limits<double>::quiet_NaN();
}

/// Sign changes in a sequence of −1, 0, 1, zeros skipped (a straight stretch neither keeps nor
/// changes a sign); closed: also from the last sign back to the first.
int sign_changes(const std::vector<int>& signs, bool closed);

}  // namespace cagd::analysis
