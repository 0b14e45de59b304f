#pragma once
/// @file
/// Alexa's commutative combination of linear transformations ("Linear combination of
/// transformations", SIGGRAPH 2002), typical_curves eq (37):
///
///   A ⊗ B = lim_{n→∞} (A^{1/n} B^{1/n})^n = exp(log A + log B).
///
/// The second form (Lie–Trotter product formula) is what `alexa_product` computes, with the
/// principal matrix logarithm and the exponential of Eigen's unsupported MatrixFunctions module.
/// ⊗ is commutative, A ⊗ I = A, and for commuting A, B it is the ordinary product AB. For two
/// rotations about the axes a and b by the angles φ and ψ it is the rotation by the vector φa + ψb
/// (rotation_vector_product below, Rodrigues' formula): the "simultaneous" rotation.
/// `alexa_product_limit(A, B, k)` evaluates the limit definition itself at n = 2^k with k repeated
/// principal square roots and k squarings — no logarithm — as the independent check of eq (37):
/// its error decreases like 1/n (alexa_limit_error_coefficient gives the constant) until the
/// rounding of the k roots and squarings takes over (n ≳ 2^14 for 3×3 rotations). The roots come
/// from the complex Schur form (MatrixXcd::sqrt), real part taken.
///
/// Preconditions (InvalidInput naming the value): square matrices of one size with finite entries,
/// no eigenvalue on the closed negative real axis (the principal logarithm must exist and be real:
/// a rotation by less than π); 0 ≤ k ≤ 60.
#include <Eigen/Dense>

namespace cagd::numeric {

/// A ⊗ B = exp(log A + log B), principal logarithms (eq 37).
Eigen::MatrixXd alexa_product(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);
/// (A^{1/n} B^{1/n})^n at n = 2^halvings, by repeated principal square roots and squarings (the limit definition).
Eigen::MatrixXd alexa_product_limit(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, int halvings);
/// lim n·‖(A^{1/n} B^{1/n})^n − A ⊗ B‖_F. By Baker–Campbell–Hausdorff the n-th power is
/// exp(Z + C/n + O(n⁻²)), Z = log A + log B, C = [log A, log B]/2, so the limit is ‖L_exp(Z, C)‖_F,
/// L_exp the Fréchet derivative of exp, read off the upper-right block of exp([[Z, C], [0, Z]])
/// (≈ ‖C‖_F for small Z).
double alexa_limit_error_coefficient(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);
/// exp([φ]×) for the rotation vector φ (axis φ/|φ|, angle |φ|): Rodrigues' formula.
Eigen::Matrix3d rotation_from_vector(const Eigen::Vector3d& phi);

}  // namespace cagd::numeric
