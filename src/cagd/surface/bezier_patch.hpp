#pragma once
// Tensor-product Bézier patches S(u, v) = Σ_i Σ_j B_{i,m}(u) B_{j,n}(v) P_{i,j}, u, v ∈ [0, 1]
// (typical_curves section 5, Fig. 6: bi-degree 24), with derivatives to 2nd order:
//   S_u  = m Σ_i Σ_j B_{i,m−1}(u) B_{j,n}(v) (P_{i+1,j} − P_{i,j}),   S_uu with m(m−1) and Δ²,
//   S_uv = m n Σ Σ B_{i,m−1}(u) B_{j,n−1}(v) ΔuΔv P_{i,j},   and symmetrically in v.
// Basis values come from core/bernstein_basis_values (O(degree), stable for any degree), so a
// point costs O(mn) per quantity. `evaluate_grid` evaluates the six quantities on a grid
// u_a × v_b by matrix products Bu · P · Bvᵀ (per coordinate), O(#u·mn + #u·#v·n) in all.
// The net is stored one matrix per coordinate: coordinate c of P_{i,j} is net[c](i, j).
// jet_de_casteljau is the independent reference for both.
// Preconditions (InvalidInput): three (m+1)×(n+1) coordinate matrices of one size, m, n ≥ 0,
// finite entries; u, v ∈ [0, 1].
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "cagd/analysis/surface_curvature.hpp"

namespace cagd::surface {

using ControlNet = std::array<Eigen::MatrixXd, 3>;

struct SurfaceGrid {
    // quantity[k][c](a, b): k = 0 S, 1 S_u, 2 S_v, 3 S_uu, 4 S_uv, 5 S_vv; c the coordinate.
    std::array<std::array<Eigen::MatrixXd, 3>, 6> quantity;
    analysis::SurfaceJet2 jet(Eigen::Index a, Eigen::Index b) const;
};

class BezierPatch {
public:
    explicit BezierPatch(ControlNet net);
    int degree_u() const { return static_cast<int>(net_[0].rows()) - 1; }
    int degree_v() const { return static_cast<int>(net_[0].cols()) - 1; }
    const ControlNet& net() const { return net_; }
    Eigen::Vector3d control_point(int i, int j) const;

    analysis::SurfaceJet2 jet(double u, double v) const;
    // Reference path: de Casteljau along v for every row of the net, then along u (spline/bezier),
    // O(mn(m + n)) per point — independent of the basis-matrix route.
    analysis::SurfaceJet2 jet_de_casteljau(double u, double v) const;
    SurfaceGrid evaluate_grid(const std::vector<double>& us, const std::vector<double>& vs) const;

private:
    ControlNet net_;
};

}  // namespace cagd::surface
