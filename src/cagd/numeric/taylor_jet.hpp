#pragma once
/// @file
/// Truncated Taylor series (a jet) of a function of one variable at a point:
///     f(x0 + h) = a_0 + a_1 h + … + a_N h^N + O(h^{N+1}),   a_k = f^{(k)}(x0) / k!.
/// Arithmetic on jets is arithmetic on the functions, exact up to order N (forward-mode automatic
/// differentiation to arbitrary order, with the order chosen at run time — Boost.Math's autodiff
/// fixes it at compile time, which the surfaces of hosaka section 4, whose recurrence (36) lowers
/// the order by one per step, cannot use). Operations between jets of different orders keep the
/// lower order. Cost: O(N²) per product or reciprocal.
/// Preconditions (InvalidInput): order ≥ 0; the reciprocal of a jet whose value is 0.
#include <vector>

namespace cagd::numeric {

/// A truncated Taylor series a_0 + a_1 h + … + a_N h^N of order N (see above).
class TaylorJet {
public:
    /// The constant jet `value` of order N = order.
    explicit TaylorJet(int order, double value = 0.0);
    /// The jet of x itself at x0: x0 + h.
    static TaylorJet variable(int order, double x0);
    /// From derivatives d[k] = f^{(k)}(x0), k = 0..N.
    static TaylorJet from_derivatives(const std::vector<double>& d);

    /// N.
    int order() const { return static_cast<int>(a_.size()) - 1; }
    /// a_0 = f(x0).
    double value() const { return a_[0]; }
    double coefficient(int k) const;   ///< a_k
    double derivative(int k) const;    ///< k! a_k = f^{(k)}(x0)
    TaylorJet differentiated() const;  ///< the jet of f', order N − 1 (order 0 → the zero jet of order 0)

    /// Adds b (the lower order kept).
    TaylorJet& operator+=(const TaylorJet& b);
    /// Subtracts b (the lower order kept).
    TaylorJet& operator-=(const TaylorJet& b);
    /// Scales by s.
    TaylorJet& operator*=(double s);
    /// Adds the constant s.
    TaylorJet& operator+=(double s) {
        a_[0] += s;
        return *this;
    }

private:
    std::vector<double> a_;
    friend TaylorJet operator*(const TaylorJet& a, const TaylorJet& b);
    friend TaylorJet reciprocal(const TaylorJet& a);
    friend TaylorJet compose(const std::vector<double>& outer_derivatives, const TaylorJet& inner);
};

/// Sum (the lower order kept).
TaylorJet operator+(TaylorJet a, const TaylorJet& b);
/// Difference (the lower order kept).
TaylorJet operator-(TaylorJet a, const TaylorJet& b);
/// Product, truncated at the lower order.
TaylorJet operator*(const TaylorJet& a, const TaylorJet& b);
/// f scaled by s.
TaylorJet operator*(TaylorJet a, double s);
/// f scaled by s.
TaylorJet operator*(double s, TaylorJet a);
TaylorJet reciprocal(const TaylorJet& a);    ///< 1/f
TaylorJet power(const TaylorJet& a, int n);  ///< f^n, any integer n (n < 0 via the reciprocal)
/// g(f(x)) from the derivatives of g at f(x0): outer_derivatives[r] = g^{(r)}(f(x0)), r = 0..N
/// (fewer entries: the missing derivatives are taken as zero, right for a polynomial g).
TaylorJet compose(const std::vector<double>& outer_derivatives, const TaylorJet& inner);

}  // namespace cagd::numeric
