#pragma once
/// @file
/// Polynomials in Bernstein form on [0, 1], in double precision:
///   p(t) = Σ_{i=0}^{d} c_i B_{i,d}(t),   B_{i,d}(t) = C(d,i) t^i (1 − t)^{d−i}.
/// Used to decide the sign of a curvature derivative exactly up to rounding (typical_curves,
/// appendix A.1: "if all C_i have one sign, the curvature is strictly monotone").
///
/// Products use C(m,i) C(k,j) / C(m+k,i+j) (Farin, CAGD ch. 5); derivative and degree elevation
/// are the textbook formulas; evaluation and subdivision are de Casteljau (stable, convex).
/// sign_on_unit_interval() isolates sign changes by recursive subdivision: a piece whose
/// coefficients all have one strict sign is settled; a value witnesses a sign only if it exceeds
/// 64 ε · max |c_i| of its own piece (local, so polynomials spanning many orders of magnitude on
/// [0, 1] are judged fairly); a piece still mixed after `max_depth` halvings either touches zero
/// within rounding (non-strict sign) or makes the result `undetermined` (a returned status).
///
/// bernstein_basis_values(d, t): all B_{i,d}(t) in O(d), stable for any degree ("Bernstein with
/// care"): start from the largest term i* = round(d t) through lgamma, run the ratio
/// B_{i+1}/B_i = (d−i)/(i+1) · t/(1−t) both ways, and renormalise by the sum (partition of unity),
/// which removes the lgamma rounding. Relative error about sqrt(d) ε on the significant terms;
/// no overflow or underflow trouble at d = 10^4. Precondition: 0 ≤ t ≤ 1, d ≥ 0.
/// Degrees up to kSmallBernsteinDegree take the triangle B_{i,k} = (1 − t) B_{i,k−1} + t B_{i−1,k−1}
/// instead (d²/2 multiply-adds of positive terms, relative error ≤ 2d ε, no lgamma/exp/log): the
/// curves here evaluate degrees ≤ 5 millions of times per comparison. The span overload writes
/// into the caller's storage (out.size() must be degree + 1), allocation-free for those degrees.
#include <span>
#include <string>
#include <vector>

namespace cagd {

/// A polynomial on [0, 1] in Bernstein form, p(t) = Σ_i c_i B_i^d(t).
class BernsteinPolynomial {
public:
    BernsteinPolynomial() = default;
    explicit BernsteinPolynomial(std::vector<double> coefficients);  ///< at least one, finite

    /// d, the number of coefficients minus one.
    int degree() const { return static_cast<int>(c_.size()) - 1; }
    /// The Bernstein coefficients c_0..c_d.
    const std::vector<double>& coefficients() const { return c_; }
    double operator()(double t) const;                  ///< de Casteljau
    BernsteinPolynomial derivative() const;             ///< degree d − 1 (d = 0: 0)
    BernsteinPolynomial elevated(int to_degree) const;  ///< same polynomial
    /// Degree d − 1 representation of a polynomial whose true degree is below d (e.g. r' × r'' of
    /// a Bézier curve, whose leading terms cancel): the inverse of elevation, from the left for
    /// the first half of the coefficients and from the right for the rest (Farin, CAGD §6.1).
    BernsteinPolynomial reduced() const;
    /// Halves on [0, τ] and [τ, 1], each reparametrised to [0, 1].
    std::pair<BernsteinPolynomial, BernsteinPolynomial> subdivide(double tau = 0.5) const;

    /// Scales every coefficient by s.
    BernsteinPolynomial& operator*=(double s);
    /// Sum (both at the higher degree).
    friend BernsteinPolynomial operator+(const BernsteinPolynomial& a, const BernsteinPolynomial& b);
    /// Difference (both at the higher degree).
    friend BernsteinPolynomial operator-(const BernsteinPolynomial& a, const BernsteinPolynomial& b);
    /// Product, of degree d_a + d_b.
    friend BernsteinPolynomial operator*(const BernsteinPolynomial& a, const BernsteinPolynomial& b);
    /// p scaled by s.
    friend BernsteinPolynomial operator*(double s, BernsteinPolynomial a) { return a *= s; }

private:
    std::vector<double> c_;
};

/// The sign of a polynomial on [0, 1], as far as its Bernstein coefficients and subdivision decide it.
enum class SignOnInterval { negative, positive, nonpositive, nonnegative, zero, changes_sign, undetermined };
/// The name of a sign class ("negative", "changes_sign", …).
const char* to_string(SignOnInterval s);

/// What sign_on_unit_interval found.
struct SignAnalysis {
    SignOnInterval sign = SignOnInterval::undetermined;  ///< the class
    /// For changes_sign: a parameter where p is clearly negative and one where it is clearly
    /// positive (witnesses), else −1.
    double t_negative = -1.0, t_positive = -1.0;  ///< witnesses of a sign change (else −1)
};
/// negative/positive: every Bernstein coefficient strictly of that sign (after subdivision where
/// needed) — p has no zero in [0, 1]. nonpositive/nonnegative: p never clearly crosses zero
/// (it may touch it). zero: all coefficients within rounding of 0.
SignAnalysis sign_on_unit_interval(const BernsteinPolynomial& p, int max_depth = 40);

/// Up to this degree the basis values come from the de Casteljau triangle, above it from the stable ratio recurrence.
inline constexpr int kSmallBernsteinDegree = 16;
/// B_0^d(t)..B_d^d(t), all d + 1 values, stable at high degree.
std::vector<double> bernstein_basis_values(int degree, double t);
/// The same into `out` (size d + 1), without allocating.
void bernstein_basis_values(int degree, double t, std::span<double> out);

}  // namespace cagd
