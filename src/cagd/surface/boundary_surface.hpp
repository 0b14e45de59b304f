#pragma once
/// @file
/// Hosaka's boundary-conforming surface between two space curves, and the joining of surfaces across
/// a section (hosaka sections 4–5, eq 31–43, with the journal's erratum Σ_{i=0}^m → Σ_{j=0}^m in
/// eq 37, 39, 40).
///
/// Synthesis (eq 31–33). Two boundary curves L_k (k = 0 lower, 1 upper) over one x range, in the
/// explicit form of eq (21): y = y_k(x), z = z_k(x), with the cross-boundary derivatives
/// ζ^{(0,j)}(x, y_k(x)) = φ_{0,j,k}(x), j = 1..m, prescribed (slopes, curvatures, … in y). The surface
///     ζ(x, y) = Σ_{j=0}^{m} l_y^j { ζ^{(0,j)}(x, y_0) p_j(v) + ζ^{(0,j)}(x, y_1) q_j(v) }           (31)
/// with v = (y − y_0(x))/l_y, l_y = y_1(x) − y_0(x): every section x = const is a Hermite curve of
/// eq (21) meeting both boundaries with the prescribed derivatives.
/// Characteristics (eq 34–38). ζ^{(i,j)}(x, y_k) = _kφ_{i,j}(x) obeys the recurrence
///     _kφ_{i,j}(x) = (d/dx) _kφ_{i−1,j}(x) − _kφ_{i−1,j+1}(x) · y_k'(x)                            (36)
/// (the chain rule along the boundary), started from _kφ_{0,j} = φ_{0,j,k} for j ≤ m and, for j > m,
/// from eq (37) at v = k (the y-derivatives of eq 31 at the boundary, by eq 7). Then (eq 34, 38)
///     ζ^{(i,n)}(x, y) = Σ_{j=0}^{m} l_y^{j−n} { _0φ_{i,j}(x) p_j^{(n)}(v) + _1φ_{i,j}(x) q_j^{(n)}(v) }
/// — the paper's induction claim, that the x-derivatives have the form of eq (31) again. It holds
/// because ∂v/∂x = {(v−1) y_0' − v y_1'}/l_y is linear in v, so x-differentiation keeps the degree
/// 2m+1 in v; the paper's proof is the identity (40) = 0 (see `identity40_bracket`).
/// `derivative` evaluates (38) with (36)–(37); `derivative_direct` differentiates (37) (eq 31 for
/// n = 0) in x directly, without (34) or (36), by Taylor arithmetic (numeric/taylor_jet.hpp): the two
/// agree to rounding (experiment `surfaces`, tests). The boundary functions are given with their
/// x-derivatives; ζ^{(i,n)} needs those up to order i.
///
/// Joining (eq 41–43). The section x = x0 of a synthesised surface S^A is the plane curve L2; a
/// second boundary L3: x = x3(y), z = z3(y) over the same y range [y_0(x0), y_1(x0)], with prescribed
/// x-derivatives ζ^{(i,0)}(x3(y), y), i = 1..m. The surface S^B between them is eq (31) with the roles
/// of x and y exchanged,
///     ζ(x, y) = Σ_{i=0}^{m} l_x^i { ζ^{(i,0)}(x0, y) p_i(u) + ζ^{(i,0)}(x3, y) q_i(u) },  u = (x − x0)/l_x,
/// l_x = x3(y) − x0 (eq 43), whose near-side data ζ^{(i,0)}(x0, y) are S^A's, from eq (34). S^A and S^B
/// then share ζ^{(i,n)} on x = x0 for i ≤ m and every n; order m+1 in x jumps in general.
///
/// Preconditions (InvalidInput): m ≥ 0; both boundaries over the same range (to 1e-12 relative),
/// x_min < x_max; m+1 functions φ per boundary; the curves must not cross or touch (y_1 > y_0 at 1025
/// equally spaced x, and at each evaluation); points with x in the range and y between the
/// boundaries (to 1e-9 of l_y); x3 > x0 over L3's range for joining, x0 inside S^A's range.
#include <functional>
#include <memory>
#include <vector>

#include "cagd/core/points.hpp"
#include "cagd/core/rational_polynomial.hpp"
#include "cagd/numeric/taylor_jet.hpp"
#include "cagd/spline/hosaka_basis.hpp"
#include "cagd/spline/hosaka_spline.hpp"

