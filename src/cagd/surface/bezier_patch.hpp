#pragma once
/// @file
/// Tensor-product Bézier patches S(u, v) = Σ_i Σ_j B_{i,m}(u) B_{j,n}(v) P_{i,j}, u, v ∈ [0, 1]
/// (typical_curves section 5, Fig. 6: bi-degree 24), with derivatives to 2nd order:
///   S_u  = m Σ_i Σ_j B_{i,m−1}(u) B_{j,n}(v) (P_{i+1,j} − P_{i,j}),   S_uu with m(m−1) and Δ²,
///   S_uv = m n Σ Σ B_{i,m−1}(u) B_{j,n−1}(v) ΔuΔv P_{i,j},   and symmetrically in v.
/// Basis values come from core/bernstein_basis_values (O(degree), stable for any degree), so a
/// point costs O(mn) per quantity. `evaluate_grid` evaluates the six quantities on a grid
/// u_a × v_b by matrix products Bu · P · Bvᵀ (per coordinate), O(#u·mn + #u·#v·n) in all.
/// The net is stored one matrix per coordinate: coordinate c of P_{i,j} is net[c](i, j).
/// jet_de_casteljau is the independent reference for both.
/// Preconditions (InvalidInput): three (m+1)×(n+1) coordinate matrices of one size, m, n ≥ 0,
/// finite entries; u, v ∈ [0, 1].
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "cagd/analysis/surface_curvature.hpp"

namespace cagd::surface {

/// A control net: x, y and z coordinates, each an (m + 1) × (n + 1) matrix.
using ControlNet = std::array<Eigen::MatrixXd, 3>;

/// A patch evaluated on a grid of (u, v): position and derivatives to second order.
struct SurfaceGrid {
    /// quantity[k][c](a, b): k = 0 S, 1 S_u, 2 S_v, 3 S_uu, 4 S_uv, 5 S_vv; c the coordinate.
    std::array<std::array<Eigen::MatrixXd, 3>, 6> quantity;
    /// The jet at grid point (us[a], vs[b]).
    analysis::SurfaceJet2 jet(Eigen::Index a, Eigen::Index b) const;
};

/// A tensor-product Bézier patch S(u, v) = Σ_i Σ_j B_i^m(u) B_j^n(v) P_ij on [0, 1]².
class BezierPatch {
public:
    /// The patch of a control net (all three matrices of one size, finite entries).
    explicit BezierPatch(ControlNet net);
    /// m, the degree in u.
    int degree_u() const { return static_cast<int>(net_[0].rows()) - 1; }
    /// n, the degree in v.
    int degree_v() const { return static_cast<int>(net_[0].cols()) - 1; }
    /// The control net.
    const ControlNet& net() const { return net_; }
    /// P_ij.
    Eigen::Vector3d control_point(int i, int j) const;

    /// S and its derivatives to second order at (u, v), through the Bernstein basis matrices.
    analysis::SurfaceJet2 jet(double u, double v) const;
    /// Reference path: de Casteljau along v for every row of the net, then along u (spline/bezier),
    /// O(mn(m + n)) per point — independent of the basis-matrix route.
    analysis::SurfaceJet2 jet_de_casteljau(double u, double v) const;
    /// The jets at every (us[a], vs[b]), sharing the basis values of each u and each v.
    SurfaceGrid evaluate_grid(const std::vector<double>& us, const std::vector<double>& vs) const;

private:
    ControlNet net_;
};

}  // namespace cagd::surface
