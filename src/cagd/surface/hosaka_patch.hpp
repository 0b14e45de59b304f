#pragma once
/// @file
/// Hosaka's surface patches from corner derivatives and from edge curves (hosaka section 4,
/// eq 25–30, with the journal's erratum to eq 29, S0(n, v) → S0(u, v)).
///
/// Tensor patch (eq 27), u, v ∈ [0, 1]:
///     S(u, v) = Σ_{i=0}^{m} Σ_{j=0}^{m} { S_00^{(i,j)} p_i(u) p_j(v) + S_01^{(i,j)} p_i(u) q_j(v)
///                                       + S_10^{(i,j)} q_i(u) p_j(v) + S_11^{(i,j)} q_i(u) q_j(v) }
/// S_kl^{(i,j)} = ∂^{i+j} S / ∂u^i ∂v^j at the corner (u, v) = (k, l); p_i, q_i = p_i(m, ·), q_i(m, ·)
/// of eq (2). It interpolates every corner derivative with i, j ≤ m. Any dimension, any m ≥ 0.
///
/// Edge-curve form (eq 28) with the edge curves R1(u) = S(u, 0), R2(v) = S(0, v), R3(u) = S(u, 1),
/// R4(v) = S(1, v), each taken relative to its own start (the paper puts the origin at S(0, 0)), their
/// chords R11 = R1(1) − R1(0), …, R41 (so R11 + R41 = R21 + R31), and f(t) = q_0(m, t):
///     S(u, v) = S(0,0) + R1(u) + {R3(u) − R1(u)} f(v) + R2(v) + {R4(v) − R2(v)} f(u)
///               + ½ f(u) f(v) {R11 + R21 − R31 − R41} + S0(u, v)                          (28)
/// (braces corrected: erratum hosaka-E5), S0 the terms of eq (27) with i, j ≥ 1 (for m = 1, eq 29:
/// S0 = T00 g(u)g(v) + T01 g(u)h(v) + T10 g(v)h(u) + T11 h(u)h(v), T_λμ = S^{(1,1)}(λ, μ)). With
/// S0 = 0 it is Coons' surface (blending 1 − f, f); every corner cross derivative S^{(i,j)}, i, j ≥ 1,
/// then vanishes ("zero twist"). Edges may be any Curve; each is mapped linearly from its own
/// parameter interval onto [0, 1] (derivatives scaled accordingly).
///
/// Cartesian patch (eq 30) over a grid x_0 < … < x_I, y_0 < … < y_J: on the cell [x_a, x_{a+1}] ×
/// [y_b, y_{b+1}] with l_x, l_y its sides and u = (x − x_a)/l_x, v = (y − y_b)/l_y,
///     ζ(x, y) = Σ_{i,j} l_x^i l_y^j { ζ_00^{(i,j)} p_i(u) p_j(v) + ζ_01^{(i,j)} p_i(u) q_j(v)
///                                   + ζ_10^{(i,j)} q_i(u) p_j(v) + ζ_11^{(i,j)} q_i(u) q_j(v) }
/// (the printed sign of the last term is "−": erratum hosaka-E6), ζ^{(i,j)} the node derivatives in
/// x and y. Neighbouring cells share the node data of their common edge, so ζ^{(a,b)} is continuous
/// across grid lines for a ≤ m (across x = const) and b ≤ m (across y = const).
/// `cartesian_spline_surface` fills the node data for m = 1 from heights alone, as section 7 (iv)
/// suggests: ζ^{(1,0)} from the spline of eq (23) along each grid row, ζ^{(0,1)} along each column,
/// ζ^{(1,1)} from the spline of the ζ^{(1,0)} along each column (de Boor's bicubic spline).
///
/// Preconditions (InvalidInput): m ≥ 0; finite data of one dimension; derivative orders ≥ 0;
/// u, v ∈ [0, 1], (x, y) inside the grid; edges meeting at the four corners (to 1e-9 of their size);
/// grid abscissae strictly increasing, at least two per direction.
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/core/points.hpp"
#include "cagd/spline/hosaka_basis.hpp"
#include "cagd/spline/hosaka_spline.hpp"

