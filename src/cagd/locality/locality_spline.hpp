#pragma once
/// @file
/// S-splines and B2-splines as interpolating curves with controllable locality
/// (paper `sb2_locality`: M. Kuroda, S. Furukawa, F. Kimura, "S-splines and B2-splines as
/// Interpolating Curves with Controllable Locality", IPSJ Journal, accepted 1993).
///
/// Data p_i at parameter u = i (uniform). Each segment [i, i+1] gets one extra control
/// point d_{2i+1}; the interpolation points p_i are the other controls. Two carriers:
///   B2-spline (eq 1–4): cubic B-spline, knots u_{2i} = i, u_{2i+1} = i + 1/2, controls d_j;
///       d_{2i} from  e(−½) d_{2i−1} + e(0) d_{2i} + e(½) d_{2i+1} = p_i        (eq 3: 1,4,1 /6)
///   S-spline (eq 5–8): quartic B-spline, every integer knot double, controls d̂_j;
///       d̂_{2i} from f̂(1) d̂_{2i−1} + ê(0) d̂_{2i} + f̂(0) d̂_{2i+1} = p_i    (eq 7: 1,2,1 /4)
/// The relation coefficients are taken from the basis functions themselves (not typed), so
/// eq (3) and (7) are checked, not assumed. Evaluation is by this conversion to B-spline
/// form (section 2.3), through cagd::BSplineCurve.
///
/// Extra control point of segment i (eq 12), α = −2 + √3 (eq 11), q_{i,j} = (p_{i−j} + p_{i+j+1})/2:
///   d_{2i+1,m} = (1 − α)/(1 − α^{m+1}) Σ_{j=0}^{m} α^j q_{i,j}.
/// An m-vector gives one m per segment, or a pair (m_left, m_right). Our reading of the pair
/// (the paper names it, without a formula): the same α^j weights, p_{i−j} for j ≤ m_left and
/// p_{i+1+j} for j ≤ m_right, normalised to sum 1 — it reduces to eq (12) when the two agree.
/// m → ∞ gives the conventional cubic B-spline interpolant of eq (10).
/// Earlier rules of section 3.4 are available for comparison: I (eq 15) = q_{i,0};
/// II(a) (eq 16) = 5/4 q_{i,0} − 1/4 q_{i,1}; II(b) FMILL (eq 17).
///
/// Ends (section 3.3), through virtual points p_{−k}, p_{n−1+k} (k = 1..m+1 and beyond):
///   natural   p_{−k} = 2 p_0 − p_k                       (point symmetry: zero end curvature)
///   tangent   p_{−k} = mirror image of p_k in the plane through p_0 ⟂ t (end tangent ∥ t)
///   bessel    `tangent` with t from the parabola through p_0, p_1, p_2 (Bessel end condition)
/// Indices beyond the far end are reflected again, so any m works on any n ≥ 2 points.
/// The virtual segments −1 and n−1 take the m of their real neighbour with left/right swapped
/// (the mirror image of that neighbour), which is what makes the end promises exact.
/// Closed curves: indices taken modulo n, m-vector of length n.
///
/// Preconditions (InvalidInput): ≥ 2 points (≥ 3 closed), finite, consecutive distinct;
/// 0 ≤ m ≤ 1000; m-vector of length 1 or the number of segments; tangent vectors finite,
/// non-zero, of the points' dimension; FMILL needs p_{i−1} ≠ p_{i+1}.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "cagd/core/points.hpp"
#include "cagd/spline/bspline.hpp"

