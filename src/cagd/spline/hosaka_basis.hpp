#pragma once
/// @file
/// Hosaka's generalised Hermite basis (hosaka section 2, eq 1–14).
///
/// A function on [0, 1] of degree 2m+1 is fixed by its derivatives up to order m at both ends:
///     φ(t) = Σ_{i=0}^{m} { φ_0^{(i)} p_i(m, t) + φ_1^{(i)} q_i(m, t) }                       (1)
///     p_i(m, t) = (1/i!) Σ_{j=0}^{m−i} (−1)^{i+j−1} C(2m+1−i, j) t^{i+j} (t − 1)^{2m+1−i−j}
///     q_i(m, t) = (1/i!) Σ_{j=0}^{m−i} (−1)^{j}     C(2m+1−i, j) t^{2m+1−i−j} (t − 1)^{i+j}    (2)
/// so that p_i^{(k)}(m, 0) = δ_ik, p_i^{(k)}(m, 1) = 0, q_i^{(k)}(m, 1) = δ_ik, q_i^{(k)}(m, 0) = 0
/// for 0 ≤ k ≤ m (eq 3–5). m = 1 gives the cubic Hermite basis (f, g, h of eq 12), m = 2 the quintic.
///
/// Two forms: exact (`hosaka_p`, `hosaka_q`: rational coefficients, for verifying the paper's
/// identities without rounding) and double (`HosakaBasis`: coefficients rounded once, Horner; for
/// m ≤ 5 on [0, 1] the values agree with the exact ones to a few ulps of the largest coefficient).
/// Preconditions: m ≥ 0, 0 ≤ i ≤ m, derivative order k ≥ 0 (InvalidInput otherwise).
#include <vector>

#include "cagd/core/rational_polynomial.hpp"

namespace cagd::spline {

RationalPolynomial hosaka_p(int m, int i);  ///< eq (2), exact
/// q_i(m, t) of eq (2), exact: q_i(m, t) = (−1)^i p_i(m, 1 − t).
RationalPolynomial hosaka_q(int m, int i);

/// The basis p_i(m, ·), q_i(m, ·), i = 0..m, in double precision, for evaluation with derivatives.
class HosakaBasis {
public:
    /// The basis of order m ≥ 0 (segments of degree 2m + 1).
    explicit HosakaBasis(int m);
    /// m.
    int m() const { return m_; }
    /// k-th derivative of p_i(m, ·) / q_i(m, ·) at t (any real t; k > 2m+1 gives 0).
    double p(int i, double t, int k = 0) const;
    /// The same for q_i(m, ·).
    double q(int i, double t, int k = 0) const;
    /// p_i and q_i, i = 0..m, at t for one derivative order k ≥ 0 (InvalidInput otherwise) into
    /// p_out[0..m] and q_out[0..m]: the same values as p() and q(), checked once (for jets).
    void values(double t, int k, double* p_out, double* q_out) const;

private:
    int m_;
    /// coefficients_[i][k]: double power-basis coefficients of the k-th derivative (p, then q).
    std::vector<std::vector<std::vector<double>>> p_, q_;
    double eval(const std::vector<std::vector<std::vector<double>>>& table, int i, double t, int k) const;
};

}  // namespace cagd::spline
