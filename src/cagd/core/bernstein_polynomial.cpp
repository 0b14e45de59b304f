#include "cagd/core/bernstein_polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cagd/core/errors.hpp"

namespace cagd {

namespace {

// C(n, k) in double by the product formula (exact for n ≤ 60, a few ulp beyond).
double binomial_double(int n, int k) {
    if (k < 0 || k > n) return 0.0;
    k = std::min(k, n - k);
    double r = 1.0;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return n <= 60 ? std::round(r) : r;
}

double max_abs(const std::vector<double>& c) {
    double m = 0.0;
    for (double v : c) m = std::max(m, std::abs(v));
    return m;
}

}  // namespace

BernsteinPolynomial::BernsteinPolynomial(std::vector<double> coefficients) : c_(std::move(coefficients)) {
    if (c_.empty()) fail_input("cagd::BernsteinPolynomial", "needs at least one coefficient");
    for (std::size_t i = 0; i < c_.size(); ++i)
        if (!std::isfinite(c_[i]))
            fail_input("cagd::BernsteinPolynomial",
                       "coefficient " + std::to_string(i) + " = " + full_precision(c_[i]) + " is not finite");
}

double BernsteinPolynomial::operator()(double t) const {
    std::vector<double> w = c_;
    for (std::size_t r = w.size() - 1; r > 0; --r)
        for (std::size_t i = 0; i < r; ++i) w[i] = (1.0 - t) * w[i] + t * w[i + 1];
    return w[0];
}

BernsteinPolynomial BernsteinPolynomial::derivative() const {
    const int d = degree();
    if (d == 0) return BernsteinPolynomial({0.0});
    std::vector<double> out(static_cast<std::size_t>(d));
    for (int i = 0; i < d; ++i) out[i] = d * (c_[i + 1] - c_[i]);
    return BernsteinPolynomial(std::move(out));
}

BernsteinPolynomial BernsteinPolynomial::elevated(int to_degree) const {
    if (to_degree < degree())
        fail_input("cagd::BernsteinPolynomial::elevated",
                   "target degree " + std::to_string(to_degree) + " below the degree " + std::to_string(degree()));
    std::vector<double> c = c_;
    for (int d = degree(); d < to_degree; ++d) {
        std::vector<double> e(static_cast<std::size_t>(d + 2));
        e[0] = c[0];
        e[d + 1] = c[d];
        for (int i = 1; i <= d; ++i) {
            const double a = static_cast<double>(i) / (d + 1);
            e[i] = a * c[i - 1] + (1.0 - a) * c[i];
        }
        c = std::move(e);
    }
    return BernsteinPolynomial(std::move(c));
}

BernsteinPolynomial BernsteinPolynomial::reduced() const {
    const int m = degree();
    if (m < 1) fail_input("cagd::BernsteinPolynomial::reduced", "degree 0 cannot be reduced");
    std::vector<double> b(static_cast<std::size_t>(m), 0.0);
    const int half = m / 2;
    // Elevation: c_i = (i/m) b_{i−1} + (1 − i/m) b_i.
    b[0] = c_[0];
    for (int i = 1; i < half; ++i) b[i] = (m * c_[i] - i * b[i - 1]) / (m - i);
    b[m - 1] = c_[m];
    for (int i = m - 1; i > half; --i) b[i - 1] = (m * c_[i] - (m - i) * b[i]) / i;
    return BernsteinPolynomial(std::move(b));
}

std::pair<BernsteinPolynomial, BernsteinPolynomial> BernsteinPolynomial::subdivide(double tau) const {
    const std::size_t n = c_.size();
    std::vector<double> w = c_, left(n), right(n);
    left[0] = w[0];
    right[n - 1] = w[n - 1];
    for (std::size_t r = 1; r < n; ++r) {
        for (std::size_t i = 0; i + r < n; ++i) w[i] = (1.0 - tau) * w[i] + tau * w[i + 1];
        left[r] = w[0];
        right[n - 1 - r] = w[n - 1 - r];
    }
    return {BernsteinPolynomial(std::move(left)), BernsteinPolynomial(std::move(right))};
}

BernsteinPolynomial& BernsteinPolynomial::operator*=(double s) {
    for (double& v : c_) v *= s;
    return *this;
}

BernsteinPolynomial operator+(const BernsteinPolynomial& a, const BernsteinPolynomial& b) {
    const int d = std::max(a.degree(), b.degree());
    std::vector<double> c = a.elevated(d).c_;
    const std::vector<double> e = b.elevated(d).c_;
    for (std::size_t i = 0; i < c.size(); ++i) c[i] += e[i];
    return BernsteinPolynomial(std::move(c));
}

BernsteinPolynomial operator-(const BernsteinPolynomial& a, const BernsteinPolynomial& b) { return a + (-1.0) * b; }

BernsteinPolynomial operator*(const BernsteinPolynomial& a, const BernsteinPolynomial& b) {
    const int m = a.degree(), k = b.degree();
    std::vector<double> c(static_cast<std::size_t>(m + k + 1), 0.0);
    // The binomials once per row (each is a loop of its own): O(mk) products instead of O(mk(m+k)),
    // the same values in the same order, so the same bits.
    const auto row = [](int n) {
        std::vector<double> r(static_cast<std::size_t>(n + 1));
        for (int i = 0; i <= n; ++i) r[static_cast<std::size_t>(i)] = binomial_double(n, i);
        return r;
    };
    const std::vector<double> bm = row(m), bk = row(k), bmk = row(m + k);
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= k; ++j) c[i + j] += a.c_[i] * b.c_[j] * bm[i] * bk[j] / bmk[i + j];
    return BernsteinPolynomial(std::move(c));
}

