#pragma once
/// @file
/// Class A matrices and (non)stationary typical Bézier control polygons
/// (typical_curves section 2.1, eq 1–4, and section 3.1).
///
/// A Bézier curve of degree n with Δb_j = M^j Δb_0 (M the transition matrix) is "class A" when
///   |(1 − t) v + t M v| ≥ |v| for t ∈ [0, 1], |v| = 1                       (eq 1)
/// Expanding, |v + t(M − I)v|² = 1 + t vᵀ(Mᵀ + M − 2I)v + t²|(M − I)v|², so (1) holds exactly when
/// Mᵀ + M − 2I is positive semidefinite; Farin's test (eq 2) asks for non-negative eigenvalues of
/// Mᵀ + M − 2I and of MᵀM − I (the latter ⇔ singular values σ_i ≥ 1, implied by the former).
/// Cao–Wang (eq 3): 2σ1 ≥ σ2 + 1 and 2σ2 ≥ σ1 + 1 (for 3×3 we require it for every pair).
/// class_a = eq (2) and σ ≥ 1 and eq (3), the paper's "class A conditions".
/// Typical matrices M = s R_θ (rotation by θ, scale s), condition (4):
///   cos θ > 1/s (s > 1)  or  cos θ > s (s < 1).
/// For s > 1, (4) is (2) (Mᵀ + M − 2I = 2(s cos θ − 1) I); for s < 1, (2) fails (σ = s < 1) and (4)
/// is (2) for M⁻¹ = s⁻¹R_{−θ}, i.e. the same curve traversed backwards is class A.
/// Nonstationary polygons (section 3.1): Δb_j = M_{j−1} ⋯ M_0 Δb_0 with per-edge matrices M_j.
/// Preconditions: square 2×2 or 3×3 finite matrices, degree ≥ 1, Δb_0 ≠ 0 (InvalidInput).
#include <Eigen/Dense>
#include <vector>

namespace cagd::aesthetic {

/// What class_a_test finds for a transition matrix M.
struct ClassATest {
    double min_eig_symmetric_part = 0.0;  ///< λ_min(Mᵀ + M − 2I), eq (2)
    double min_eig_gram = 0.0;            ///< λ_min(MᵀM − I), eq (2)
    Eigen::VectorXd singular_values;      ///< descending
    bool eq1 = false;                     ///< λ_min(Mᵀ + M − 2I) ≥ 0 ⇔ eq (1)
    bool eq2 = false;                     ///< both eigenvalue tests of eq (2)
    bool singular_at_least_one = false;   ///< σ_min ≥ 1
    bool cao_wang = false;                ///< eq (3)
    bool symmetric = false;               ///< M symmetric (to the tolerance)
    bool class_a = false;                 ///< eq2 && singular_at_least_one && cao_wang
};
/// The tests above for M; `tolerance` relaxes every inequality by that amount.
ClassATest class_a_test(const Eigen::MatrixXd& m, double tolerance = 0.0);

Eigen::Matrix2d typical_matrix(double theta, double scale);  ///< s R_θ
bool typical_matrix_condition(double theta, double scale);   ///< eq (4)

/// b_0, b_1 = b_0 + Δb_0, b_{j+1} = b_j + M^j Δb_0, j < degree: (degree + 1) × dim.
Eigen::MatrixXd class_a_control_points(const Eigen::VectorXd& b0, const Eigen::VectorXd& db0, const Eigen::MatrixXd& m,
                                       int degree);
/// Δb_j = M_{j−1} ⋯ M_0 Δb_0 for matrices M_0 … M_{n−2}: n + 1 points.
Eigen::MatrixXd nonstationary_control_points(const Eigen::VectorXd& b0, const Eigen::VectorXd& db0,
                                             const std::vector<Eigen::MatrixXd>& matrices);

/// Planar polygon → the similarity M_j = s_j R_{φ_j} mapping edge j to edge j + 1:
/// rotations φ_j ∈ (−π, π] and scales s_j = |Δb_{j+1}|/|Δb_j|, j = 0 … n−2.
struct PlanarTransitions {
    std::vector<double> rotations;  ///< φ_j
    std::vector<double> scales;     ///< s_j
};
/// The transitions of a planar polygon (no zero edge).
PlanarTransitions planar_transitions(const Eigen::MatrixXd& points);

}  // namespace cagd::aesthetic
