#pragma once
/// @file
/// Polynomials with exact rational coefficients (Boost.Multiprecision cpp_rational), in the power
/// basis c_0 + c_1 t + … + c_d t^d: enough algebra to build a basis from its defining formula and
/// to verify printed identities exactly (no rounding), e.g. hosaka eq (2)–(14).
/// Also exact binomial coefficients and factorials. Preconditions: non-negative arguments
/// (InvalidInput otherwise).
#include <boost/multiprecision/cpp_int.hpp>
#include <string>
#include <vector>

namespace cagd {

/// Exact rational numbers (Boost.Multiprecision).
using Rational = boost::multiprecision::cpp_rational;

/// n! exactly.
Rational factorial(int n);
Rational binomial(int n, int k);  ///< 0 for k < 0 or k > n

/// A polynomial Σ c_k t^k with exact rational coefficients.
class RationalPolynomial {
public:
    RationalPolynomial() = default;
    /// From the coefficients c_0, c_1, … (trailing zeros are dropped).
    explicit RationalPolynomial(std::vector<Rational> coefficients);
    /// The constant polynomial c.
    static RationalPolynomial constant(const Rational& c);
    static RationalPolynomial monomial(int degree, const Rational& c = 1);     ///< c t^degree
    static RationalPolynomial linear(const Rational& c0, const Rational& c1);  ///< c0 + c1 t

    /// Degree of the highest non-zero coefficient; −1 for the zero polynomial.
    int degree() const;
    /// Whether this is the zero polynomial.
    bool is_zero() const { return degree() < 0; }
    /// The coefficients c_0..c_degree.
    const std::vector<Rational>& coefficients() const { return c_; }
    Rational coefficient(int k) const;  ///< 0 beyond the stored ones

    Rational operator()(const Rational& t) const;  ///< exact value (Horner)
    double value(double t) const;                  ///< in double, from rounded coefficients
    /// The derivative of the given order, exactly.
    RationalPolynomial derivative(int order = 1) const;
    RationalPolynomial compose_one_minus() const;  ///< p(1 − t)
    /// p^n for n ≥ 0.
    RationalPolynomial power(int n) const;

    /// Adds o.
    RationalPolynomial& operator+=(const RationalPolynomial& o);
    /// Subtracts o.
    RationalPolynomial& operator-=(const RationalPolynomial& o);
    /// Scales by s.
    RationalPolynomial& operator*=(const Rational& s);
    /// Sum.
    friend RationalPolynomial operator+(RationalPolynomial a, const RationalPolynomial& b) { return a += b; }
    /// Difference.
    friend RationalPolynomial operator-(RationalPolynomial a, const RationalPolynomial& b) { return a -= b; }
    /// p scaled by s.
    friend RationalPolynomial operator*(RationalPolynomial a, const Rational& s) { return a *= s; }
    /// p scaled by s.
    friend RationalPolynomial operator*(const Rational& s, RationalPolynomial a) { return a *= s; }
    /// Product.
    friend RationalPolynomial operator*(const RationalPolynomial& a, const RationalPolynomial& b);
    /// Equality of the polynomials (not of their stored representation).
    friend bool operator==(const RationalPolynomial& a, const RationalPolynomial& b) { return (a - b).is_zero(); }

    std::string to_string() const;  ///< e.g. "3 t^2 - 2 t^3"

private:
    std::vector<Rational> c_;
};

}  // namespace cagd