const char* to_string(SignOnInterval s) {
    switch (s) {
        case SignOnInterval::negative: return "negative";
        case SignOnInterval::positive: return "positive";
        case SignOnInterval::nonpositive: return "nonpositive";
        case SignOnInterval::nonnegative: return "nonnegative";
        case SignOnInterval::zero: return "zero";
        case SignOnInterval::changes_sign: return "changes_sign";
        case SignOnInterval::undetermined: return "undetermined";
    }
    return "?";
}

namespace {

struct SignSearch {
    int max_depth;
    double t_negative = -1.0, t_positive = -1.0;
    bool unresolved = false, all_strict = true;

    // A value is clearly signed when it exceeds the rounding level of the piece it belongs to.
    void note(double value, double t, double threshold) {
        if (value < -threshold && t_negative < 0) t_negative = t;
        if (value > threshold && t_positive < 0) t_positive = t;
    }
    // Visits [a, b]; stops early once both signs are witnessed.
    void visit(const BernsteinPolynomial& p, double a, double b, int depth) {
        if (t_negative >= 0 && t_positive >= 0) return;
        const auto& c = p.coefficients();
        const double threshold = 64.0 * std::numeric_limits<double>::epsilon() * max_abs(c);
        note(c.front(), a, threshold);
        note(c.back(), b, threshold);
        if (std::all_of(c.begin(), c.end(), [](double v) { return v < 0.0; })) return;
        if (std::all_of(c.begin(), c.end(), [](double v) { return v > 0.0; })) return;
        if (depth >= max_depth) {  // a piece of width 2^−max_depth that still mixes signs
            const bool nonpos = std::all_of(c.begin(), c.end(), [&](double v) { return v <= threshold; });
            const bool nonneg = std::all_of(c.begin(), c.end(), [&](double v) { return v >= -threshold; });
            if (nonpos || nonneg)
                all_strict = false;  // touches zero within rounding
            else
                unresolved = true;
            return;
        }
        const auto halves = p.subdivide(0.5);
        const double mid = 0.5 * (a + b);
        visit(halves.first, a, mid, depth + 1);
        visit(halves.second, mid, b, depth + 1);
    }
};

}  // namespace

