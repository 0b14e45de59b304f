#pragma once
/// @file
/// Curvature monotonicity of cubic B-spline segments (typical_curves section 3.4 and appendix A).
///
/// Unit polygon (Fig. 2 top): P_{i+1} = (0, 0), P_{i+2} = (1, 0), unit edges, turning angle θ0 at
/// P_{i+1} and θ1 at P_{i+2} (positive = left turn). The uniform segment's Bézier points (A.1)
///   Q0 = (P_i + 4P_{i+1} + P_{i+2})/6, Q1 = (2P_{i+1} + P_{i+2})/3, Q2 = (P_{i+1} + 2P_{i+2})/3,
///   Q3 = (P_{i+1} + 4P_{i+2} + P_{i+3})/6.
/// h(t) = f'g − (3/2) f g' (analysis/curvature_monotonicity) is a quintic; its Bernstein
/// coefficients for the unit polygon, derived with sympy and checked against the product
/// computation (tests, experiment appendix_coefficients), are
///   C0 = cos³(θ0/2) [sin(θ0/2 + θ1) − 3 sin(θ0/2)]
///   C1 = −(2/5)[2 − 4cos θ0 + cos θ1 + cos(θ0 + θ1)] sin θ0 − cos³(θ0/2)[3 sin(θ0/2) − sin(θ0/2 + θ1)]
///   C2 = (1/40){−22 sin θ0 + 7 sin 2θ0 − 2cos(θ0/2)[32 sin(θ0/2 − θ1) + 14 sin(θ0/2 + θ1)
///                − 6 sin(3θ0/2 + θ1) + sin(θ0/2 + 2θ1) + sin(3θ0/2 + 2θ1)]}
///   C_{5−k}(θ0, θ1) = −C_k(θ1, θ0)   (reversal), which gives C3, C4, C5; in particular
///   C5 = −cos³(θ1/2) [sin(θ0 + θ1/2) − 3 sin(θ1/2)].
/// (The paper's C0, C1, C4, C5 agree; its C2 and C3 are damaged, ERRATA typical_curves-E7.)
/// Condition (29), corrected (ERRATA typical_curves-E8): sin(θ0 + θ1/2) − 3 sin(θ1/2) > 0 ⇔ C5 < 0,
/// whose boundary is eq (30): θ1 = 2 arccos((3 − cos θ0)/sqrt(10 − 6 cos θ0)).
///
/// Any cubic segment with Bézier points Q is the uniform segment of exactly one polygon:
///   P_{i+1} = 2Q1 − Q2, P_{i+2} = 2Q2 − Q1, P_i = 6Q0 − 4P_{i+1} − P_{i+2}, P_{i+3} = 6Q3 − P_{i+1} − 4P_{i+2},
/// so (29) applies to a segment of any cubic B-spline whose equivalent polygon has equal edges.
/// For endpoint-interpolating knots this polygon is R0 = 6P0 − 6P1 + P2, R2 = P1' = (3P1 − P2)/2,
/// P2, P3 for the first segment and P1', P2, P3, P4 for the second (appendix A.2).
///
/// Preconditions: finite angles in [0, π) for the closed forms; control polygons without
/// coincident consecutive points and with finite coordinates (InvalidInput otherwise).
#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

#include "cagd/analysis/curvature_monotonicity.hpp"
#include "cagd/spline/bspline.hpp"

