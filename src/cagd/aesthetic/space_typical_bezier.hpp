#pragma once
/// @file
/// Nonstationary typical Bézier space curves (typical_curves section 4, eq 33–37).
///
/// Scale factor 1, n edges of length Δs = L/n. Edge j points along t_j, the first column of the
/// frame F_j = [t_j n_j b_j]; F_0 = I (t = e_x, n = e_y, b = e_z), b_0 = 0, b_{j+1} = b_j + Δs t_j.
/// The frame is moved by the transition matrix expressed in the frame itself (t, n, b ↔ x, y, z):
///   F_{j+1} = F_j T_j,   T_j = R_κ(Δθ_κ,j) ⊗ R_τ(Δθ_τ,j)                               (eq 36–37)
///   Δθ_κ,j = θ_κ((j+1)Δs) − θ_κ(jΔs),  Δθ_τ,j = θ_τ((j+1)Δs) − θ_τ(jΔs),   j = 0 … n−2,
/// R_κ the rotation about b (z) turning t towards n, R_τ the rotation about t (x) turning n towards
/// b, θ_κ, θ_τ of eq (34)–(35). With Alexa's ⊗ (numeric/alexa_product), T_j is the rotation by the
/// vector (Δθ_τ,j, 0, Δθ_κ,j): the frame turns about the Darboux vector τt + κb, exactly as the
/// Frenet–Serret equations (33) move it over one step when κ/τ is constant on it. The polygon is a
/// first-order (Lie–Euler) discretisation of the log-aesthetic space curve: its vertices b_j
/// approach C(jΔs) like O(Δs).
/// The paper's sequential alternatives are kept to compare: kappa_then_tau (T = R_κ R_τ) and
/// tau_then_kappa (T = R_τ R_κ).
///
/// What the polygon's own discrete Frenet data are (polygon_frenet_angles): the turning angle φ_j
/// between edges j and j+1 and the dihedral angle ψ_j between the planes (e_j, e_{j+1}) and
/// (e_{j+1}, e_{j+2}) (signed about e_{j+1}); n − 1 turning angles, n − 2 dihedral angles — one fewer
/// than the torsion rotations, so one torsion rotation can never show: with tau_then_kappa,
/// ψ_j = Δθ_τ,j+1 exactly and the first torsion rotation only turns the initial frame about t_0 (a
/// rigid motion — the paper's observation that the first three control points fix the osculating
/// plane); with kappa_then_tau ψ_j = Δθ_τ,j and the last one is lost; with ⊗, whose rotation is
/// R_τ(½Δθ_τ) R_κ(Δθ_κ) R_τ(½Δθ_τ) up to third order in the angles (symmetric splitting),
/// ψ_j ≈ ½(Δθ_τ,j + Δθ_τ,j+1): half of the first and half of the last are lost.
///
/// Preconditions (InvalidInput naming the value): degree ≥ 3 (a torsion needs four control points),
/// the parameters of LogAestheticSpaceCurve; rotation lists of equal length n − 1 with finite
/// entries of modulus < π; edge length finite > 0; an orthonormal right-handed initial frame.
#include <Eigen/Dense>
#include <vector>

#include "cagd/aesthetic/log_aesthetic_space_curve.hpp"

namespace cagd::aesthetic {

/// How R_κ and R_τ combine in a frame's transition: Alexa's product (eq 37) or one after the other.
enum class FrenetComposition { alexa, kappa_then_tau, tau_then_kappa };
/// The name of a composition ("alexa", …).
const char* to_string(FrenetComposition c);

Eigen::Matrix3d curvature_rotation(double angle);  ///< R_κ of eq (36): about z (b)
Eigen::Matrix3d torsion_rotation(double angle);    ///< R_τ of eq (36): about x (t)
/// The transition of a frame by the curvature angle and the torsion angle, composed as asked.
Eigen::Matrix3d frenet_transition(double curvature_angle, double torsion_angle, FrenetComposition c);

/// A typical Bézier space polygon: its points, frames and rotations.
struct SpaceTypicalPolygon {
    Eigen::MatrixXd points;                   ///< (n + 1) × 3
    std::vector<Eigen::Matrix3d> frames;      ///< F_0 … F_{n−1}
    std::vector<double> curvature_rotations;  ///< Δθ_κ,j, j = 0 … n−2
    std::vector<double> torsion_rotations;    ///< Δθ_τ,j, j = 0 … n−2
    double edge_length = 0.0;                 ///< Δs
};

/// The space typical polygon of degree n approximating the log-aesthetic space curve p (eq 36).
SpaceTypicalPolygon space_typical_polygon(const LogAestheticSpaceParameters& p, int degree,
                                          FrenetComposition composition = FrenetComposition::alexa);
/// The same construction from given rotation angles (n − 1 of each) and edge length.
SpaceTypicalPolygon space_typical_polygon_from_rotations(
    const std::vector<double>& curvature_rotations, const std::vector<double>& torsion_rotations, double edge_length,
    FrenetComposition composition = FrenetComposition::alexa,
    const Eigen::Matrix3d& initial_frame = Eigen::Matrix3d::Identity());

/// The discrete Frenet angles of a space polygon.
struct PolygonFrenetAngles {
    std::vector<double> turning;   ///< φ_j ∈ [0, π], j = 0 … n−2
    std::vector<double> dihedral;  ///< ψ_j ∈ (−π, π], j = 0 … n−3 (positive: right-handed about e_{j+1})
};
/// Preconditions: ≥ 4 points in 3-D, no zero edge, no two consecutive edges parallel.
PolygonFrenetAngles polygon_frenet_angles(const Eigen::MatrixXd& points);

}  // namespace cagd::aesthetic
