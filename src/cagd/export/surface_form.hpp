#pragma once
/// @file
/// Surfaces in CAD form: a grid of tensor-product Bézier patches, and the one B-spline surface that
/// holds them (for STEP), for the surfaces whose form is exactly polynomial.
///
/// Cell (a, b) of the grid covers [u_a, u_{a+1}] × [v_b, v_{b+1}] and carries the net P_{i,j},
/// i = 0..p, j = 0..q, of S(u, v) = Σ_i Σ_j B_i^p(ū) B_j^q(v̄) P_{i,j}, ū, v̄ the local parameters in [0, 1].
///
/// Which surfaces, and how (each exact by construction, then measured):
///   typical_curves section 5, the typical surface: a BezierPatch is its own net (one cell).
///   hosaka eq (27), the tensor patch of order m: degree 2m + 1 in u and v. Every curve
///     u ↦ ∂^j S/∂v^j (u, l), j ≤ m, l ∈ {0, 1}, is a polynomial of degree 2m + 1 whose end jets are
///     the corner derivatives S_kl^{(i,j)}, i ≤ m, so its Bézier points come from
///     bezier_from_end_jets (spline/bezier.hpp); the Bézier points are then polynomials in v with
///     those jets at v = 0 and 1, and bezier_from_end_jets again gives the net.
///   hosaka eq (30), the Cartesian surface: the graph (x, y, ζ(x, y)) is, on each grid cell, the same
///     construction from the node derivatives l_x^i l_y^j ζ^{(i,j)}, with x and y linear.
///   hosaka eq (28), the edge-form patch (Coons for S0 = 0): polynomial where its four edges are
///     (Curve::polynomial_degree ≥ 0), of degree max(2m + 1, edge degrees) in each direction, with
///     the edges' breakpoints (mapped onto [0, 1]) as the grid. Each cell's net solves the tensor
///     interpolation at (p + 1) × (q + 1) Chebyshev points, N_u P N_vᵀ = S (per coordinate).
/// Every form is measured: `conversion_error` is the largest distance between the surface and the
/// patches at 7 × 7 points inside each cell that no construction used. `exact` holds when it is at
/// most 1e-12 of the net's bounding-box diagonal (rounding only).
///
/// The B-spline surface (bspline_surface) has every interior knot of full multiplicity (p in u, q
/// in v): the nets as they are, neighbours sharing their common row or column of control points
/// (taken from the lower cell; the mismatch is added to the conversion error). Exact, and read by
/// every reader; fewer knots are possible where the surface is smoother (hosaka eq 30 is C^m).
///
/// Not polynomial, so not here: the boundary-conforming and joined surfaces (hosaka eq 31–43, their
/// boundaries are arbitrary functions) and the smoothing plates (written as grids only).
/// Preconditions (InvalidInput): planar data (2 coordinates) get z = 0; an edge-form patch whose
/// edges are not all polynomial is rejected naming the edge.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "cagd/surface/bezier_patch.hpp"
#include "cagd/surface/hosaka_patch.hpp"

namespace cagd::exports {

/// The most control points a surface's patches hold (cells × (p + 1)(q + 1)): 240 MB of coordinates,
/// built in under a minute; to_bezier refuses more before it builds any (InvalidInput naming the
/// cells and degrees), and the surface document's reader refuses more.
inline constexpr long long kMaxSurfaceControlPoints = 10'000'000;

/// A grid of Bézier patches of one bi-degree (see above).
struct BezierSurfacePieces {
    int degree_u = 0;              ///< p
    int degree_v = 0;              ///< q
    std::vector<double> u_breaks;  ///< u_0 < … < u_K
    std::vector<double> v_breaks;  ///< v_0 < … < v_L
    /// The nets, cell (a, b) at index a + K b; each (p + 1) × (q + 1) per coordinate (x, y, z).
    std::vector<surface::ControlNet> nets;
    /// K, the cells along u.
    int cells_u() const { return static_cast<int>(u_breaks.size()) - 1; }
    /// L, the cells along v.
    int cells_v() const { return static_cast<int>(v_breaks.size()) - 1; }
    /// The net of cell (a, b).
    const surface::ControlNet& net(int a, int b) const { return nets[static_cast<std::size_t>(a + cells_u() * b)]; }
    /// S(u, v), (u, v) inside the grid (the cell to the lower side on a break).
    Eigen::Vector3d point(double u, double v) const;
};

/// A surface's patches and how well they hold it.
struct SurfaceForm {
    BezierSurfacePieces pieces;     ///< the patches
    double conversion_error = 0.0;  ///< measured (see above)
    bool exact = false;             ///< conversion_error ≤ 1e-12 of the net's diagonal
};

/// The typical surface's own net: the patch is a Bézier patch, copied (exact, conversion_error 0).
SurfaceForm to_bezier(const surface::BezierPatch& patch);
/// Hosaka's tensor patch, eq (27).
SurfaceForm to_bezier(const surface::HosakaPatch& patch);
/// Hosaka's Cartesian surface, eq (30), as the graph (x, y, ζ): a cell per grid cell, in x and y.
SurfaceForm to_bezier(const surface::CartesianSurface& surface);
/// Hosaka's edge-form patch, eq (28); InvalidInput when an edge is not polynomial.
SurfaceForm to_bezier(const surface::EdgeFormPatch& patch);

/// A B-spline surface: clamped knots in u and v, (n_u × n_v) control points per coordinate.
struct BSplineSurface {
    int degree_u = 0;             ///< p
    int degree_v = 0;             ///< q
    std::vector<double> knots_u;  ///< n_u + p + 1 knots
    std::vector<double> knots_v;  ///< n_v + q + 1 knots
    surface::ControlNet control;  ///< x, y, z, each n_u × n_v
};
/// The patches as one B-spline surface (see above); `mismatch` receives the largest distance
/// between the rows or columns that neighbouring nets share (0 for a continuous surface).
BSplineSurface bspline_surface(const BezierSurfacePieces& pieces, double* mismatch = nullptr);

/// The bounding-box diagonal of all the nets' control points.
double net_diagonal(const BezierSurfacePieces& pieces);

}  // namespace cagd::exports
