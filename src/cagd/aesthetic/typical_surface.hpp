#pragma once
/// @file
/// Nonstationary typical surfaces (typical_curves section 5, Fig. 6).
///
/// A control net P_{i,j} (i = 0 … m, j = 0 … n) whose edges keep their lengths across each control
/// polygon: |P_{i,j+1}P_{i+1,j+1}| = |P_{i,j}P_{i+1,j}| and |P_{i+1,j}P_{i+1,j+1}| = |P_{i,j}P_{i,j+1}|.
/// Given P_{i,j}, P_{i+1,j}, P_{i,j+1}, these two conditions leave P_{i+1,j+1} one degree of freedom,
/// the rotation about the diagonal axis through P_{i+1,j} and P_{i,j+1}: we start from the
/// parallelogram point P_{i+1,j} + P_{i,j+1} − P_{i,j} and turn it by the angle φ_{i,j},
/// right-handed about the direction P_{i,j+1} − P_{i+1,j}:
///   P_{i+1,j+1} = D + Rot(a, φ_{i,j}) (P_{i+1,j} + P_{i,j+1} − P_{i,j} − D),  D = P_{i+1,j}, a the axis.
/// (φ = 0 everywhere: P_{i,j} = P_{i,0} + P_{0,j} − P_{0,0}, a translation surface.) The boundary rows
/// P_{i,0} and P_{0,j} are given; each point depends only on its three predecessors, so the net is
/// independent of the order of construction. The paper prints the second condition as
/// |P_{i,j}P_{i+1,j+1}| = |P_{i+1,j}P_{i+1,j+1}| — ERRATA typical_curves-E15: the rotation about the
/// diagonal, which the paper describes, keeps the adjacent edge instead.
///
/// log_aesthetic_typical_net(α_u, α_v, L, degree, φ): the Fig. 6 construction. P_{i,0} is the scale-1
/// typical polygon approximating eq (15) with α_u (aesthetic/typical_bezier) in the x–z plane,
/// P_{0,j} the one for α_v in the y–z plane (planar (x, y) ↦ (x, 0, y) and (0, x, y)), both starting
/// at the origin along +x and +y with edge length L/degree; every φ_{i,j} = φ.
///
/// Preconditions (InvalidInput naming the value): boundaries of equal dimension 3 with at least two
/// points each, sharing P_{0,0} (to 1e-12 of their size), no zero-length edge, finite; angles finite;
/// a non-degenerate diagonal (P_{i+1,j} ≠ P_{i,j+1}).
#include <Eigen/Dense>

#include "cagd/surface/bezier_patch.hpp"

namespace cagd::aesthetic {

/// The fourth point of one control polygon (the rotation about its diagonal).
Eigen::Vector3d rotated_fourth_point(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10, const Eigen::Vector3d& p01,
                                     double angle);

/// u_boundary: (m+1)×3, the points P_{i,0}; v_boundary: (n+1)×3, the points P_{0,j}.
surface::ControlNet typical_surface_net(const Eigen::MatrixXd& u_boundary, const Eigen::MatrixXd& v_boundary,
                                        double angle);
/// The nonstationary typical surface net of typical_curves section 5: scale-1 typical polygons for α_u and α_v as its
/// boundaries (degree n, polygon length `length`), every further point turned by `angle`.
surface::ControlNet log_aesthetic_typical_net(double alpha_u, double alpha_v, double length, int degree, double angle);

}  // namespace cagd::aesthetic
