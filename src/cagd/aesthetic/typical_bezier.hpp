#pragma once
/// @file
/// Nonstationary typical Bézier control polygons that approximate log-aesthetic curves
/// (typical_curves section 3.1–3.3, eq 16–28).
///
/// Target: the normalised curve of eq (15), θ(s) = α s^e, e = (α − 1)/α, κ = (α − 1) s^{−1/α}.
///
/// Scale-1 construction (eq 16–17): n equal edges Δs = L/n with directions θ(jΔs), j = 0 … n−1:
///   b_0 = 0, b_{j+1} = b_j + Δs e^{iα(jΔs)^e}.   M_j = R_{φ_j},  φ_j = θ((j+1)Δs) − θ(jΔs).
/// (The paper's eq (17) writes the rotation between the directions at (j+1)Δs and (j+2)Δs, i.e.
/// φ_{j+1} — an index shift, see ERRATA typical_curves-E2.) First-order rotation (eq 18)
///   Δθ_j ≈ (α − 1) ((j+1)Δs)^{−1/α} Δs,  ratio Δθ_{j+1}/Δθ_j = ((j+1)/(j+2))^{1/α}   (eq 19).
/// Constant-rotation construction (eq 20–22): every rotation is Δθ and the edges are
///   Δs_j = (j+1)^{1/(α−1)} (|Δθ|/|α − 1|)^{α/(α−1)},  Δs_{j+1}/Δs_j = ((j+2)/(j+1))^{1/(α−1)},
/// eq (21) with the constant "a" of eq (20) equal to α (the rotation of eq 18 solved for Δs);
/// the turning direction is that of eq (15), sign(α − 1). Given the total length L, Δθ follows
/// from Σ Δs_j = L in closed form. This polygon converges to a log-aesthetic curve of slope α,
/// but not to the same piece of eq (15): (20) uses (j+1)Δs_j for the arc length Σ_{k≤j} Δs_k.
/// Log spiral (eq 23–24): points e^{(a+ib)t_j}, t_j = jΔθ/b: constant rotation Δθ and constant
/// scale e^{aΔθ/b} — a stationary (ordinary typical) matrix.
///
/// Defined for (InvalidInput otherwise, naming α): scale-1 for α < 0 or α > 1 (θ(0) must be
/// finite and the directions must turn: for 0 < α < 1, 0^e diverges; α = 1 gives e = 0, all
/// directions equal, a straight line; α = 0 divides by zero); constant rotation for α ∉ {0, 1}
/// (eq 21 divides by α − 1, and by α through eq 20). degree ≥ 1 (≥ 2 where a rotation is needed),
/// finite L > 0, finite Δθ ≠ 0.
#include <Eigen/Dense>
#include <vector>

namespace cagd::aesthetic {

/// A planar typical (or nonstationary typical) Bézier control polygon with its edges, rotations and scales.
struct TypicalPolygon {
    Eigen::MatrixXd points;            ///< (n + 1) × 2, b_0 = (0, 0), first edge along +x
    std::vector<double> edge_lengths;  ///< Δs_j, j = 0 … n−1
    std::vector<double> rotations;     ///< φ_j: edge j → edge j + 1, j = 0 … n−2
    std::vector<double> scales;        ///< s_j = Δs_{j+1}/Δs_j
};

/// The scale-1 polygon of eq (16): n equal edges whose rotations follow the log-aesthetic law (α < 0 or α > 1).
TypicalPolygon scale_one_typical_polygon(double alpha, double length, int degree);
/// The constant-rotation polygon of eq (21): equal rotations, edge lengths following the law (α ≠ 0, 1).
TypicalPolygon constant_rotation_typical_polygon(double alpha, double length, int degree);
/// The same with the rotation Δθ given instead of the length (eq 21 as printed, a = α).
TypicalPolygon constant_rotation_typical_polygon_by_angle(double alpha, double rotation, int degree);
/// The polygon of a logarithmic spiral r = a e^{bθ}: equal rotations and a constant scale.
TypicalPolygon log_spiral_polygon(double a, double b, double rotation, int degree);

double first_order_rotation(double alpha, double ds, int j);  ///< eq (18)
double first_order_rotation_ratio(double alpha, int j);       ///< eq (19)
double constant_rotation_scale_ratio(double alpha, int j);    ///< eq (22)
/// Exact ratio of the eq (17) rotations, φ_{j+2}/φ_{j+1} = (θ((j+3)Δs) − θ((j+2)Δs))/(θ((j+2)Δs) − θ((j+1)Δs)):
/// independent of Δs, → eq (19) as j → ∞.
double exact_rotation_ratio(double alpha, int j);

}  // namespace cagd::aesthetic
