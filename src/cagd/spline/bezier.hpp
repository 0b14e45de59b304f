#pragma once
/// @file
/// Bézier curves r(t) = Σ_{j=0}^{p} B_{j,p}(s) b_j, s = (t − a)/(b − a), t ∈ [a, b].
/// Derivatives come from the forward differences of the control points (hodographs):
///   r^(k)(t) = p!/(p−k)! (b − a)^{−k} Σ_j Δ^k b_j B_{j,p−k}(s).
/// Three evaluation methods, chosen at construction:
///   de_casteljau  repeated convex combinations: stable for any degree, O(p²) per derivative order
///                 (the default);
///   bernstein     the basis values by core/bernstein_basis_values (O(p), stable for any degree:
///                 for p in the hundreds or thousands, where O(p²) is slow);
///   power_basis   the monomial coefficients a_k = C(p,k) Σ_j (−1)^{k−j} C(k,j) b_j and Horner —
///                 the naive method, kept to show why it must not be used: the a_k grow like 2^p
///                 and cancel, so its error grows exponentially with p (typical_curves Fig. 1).
/// Preconditions: at least one control point, finite a < b.
#include <Eigen/Dense>
#include <vector>

#include "cagd/core/curve.hpp"

namespace cagd {

/// How a Bézier curve is evaluated: de Casteljau (stable, O(n²)), stable Bernstein values (O(n) per point, any degree)
/// or the power basis (fast, unstable at high degree).
enum class BezierEvaluation { de_casteljau, bernstein, power_basis };

/// A Bézier curve r(t) = Σ B_i^n((t − a)/(b − a)) P_i on [a, b].
class BezierCurve : public Curve {
public:
    /// Control points P_0..P_n (one per row), parameter interval [a, b] (a < b) and evaluation method.
    explicit BezierCurve(Eigen::MatrixXd control_points, double a = 0.0, double b = 1.0,
                         BezierEvaluation method = BezierEvaluation::de_casteljau);
    /// n.
    int degree() const { return static_cast<int>(control_.rows()) - 1; }
    /// P_0..P_n, one per row.
    const Eigen::MatrixXd& control_points() const { return control_; }
    /// The evaluation method.
    BezierEvaluation evaluation() const { return method_; }
    int dimension() const override { return static_cast<int>(control_.cols()); }
    double t_min() const override { return a_; }
    double t_max() const override { return b_; }
    void evaluate_jet(double t, int first, JetSide, Eigen::Ref<Eigen::MatrixXd> out) const override {
        take_rows(whole_jet(t, first + static_cast<int>(out.rows()) - 1), first, out);
    }
    std::vector<double> breakpoints() const override { return {a_, b_}; }
    int polynomial_degree() const override { return degree(); }

private:
    Eigen::MatrixXd whole_jet(double t, int order) const;  ///< rows 0..order by the evaluation method
    Eigen::MatrixXd control_;
    double a_, b_;
    BezierEvaluation method_;
    Eigen::MatrixXd monomial_;  ///< power_basis only: row k = a_k
};

/// The monomial coefficients of the Bézier polynomial of `control` on [0, 1]: row k is a_k in
/// r(s) = Σ_k a_k s^k, a_k = C(p,k) Σ_{j≤k} (−1)^{k−j} C(k,j) b_j (exact conversion; the a_k grow
/// like 2^p, so the power basis suits low degrees only, as the power_basis evaluation shows).
Eigen::MatrixXd monomial_from_bernstein(const Eigen::MatrixXd& control);
/// The inverse: the control points b_j = Σ_{k≤j} C(j,k)/C(p,k) a_k of the polynomial with monomial
/// coefficients `monomial` (row k = a_k) on [0, 1].
Eigen::MatrixXd bernstein_from_monomial(const Eigen::MatrixXd& monomial);

/// The p + 1 control points of the degree-p polynomial on [a, b] (h = b − a > 0) from its
/// derivatives at the two ends: J0 (rows 0..⌊p/2⌋ used) at a and J1 (rows 0..p − ⌊p/2⌋ − 1 used) at
/// b, since Δ^j b_0 = (p−j)!/p! h^j r^(j)(a) and likewise backwards from b_p:
///     b_k     = Σ_{j=0}^{k} C(k, j) (p−j)!/p! h^j r^(j)(a),      k = 0 … ⌊p/2⌋,
///     b_{p−k} = Σ_{j=0}^{k} C(k, j) (p−j)!/p! (−h)^j r^(j)(b),   k = 0 … p − ⌊p/2⌋ − 1.
/// Half the points from each end: no derivative above order ⌈p/2⌉ enters, and the terms stay of the
/// size of the control polygon (a Taylor expansion from one end would use orders up to p).
Eigen::MatrixXd bezier_from_end_jets(int degree, double h, const Eigen::MatrixXd& J0, const Eigen::MatrixXd& J1);

}  // namespace cagd