namespace cagd::locality {

/// The carrier: B2-spline (cubic, knots at halves) or S-spline (quartic, double knots).
enum class SplineForm { b2_spline, s_spline };

/// The locality of one segment: m on its left and on its right (equal unless an m-vector gives a pair).
struct SegmentLocality {
    int left = 0;   ///< m_left: points p_{i−j}, j ≤ m_left
    int right = 0;  ///< m_right: points p_{i+1+j}, j ≤ m_right
};
/// One SegmentLocality for all segments, or one per segment.
using MVector = std::vector<SegmentLocality>;

/// The end condition of section 3.3 (see above).
enum class EndKind { natural, tangent, bessel };
/// The end condition at one end.
struct EndCondition {
    EndKind kind = EndKind::natural;  ///< natural, tangent or Bessel
    Eigen::VectorXd tangent;          ///< used by EndKind::tangent
};

/// How the extra control point of a segment is chosen: eq (12) with locality m, or an earlier rule of section 3.4.
enum class ExtraPointRule { locality, method_I, method_IIa, fmill };

/// The options of an S- or B2-spline interpolant.
struct Options {
    SplineForm form = SplineForm::s_spline;          ///< the carrier
    MVector m = MVector(1, SegmentLocality{2, 2});   ///< one entry (all segments) or one per segment
    bool closed = false;                             ///< a closed curve
    EndCondition start;                              ///< the condition at the first point
    EndCondition end;                                ///< the condition at the last point
    ExtraPointRule rule = ExtraPointRule::locality;  ///< the extra-point rule
};

/// The interpolant and its extra control points.
struct LocalitySpline {
    BSplineCurve curve;            ///< parameter u ∈ [0, n−1] (open) or [0, n] (closed)
    Eigen::MatrixXd extra_points;  ///< d_{2i+1} for segments i = −1 .. n−1 (open), 0..n (closed)
    int first_segment = -1;        ///< segment index of extra_points row 0
};

/// The largest locality m accepted.
constexpr int kMaxLocality = 1000;

/// α of eq (11): −2 + √3, the root of α² + 4α + 1 = 0 inside (−1, 0).
double alpha();

/// Weights of the barycentric combination for one segment: `left(j)` multiplies p_{i−j},
/// `right(j)` multiplies p_{i+1+j}. They sum to 1.
struct SegmentWeights {
    Eigen::VectorXd left;   ///< left(j) multiplies p_{i−j}
    Eigen::VectorXd right;  ///< right(j) multiplies p_{i+1+j}
};
/// The weights of eq (12) (or of the pair's reading above) for one segment's locality.
SegmentWeights extra_point_weights(SegmentLocality m);

/// Eq (13): (d_{2i−1,m} + 4 d_{2i+1,m} + d_{2i+3,m})/6 = w0 q_{i,0} + w1 q_{i,m} + w2 q_{i,m+1},
/// closed form (w0, w1, w2) = (1, −(1−α)α^{m+1}/6, (1−α)α^m/6) / (1 − α^{m+1}).  m ≥ 1.
Eigen::Vector3d truncation_weights(int m);
/// The same weights obtained independently: apply the (1,4,1)/6 stencil to the weight
/// vectors of eq (12) on p_{i−m−1} .. p_{i+m+2} and read off the coefficients of
/// q_{i,0}, q_{i,m}, q_{i,m+1}; also returns the largest coefficient left on any other q_{i,j}.
struct StencilWeights {
    Eigen::Vector3d weights;     ///< (w0, w1, w2)
    double largest_other = 0.0;  ///< the largest coefficient left on any other q_{i,j}
};
/// The weights of eq (13) by the stencil (see above), m ≥ 1.
StencilWeights truncation_weights_by_stencil(int m);

/// Parse "2" or "1,2,1:3,0" (l:r is a pair) into an MVector; InvalidInput names the token.
MVector parse_m_vector(const std::string& text);
/// The text form of an m-vector ("2", "1,2,1:3").
std::string format_m_vector(const MVector& m);

/// The interpolating curve (the whole construction: virtual points, eq (12), eq (3)/(7)).
LocalitySpline interpolate(const PointList& points, const Options& options);
/// The same through points validated already: the same curve, the points not checked again where
/// their checks cover this construction's (options.closed as they were validated).
LocalitySpline interpolate(const ValidPoints& points, const Options& options);

/// p_k for any integer k: the data point for 0 ≤ k ≤ n−1, otherwise the virtual point of
/// section 3.3 given by the options' end conditions (index modulo n for closed curves).
Eigen::RowVectorXd extended_point(const PointList& points, const Options& options, long k);

/// Basis functions of section 2 at u (derivative order k): e (B2 cubic, knots spaced ½,
/// support [−1, 1]), ê and f̂ (quartic, double knots, supports [−1, 1] and [−1, 2]).
double basis_e(double u, int k = 0);
/// ê of section 2 (S-spline, quartic).
double basis_e_hat(double u, int k = 0);
/// f̂ of section 2 (S-spline, quartic).
double basis_f_hat(double u, int k = 0);
/// Blending functions of eq (4) and (8): r = Σ g(u−i) p_i + Σ h(u−i) d_{2i+1}.
double blending_g(SplineForm form, double u, int k = 0);
/// h of eq (4) and (8).
double blending_h(SplineForm form, double u, int k = 0);
/// Coefficients of the relation (3)/(7) between p_i and the controls, from the basis:
/// p_i = side·d_{2i−1} + centre·d_{2i} + side·d_{2i+1}.
struct KnotRelation {
    double side;    ///< the coefficient of d_{2i±1}
    double centre;  ///< the coefficient of d_{2i}
};
/// The relation (3) or (7) of a carrier.
KnotRelation knot_relation(SplineForm form);

/// Interpolating blending function (Figs. 3, 4): the scalar interpolant of p_i = δ_{i0} on the
/// infinite line, for a uniform m; parameter u ∈ [−m−3, m+3] (support [−m−2, m+2]).
BSplineCurve interpolating_blending_function(SplineForm form, int m);

/// The conventional interpolating cubic B-spline of eq (10) (uniform parameter), natural
/// ends (c_0 = p_0, c_{−1} = 2p_0 − c_1; zero end curvature) or closed, solved as the
/// banded linear system it is (Eigen SparseLU). Knots at integers, u ∈ [0, n−1] or [0, n].
BSplineCurve cubic_bspline_interpolant(const PointList& points, bool closed);

/// The Bessel end tangent at p_0 (from p_0, p_1, p_2) pointing into the curve; at the last
/// point pass the points reversed.
Eigen::VectorXd bessel_tangent(const PointList& points);

}  // namespace cagd::locality