namespace cagd::surface {

/// f(x, k) = d^k f / dx^k at x, k ≥ 0.
using DerivativeFunction = std::function<double(double x, int k)>;

/// Simple boundary data with exact derivatives of every order.
DerivativeFunction constant_function(double c);
DerivativeFunction polynomial_function(std::vector<double> coefficients);  ///< Σ c_k x^k
DerivativeFunction sinusoid(double amplitude, double frequency, double phase,
                            double offset = 0);  ///< offset + A sin(ω x + φ)
/// Column `column` of an explicit spline (eq 21–23); piecewise cubic, so derivatives beyond 3 are 0
/// (at an interior abscissa, those of the interval to its right).
DerivativeFunction explicit_spline_function(std::shared_ptr<const spline::ExplicitSpline> spline, int column);

/// A boundary line of eq (31): y = y_k(x) over [x_min, x_max] with the cross-boundary derivatives ζ^{(0,j)} along it.
struct BoundaryCurve {
    double x_min = 0.0;                   ///< first x
    double x_max = 1.0;                   ///< last x
    DerivativeFunction y;                 ///< y_k(x)
    std::vector<DerivativeFunction> phi;  ///< phi[j] = ζ^{(0,j)}(x, y_k(x)), j = 0..m (phi[0] = z_k(x))
};

/// A boundary through points (x, y, z), x strictly increasing: y(x), z(x) the explicit spline of
/// eq (21)–(23); constant cross-boundary derivatives ζ^{(0,j)} = cross_derivatives[j−1], j = 1..m.
BoundaryCurve boundary_through_points(const PointList& xyz, const std::vector<double>& cross_derivatives);

/// Boundary-conforming synthesis (eq 31–40): the surface of order m between a lower and an upper boundary line.
class BoundaryConformingSurface {
public:
    /// The surface between `lower` and `upper` (the same x range, upper above lower) with phi of m + 1 functions each.
    BoundaryConformingSurface(int m, BoundaryCurve lower, BoundaryCurve upper);
    /// m.
    int m() const { return basis_.m(); }
    /// First x of the boundaries.
    double x_min() const { return lower_.x_min; }
    /// Last x of the boundaries.
    double x_max() const { return lower_.x_max; }
    /// y_0(x), the lower boundary.
    double y_lower(double x) const;
    /// y_1(x), the upper boundary.
    double y_upper(double x) const;
    /// ζ(x, y).
    double value(double x, double y) const { return derivative(x, y, 0, 0); }
    double derivative(double x, double y, int i, int n) const;         ///< ζ^{(i,n)}, eq (38)
    double characteristic(double x, int k, int i, int j) const;        ///< _kφ_{i,j}(x), eq (35)–(37)
    double derivative_direct(double x, double y, int i, int n) const;  ///< ζ^{(i,n)} without (34), (36)

private:
    spline::HosakaBasis basis_;
    BoundaryCurve lower_, upper_;
    struct Inputs {
        numeric::TaylorJet y[2];
        std::vector<numeric::TaylorJet> phi[2];
    };
    Inputs inputs(double x, int order) const;
    /// _kφ_{i,j} for j = 0..m at x (values), by (36)–(37).
    std::vector<double> characteristics(double x, int k, int i, int jmax) const;
    double section_v(double x, double y, const char* who) const;
};

/// The four brackets of eq (40), exact, for basis index j of order m: k = 0 multiplies ζ^{(i,j)}(x, y_0),
/// k = 1 multiplies ζ^{(i,j)}(x, y_1); s = 0 is the coefficient of y_0', s = 1 of y_1'. As derived:
///   k=0, s=0: −j p_j + p_{j−1} + p_j'·(v−1) + p_j^{(m+1)}(m, 0) p_m      k=0, s=1: j p_j − p_j'·v + p_j^{(m+1)}(m, 1)
///   q_m k=1, s=0: −j q_j + q_j'·(v−1) + q_j^{(m+1)}(m, 0) p_m                 k=1, s=1: j q_j + q_{j−1} − q_j'·v +
///   q_j^{(m+1)}(m, 1) q_m
/// (p_{−1} = q_{−1} = 0). The paper: "by (10) always 0" (erratum hosaka-E7 for the printed form).
RationalPolynomial identity40_bracket(int m, int j, int k, int s);

/// Two surfaces joined across the section x = x0 (eq 41–43): S^B continues `a` beyond the section.
class SectionJoinedSurface {
public:
    /// `far` is L3 with x and y exchanged: far.x_min..x_max is its y range, far.y(y) = x3(y),
    /// far.phi[0](y) = z3(y), far.phi[i](y) = ζ^{(i,0)}(x3(y), y).
    SectionJoinedSurface(const BoundaryConformingSurface& a, double x0, BoundaryCurve far);
    /// The section's x.
    double x0() const { return x0_; }
    /// First y of the joined part.
    double y_min() const { return joined_->x_min(); }
    /// Last y of the joined part.
    double y_max() const { return joined_->x_max(); }
    /// x3(y), the far boundary.
    double x_far(double y) const { return joined_->y_upper(y); }
    /// ζ(x, y).
    double value(double x, double y) const { return derivative(x, y, 0, 0); }
    /// ζ^{(i,n)}(x, y).
    double derivative(double x, double y, int i, int n) const { return joined_->derivative(y, x, n, i); }

private:
    std::shared_ptr<const BoundaryConformingSurface> a_, joined_;
    double x0_;
};

}  // namespace cagd::surface