namespace cagd::surface {

/// S_kl^{(i,j)} for k, l ∈ {0, 1}, i, j = 0..m, each a vector of `dimension` coordinates (zero at first).
class CornerDerivatives {
public:
    /// Storage for the derivatives ζ^{(i,j)} (i, j = 0..m) at the four corners (k, l) ∈ {0, 1}², vectors of `dimension`
    /// coordinates, all zero.
    CornerDerivatives(int m, int dimension);
    /// m.
    int m() const { return m_; }
    /// Coordinates per derivative.
    int dimension() const { return dimension_; }
    /// The derivative S^{(i,j)} at corner (k, l), writable.
    Eigen::VectorXd& at(int k, int l, int i, int j);
    /// The derivative S^{(i,j)} at corner (k, l).
    const Eigen::VectorXd& at(int k, int l, int i, int j) const;

private:
    int m_, dimension_;
    std::vector<Eigen::VectorXd> data_;
    std::size_t index(int k, int l, int i, int j) const;
};

/// The four edge curves of a patch, each on [0, 1].
struct PatchEdges {
    std::shared_ptr<const Curve> r1;  ///< R1(u) = S(u, 0)
    std::shared_ptr<const Curve> r2;  ///< R2(v) = S(0, v)
    std::shared_ptr<const Curve> r3;  ///< R3(u) = S(u, 1)
    std::shared_ptr<const Curve> r4;  ///< R4(v) = S(1, v)
};

/// The tensor patch of eq (27): Σ p/q(u) p/q(v) of the corner derivatives, order m.
class HosakaPatch {
public:
    /// The patch of the given corner derivatives.
    explicit HosakaPatch(CornerDerivatives corners);
    /// m.
    int m() const { return corners_.m(); }
    /// The corner derivatives.
    const CornerDerivatives& corners() const { return corners_; }
    /// S(u, v).
    Eigen::VectorXd point(double u, double v) const { return derivative(u, v, 0, 0); }
    Eigen::VectorXd derivative(double u, double v, int a, int b) const;  ///< S^{(a,b)}(u, v)
    /// Edge curve 1..4 (R1(u) = S(u,0), R2(v) = S(0,v), R3(u) = S(u,1), R4(v) = S(1,v)) on [0, 1].
    spline::HosakaCurve edge(int which) const;
    PatchEdges edges() const;  ///< all four, for the edge-curve form

private:
    CornerDerivatives corners_;
    spline::HosakaBasis basis_;
};

/// The edge-curve form of eq (28): the patch through four edge curves with a corner correction S0.
class EdgeFormPatch {
public:
    /// S0 from the corner derivatives with i, j ≥ 1 of `twists` (its other entries are ignored).
    EdgeFormPatch(int m, PatchEdges edges, CornerDerivatives twists);
    /// S0 = 0: Coons' surface.
    EdgeFormPatch(int m, PatchEdges edges);
    /// m.
    int m() const { return basis_.m(); }
    /// The four edge curves.
    const PatchEdges& edges() const { return edges_; }
    /// S(u, v).
    Eigen::VectorXd point(double u, double v) const { return derivative(u, v, 0, 0); }
    /// S^{(a,b)}(u, v).
    Eigen::VectorXd derivative(double u, double v, int a, int b) const;

private:
    spline::HosakaBasis basis_;
    PatchEdges edges_;
    CornerDerivatives twists_;
    Eigen::VectorXd corner_term_;  ///< ½ {R11 + R21 − R31 − R41}
};

/// Coons' bicubically blended patch in Coons' own Boolean-sum form, P_u ⊕ P_v = P_u + P_v − P_u P_v
/// with blending functions 1 − f, f (f = q_0(m, ·)): the surface eq (28) with S0 = 0 claims to equal.
Eigen::VectorXd coons_boolean_sum(const PatchEdges& edges, int m, double u, double v);

/// The edges of `edges` evaluated on [0, 1] (row k: k-th derivative), as eq (28) sees them.
Eigen::MatrixXd unit_edge_jet(const Curve& edge, double s, int order);

/// The Cartesian patch of eq (30): ζ(x, y) over a rectangular grid from node derivatives, order m.
class CartesianSurface {
public:
    /// node_derivatives[a + (I+1) b] (node (x_a, y_b)): (m+1) × (m+1) matrix, entry (i, j) = ζ^{(i,j)}.
    CartesianSurface(int m, std::vector<double> x, std::vector<double> y,
                     std::vector<Eigen::MatrixXd> node_derivatives);
    /// m.
    int m() const { return basis_.m(); }
    /// The grid's x lines.
    const std::vector<double>& x() const { return x_; }
    /// The grid's y lines.
    const std::vector<double>& y() const { return y_; }
    /// ζ(x, y).
    double value(double x, double y) const { return derivative(x, y, 0, 0); }
    double derivative(double x, double y, int a, int b) const;  ///< ζ^{(a,b)}(x, y)
    /// The same on cell (cx, cy) at local (u, v) ∈ [0, 1]² (one-sided values on the cell's edges).
    double derivative_in(int cx, int cy, double u, double v, int a, int b) const;
    /// The node derivatives of node (x_a, y_b): entry (i, j) = ζ^{(i,j)}.
    const Eigen::MatrixXd& node(int a, int b) const;

private:
    spline::HosakaBasis basis_;
    std::vector<double> x_, y_;
    std::vector<Eigen::MatrixXd> nodes_;
};

/// Edges through point lists (2-D or 3-D): each the C2 spline of eq (20) (chord scale, natural ends);
/// bottom = R1 (v = 0), left = R2 (u = 0), top = R3 (v = 1), right = R4 (u = 1). The corners must
/// coincide (EdgeFormPatch checks it).
PatchEdges edges_through_points(const PointList& bottom, const PointList& left, const PointList& top,
                                const PointList& right);

/// m = 1 Cartesian surface through heights z(a, b) = ζ(x_a, y_b) (rows: x, columns: y), node
/// derivatives from natural splines (eq 23) along the grid lines as described above.
CartesianSurface cartesian_spline_surface(const std::vector<double>& x, const std::vector<double>& y,
                                          const Eigen::MatrixXd& z);
/// The same from rows (x, y, z) in any order that cover a rectangular grid exactly once.
CartesianSurface cartesian_spline_surface(const PointList& xyz);

/// Heights on a rectangular grid: z(a, b) = ζ(x_a, y_b) (rows: x, columns: y).
struct GridHeights {
    std::vector<double> x;  ///< the grid's x lines, ascending
    std::vector<double> y;  ///< the grid's y lines, ascending
    Eigen::MatrixXd z;      ///< z(a, b) at (x_a, y_b)
};
/// From rows (x, y, z) in any order; InvalidInput for non-finite rows, a node given twice or
/// points that do not cover the grid of their distinct x and y exactly once (a ragged grid).
GridHeights grid_from_points(const PointList& xyz);

}  // namespace cagd::surface