SignAnalysis sign_on_unit_interval(const BernsteinPolynomial& p, int max_depth) {
    const double scale = max_abs(p.coefficients());
    SignAnalysis out;
    if (scale == 0.0) {
        out.sign = SignOnInterval::zero;
        return out;
    }
    SignSearch search{max_depth};
    search.visit(p, 0.0, 1.0, 0);
    out.t_negative = search.t_negative;
    out.t_positive = search.t_positive;
    const bool neg = search.t_negative >= 0, pos = search.t_positive >= 0;
    if (neg && pos) {
        out.sign = SignOnInterval::changes_sign;
    } else if (search.unresolved) {
        out.sign = SignOnInterval::undetermined;
    } else if (!neg && !pos) {
        out.sign = SignOnInterval::zero;
    } else if (neg) {
        out.sign = search.all_strict ? SignOnInterval::negative : SignOnInterval::nonpositive;
    } else {
        out.sign = search.all_strict ? SignOnInterval::positive : SignOnInterval::nonnegative;
    }
    if (out.sign != SignOnInterval::changes_sign) out.t_negative = out.t_positive = -1.0;
    return out;
}

namespace {

void require_basis_arguments(int degree, double t) {
    if (degree < 0) fail_input("cagd::bernstein_basis_values", "degree " + std::to_string(degree) + " < 0");
    if (!(t >= 0.0 && t <= 1.0))
        fail_input("cagd::bernstein_basis_values", "t = " + full_precision(t) + " outside [0, 1]");
}

// B_{0..d,d}(t) by the triangle of convex combinations (d ≤ kSmallBernsteinDegree).
void small_degree_basis(int d, double t, double* b) {
    const double s = 1.0 - t;
    b[0] = 1.0;
    for (int k = 1; k <= d; ++k) {
        b[k] = t * b[k - 1];
        for (int i = k - 1; i > 0; --i) b[i] = s * b[i] + t * b[i - 1];
        b[0] *= s;
    }
}

}  // namespace

void bernstein_basis_values(int degree, double t, std::span<double> out) {
    require_basis_arguments(degree, t);
    if (out.size() != static_cast<std::size_t>(degree) + 1)
        fail_input("cagd::bernstein_basis_values", "output holds " + std::to_string(out.size()) + " values; degree " +
                                                       std::to_string(degree) + " needs " + std::to_string(degree + 1));
    if (degree <= kSmallBernsteinDegree) {
        small_degree_basis(degree, t, out.data());
        return;
    }
    const std::vector<double> b = bernstein_basis_values(degree, t);
    std::copy(b.begin(), b.end(), out.begin());
}

std::vector<double> bernstein_basis_values(int degree, double t) {
    require_basis_arguments(degree, t);
    const int d = degree;
    std::vector<double> b(static_cast<std::size_t>(d + 1), 0.0);
    if (d <= kSmallBernsteinDegree) {
        small_degree_basis(d, t, b.data());
        return b;
    }
    if (t == 0.0 || t == 1.0) {
        b[t == 0.0 ? 0 : d] = 1.0;
        return b;
    }
    const int mode = std::clamp(static_cast<int>(std::lround(d * t)), 0, d);
    const double log_mode = std::lgamma(d + 1.0) - std::lgamma(mode + 1.0) - std::lgamma(d - mode + 1.0) +
                            mode * std::log(t) + (d - mode) * std::log1p(-t);
    b[mode] = std::exp(log_mode);
    const double ratio = t / (1.0 - t);
    for (int i = mode; i < d; ++i) b[i + 1] = b[i] * (d - i) / (i + 1.0) * ratio;
    for (int i = mode; i > 0; --i) b[i - 1] = b[i] * i / (d - i + 1.0) / ratio;
    double sum = 0.0;
    for (double v : b) sum += v;
    for (double& v : b) v /= sum;
    return b;
}

}  // namespace cagd