namespace cagd::aesthetic {

/// The four points of a cubic Bézier segment, one per row.
using CubicPoints = Eigen::Matrix<double, 4, 2>;

/// The unit-edge polygon of the region plots: three edges of length 1 turning by θ0 and then θ1.
CubicPoints unit_edge_polygon(double theta0, double theta1);
CubicPoints uniform_segment_bezier(const CubicPoints& polygon);     ///< A.1
CubicPoints equivalent_uniform_polygon(const CubicPoints& bezier);  ///< the inverse of A.1

std::array<double, 6> monotonicity_coefficients(double theta0, double theta1);  ///< C0 … C5
double condition29(double theta0, double theta1);                               ///< sin(θ0 + θ1/2) − 3 sin(θ1/2)
double theta1_bound(double theta0);                                             ///< eq (30)

/// The endpoint-interpolating polygon of section 3.4 (Fig. 2 bottom) from a unit-edge polygon
/// Q0 … Qn (n ≥ 4): P_k = Q_k for 2 ≤ k ≤ n−2; P1 on Q2Q1 with |P1P2| = 2/3 and P0 on the line of
/// Q1Q0 with |P0P1| = cos θ0/3, θ0 the turn at Q1 (|θ0| < π/2); the end mirrored. Then R2 = P1' = Q1,
/// and the first segment's equivalent uniform polygon R0 R2 P2 P3 has unit edges and the turn 2θ0
/// at R2 (appendix A.2). InvalidInput for fewer than 5 points, zero edges or |θ0| ≥ π/2.
Eigen::MatrixXd endpoint_interpolating_polygon(const Eigen::MatrixXd& unit_polygon);

/// Fig. 7 classification of one (θ0, θ1) of the unit polygon: (29), the Bernstein signs, and the
/// exact sign of dκ/dt on [0, 1] (Bernstein subdivision of h from the closed-form C_i).
struct RegionPoint {
    bool condition29 = false;                               ///< sin(θ0 + θ1/2) − 3 sin(θ1/2) > 0
    bool all_negative = false;                              ///< every C_i < 0
    bool c0_negative = false;                               ///< C_0 < 0
    bool c4_negative = false;                               ///< C_4 < 0
    bool c5_negative = false;                               ///< C_5 < 0
    analysis::Trend exact = analysis::Trend::undetermined;  ///< the exact trend of κ on the segment
};
/// The verdicts for the unit-edge polygon with turning angles θ0, θ1.
RegionPoint classify_unit_polygon(double theta0, double theta1);
/// The n × n grid θ0 = lo + (hi − lo) i/(n−1) (rows i), θ1 likewise (columns j); n ≥ 2.
std::vector<RegionPoint> monotonicity_region(int n, double lo, double hi);

/// Cubic B-splines on the knots the paper uses: uniform (segments from P_i … P_{i+3}) and
/// endpoint-interpolating (knots 0,0,0,0,1,…,m,m,m,m).
BSplineCurve uniform_cubic_bspline(const Eigen::MatrixXd& control);
/// The cubic B-spline with these control points and endpoint-interpolating knots (appendix A.2).
BSplineCurve endpoint_interpolating_cubic_bspline(const Eigen::MatrixXd& control);

/// A verdict on curvature monotonicity: guaranteed, not guaranteed, or the test does not apply.
enum class Guarantee { monotone, not_guaranteed, not_applicable };
/// The name of a verdict ("monotone", …).
const char* to_string(Guarantee g);

/// The verdicts on one segment of a cubic B-spline.
struct SegmentVerdict {
    int segment = 0;                                            ///< the segment's index
    CubicPoints bezier;                                         ///< the segment's Bézier points
    CubicPoints polygon;                                        ///< the equivalent uniform polygon
    std::array<double, 3> edges{};                              ///< its edge lengths
    double turn0 = 0.0;                                         ///< its signed turning angle at the 2nd point
    double turn1 = 0.0;                                         ///< at the 3rd point
    bool equal_edges = false;                                   ///< |e_k − e_0| ≤ 1e-9 |e_0|
    Guarantee condition29_verdict = Guarantee::not_applicable;  ///< (29), equal edges, same-sign turns
    double condition29_value = 0.0;          ///< sin(θa + θb/2) − 3 sin(θb/2), θa = the larger |turn|
    std::array<double, 6> h_coefficients{};  ///< Bernstein coefficients of h
    Guarantee bernstein_verdict = Guarantee::not_guaranteed;  ///< all C_i strictly one sign
    analysis::Trend exact = analysis::Trend::undetermined;    ///< sign of dκ/dt on the segment
};
/// The verdicts on every segment and on the whole curve.
struct MonotonicityReport {
    std::vector<SegmentVerdict> segments;                         ///< one per segment
    analysis::Trend whole_curve = analysis::Trend::undetermined;  ///< all segments one trend
};
/// Any planar cubic B-spline (degree 3, dimension 2).
MonotonicityReport cubic_bspline_curvature_monotonicity(const BSplineCurve& curve);

}  // namespace cagd::aesthetic
