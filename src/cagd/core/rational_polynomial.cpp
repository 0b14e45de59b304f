#include "cagd/core/rational_polynomial.hpp"

#include <sstream>

#include "cagd/core/errors.hpp"

namespace cagd {

Rational factorial(int n) {
    if (n < 0) fail_input("cagd::factorial", "n must be >= 0, got " + std::to_string(n));
    Rational f = 1;
    for (int k = 2; k <= n; ++k) f *= k;
    return f;
}

Rational binomial(int n, int k) {
    if (n < 0) fail_input("cagd::binomial", "n must be >= 0, got " + std::to_string(n));
    if (k < 0 || k > n) return 0;
    return factorial(n) / (factorial(k) * factorial(n - k));
}

RationalPolynomial::RationalPolynomial(std::vector<Rational> coefficients) : c_(std::move(coefficients)) {}

RationalPolynomial RationalPolynomial::constant(const Rational& c) { return RationalPolynomial({c}); }

RationalPolynomial RationalPolynomial::monomial(int degree, const Rational& c) {
    if (degree < 0)
        fail_input("cagd::RationalPolynomial::monomial", "degree must be >= 0, got " + std::to_string(degree));
    std::vector<Rational> v(static_cast<std::size_t>(degree) + 1, Rational(0));
    v.back() = c;
    return RationalPolynomial(std::move(v));
}

RationalPolynomial RationalPolynomial::linear(const Rational& c0, const Rational& c1) {
    return RationalPolynomial({c0, c1});
}

int RationalPolynomial::degree() const {
    for (int k = static_cast<int>(c_.size()) - 1; k >= 0; --k)
        if (c_[static_cast<std::size_t>(k)] != 0) return k;
    return -1;
}

Rational RationalPolynomial::coefficient(int k) const {
    return k >= 0 && k < static_cast<int>(c_.size()) ? c_[static_cast<std::size_t>(k)] : Rational(0);
}

Rational RationalPolynomial::operator()(const Rational& t) const {
    Rational v = 0;
    for (auto it = c_.rbegin(); it != c_.rend(); ++it) v = v * t + *it;
    return v;
}

double RationalPolynomial::value(double t) const {
    double v = 0.0;
    for (auto it = c_.rbegin(); it != c_.rend(); ++it) v = v * t + static_cast<double>(*it);
    return v;
}

RationalPolynomial RationalPolynomial::derivative(int order) const {
    if (order < 0)
        fail_input("cagd::RationalPolynomial::derivative", "order must be >= 0, got " + std::to_string(order));
    std::vector<Rational> d = c_;
    for (int r = 0; r < order; ++r) {
        if (d.size() <= 1) return RationalPolynomial();
        std::vector<Rational> e(d.size() - 1);
        for (std::size_t k = 1; k < d.size(); ++k) e[k - 1] = d[k] * static_cast<int>(k);
        d = std::move(e);
    }
    return RationalPolynomial(std::move(d));
}

RationalPolynomial RationalPolynomial::compose_one_minus() const {
    RationalPolynomial out;
    const RationalPolynomial one_minus_t = linear(1, -1);
    RationalPolynomial power_k = constant(1);
    for (std::size_t k = 0; k < c_.size(); ++k) {
        out += power_k * c_[k];
        power_k = power_k * one_minus_t;
    }
    return out;
}

RationalPolynomial RationalPolynomial::power(int n) const {
    if (n < 0) fail_input("cagd::RationalPolynomial::power", "n must be >= 0, got " + std::to_string(n));
    RationalPolynomial r = constant(1);
    for (int k = 0; k < n; ++k) r = r * *this;
    return r;
}

RationalPolynomial& RationalPolynomial::operator+=(const RationalPolynomial& o) {
    if (o.c_.size() > c_.size()) c_.resize(o.c_.size(), Rational(0));
    for (std::size_t k = 0; k < o.c_.size(); ++k) c_[k] += o.c_[k];
    return *this;
}

RationalPolynomial& RationalPolynomial::operator-=(const RationalPolynomial& o) {
    if (o.c_.size() > c_.size()) c_.resize(o.c_.size(), Rational(0));
    for (std::size_t k = 0; k < o.c_.size(); ++k) c_[k] -= o.c_[k];
    return *this;
}

RationalPolynomial& RationalPolynomial::operator*=(const Rational& s) {
    for (auto& x : c_) x *= s;
    return *this;
}

RationalPolynomial operator*(const RationalPolynomial& a, const RationalPolynomial& b) {
    if (a.c_.empty() || b.c_.empty()) return RationalPolynomial();
    std::vector<Rational> v(a.c_.size() + b.c_.size() - 1, Rational(0));
    for (std::size_t i = 0; i < a.c_.size(); ++i)
        for (std::size_t j = 0; j < b.c_.size(); ++j) v[i + j] += a.c_[i] * b.c_[j];
    return RationalPolynomial(std::move(v));
}

std::string RationalPolynomial::to_string() const {
    std::ostringstream s;
    bool first = true;
    for (int k = 0; k <= degree(); ++k) {
        const Rational& c = c_[static_cast<std::size_t>(k)];
        if (c == 0) continue;
        if (!first)
            s << (c < 0 ? " - " : " + ");
        else if (c < 0)
            s << "-";
        const Rational a = c < 0 ? Rational(-c) : c;
        if (a != 1 || k == 0) s << a << (k > 0 ? " " : "");
        if (k > 0) s << "t" << (k > 1 ? "^" + std::to_string(k) : "");
        first = false;
    }
    return first ? "0" : s.str();
}

}  // namespace cagd
