#include "cagd/spline/hosaka_basis.hpp"

#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::spline {

namespace {

void require_indices(const char* who, int m, int i) {
    if (m < 0) fail_input(who, "m must be >= 0, got " + std::to_string(m));
    if (i < 0 || i > m)
        fail_input(who, "i must be in [0, m] = [0, " + std::to_string(m) + "], got " + std::to_string(i));
}

// The polynomial with power-basis coefficients c (constant first) at t, by Horner.
double horner(const std::vector<double>& c, double t) {
    double v = 0.0;
    for (auto it = c.rbegin(); it != c.rend(); ++it) v = v * t + *it;
    return v;
}

// (1/i!) Σ_j sign(j) C(2m+1−i, j) t^{a(j)} (t − 1)^{2m+1−a(j)}
template <class Sign, class Power>
RationalPolynomial basis_sum(int m, int i, Sign sign, Power t_power) {
    const RationalPolynomial t_minus_1 = RationalPolynomial::linear(-1, 1);
    RationalPolynomial sum;
    for (int j = 0; j <= m - i; ++j) {
        const int a = t_power(j);
        sum += RationalPolynomial::monomial(a, sign(j) * binomial(2 * m + 1 - i, j)) * t_minus_1.power(2 * m + 1 - a);
    }
    return sum * (Rational(1) / factorial(i));
}

}  // namespace

RationalPolynomial hosaka_p(int m, int i) {
    require_indices("cagd::spline::hosaka_p", m, i);
    return basis_sum(
        m, i, [&](int j) { return (i + j - 1) % 2 == 0 ? 1 : -1; }, [&](int j) { return i + j; });
}

RationalPolynomial hosaka_q(int m, int i) {
    require_indices("cagd::spline::hosaka_q", m, i);
    return basis_sum(
        m, i, [&](int j) { return j % 2 == 0 ? 1 : -1; }, [&](int j) { return 2 * m + 1 - i - j; });
}

HosakaBasis::HosakaBasis(int m) : m_(m) {
    require_indices("cagd::spline::HosakaBasis", m, 0);
    const auto fill = [&](auto basis, std::vector<std::vector<std::vector<double>>>& table) {
        table.resize(static_cast<std::size_t>(m) + 1);
        for (int i = 0; i <= m; ++i) {
            RationalPolynomial poly = basis(m, i);
            for (int k = 0; k <= 2 * m + 1; ++k) {
                std::vector<double> c;
                for (const Rational& r : poly.coefficients()) c.push_back(static_cast<double>(r));
                table[static_cast<std::size_t>(i)].push_back(std::move(c));
                poly = poly.derivative();
            }
        }
    };
    fill(hosaka_p, p_);
    fill(hosaka_q, q_);
}

double HosakaBasis::eval(const std::vector<std::vector<std::vector<double>>>& table, int i, double t, int k) const {
    require_indices("cagd::spline::HosakaBasis", m_, i);
    if (k < 0) fail_input("cagd::spline::HosakaBasis", "derivative order must be >= 0, got " + std::to_string(k));
    if (k > 2 * m_ + 1) return 0.0;
    return horner(table[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)], t);
}

void HosakaBasis::values(double t, int k, double* p_out, double* q_out) const {
    if (k < 0) fail_input("cagd::spline::HosakaBasis", "derivative order must be >= 0, got " + std::to_string(k));
    for (int i = 0; i <= m_; ++i) {
        const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(k);
        p_out[i] = k > 2 * m_ + 1 ? 0.0 : horner(p_[a][b], t);
        q_out[i] = k > 2 * m_ + 1 ? 0.0 : horner(q_[a][b], t);
    }
}

double HosakaBasis::p(int i, double t, int k) const { return eval(p_, i, t, k); }
double HosakaBasis::q(int i, double t, int k) const { return eval(q_, i, t, k); }

}  // namespace cagd::spline
