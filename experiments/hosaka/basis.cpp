// hosaka section 2, eq (1)–(14): Hosaka's generalised Hermite basis p_i(m, t), q_i(m, t).
// Every printed identity is checked exactly (rational arithmetic) for m = 0..5, every i, every
// derivative order it speaks of; a claim's value is the number of (m, i, k) cases where the
// printed statement fails (the paper's value: 0). Printed formulas are transcribed here as
// printed (OCR text); where one fails, the corrected formula is checked too (reference/ERRATA.md).
#include <functional>
#include <string>

#include "cagd/core/rational_polynomial.hpp"
#include "cagd/spline/hosaka_basis.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using cagd::spline::hosaka_p;
using cagd::spline::hosaka_q;

namespace {

constexpr int kMaxM = 5;
const Rational kZero = 0, kOne = 1;

Rational sign(int e) { return (e % 2 == 0) ? Rational(1) : Rational(-1); }
// 1/n! with 1/n! = 0 for negative n (the convention that ends the paper's sums)
Rational inv_factorial(int n) { return n < 0 ? Rational(0) : Rational(1) / factorial(n); }

Rational derivative_at(const RationalPolynomial& p, int k, const Rational& t) { return p.derivative(k)(t); }

// Count the (m, i, k) cases, m = 0..5, i = 0..m, k in [k_lo(m), k_hi(m)], where `holds` is false.
long count_failures(const std::function<int(int)>& k_lo, const std::function<int(int)>& k_hi,
                    const std::function<bool(int, int, int)>& holds) {
    long failures = 0;
    for (int m = 0; m <= kMaxM; ++m)
        for (int i = 0; i <= m; ++i)
            for (int k = k_lo(m); k <= k_hi(m); ++k) failures += holds(m, i, k) ? 0 : 1;
    return failures;
}

// eq (7) as printed, first line: p_i^{(k)}(m, 0) = (1/i!) Σ_{j=0}^{m−i} (−1)^{i+j−k} (2m+1)! k / (j! (k−i−j)!
// (2m+1−k)!)
Rational eq7_p0_printed(int m, int i, int k) {
    Rational s = 0;
    for (int j = 0; j <= m - i; ++j)
        s += sign(i + j - k) * factorial(2 * m + 1) * k * inv_factorial(j) * inv_factorial(k - i - j) *
             inv_factorial(2 * m + 1 - k);
    return s / factorial(i);
}
// ... corrected (derived by differentiating eq 2 at t = 0): (2m+1−i)! k! in the numerator.
Rational eq7_p0_corrected(int m, int i, int k) {
    Rational s = 0;
    for (int j = 0; j <= m - i; ++j)
        s += sign(i + j - k) * factorial(2 * m + 1 - i) * factorial(k) * inv_factorial(j) * inv_factorial(k - i - j) *
             inv_factorial(2 * m + 1 - k);
    return s / factorial(i);
}
// eq (7) as printed, second line: p_i^{(k)}(m, 1) = (1/i!) Σ_j (−1)^{i+j−k} (2m+1−i)!/(j!(2m+1−i−j)!) ·
// k!(i+j)!/((k−2m−1+i+j)!(2m+1−k)!)
Rational eq7_p1(int m, int i, int k, bool printed_sign) {
    Rational s = 0;
    for (int j = 0; j <= m - i; ++j)
        s += sign(printed_sign ? i + j - k : i + j - 1) * factorial(2 * m + 1 - i) * inv_factorial(j) *
             inv_factorial(2 * m + 1 - i - j) * factorial(k) * factorial(i + j) * inv_factorial(k - 2 * m - 1 + i + j) *
             inv_factorial(2 * m + 1 - k);
    return s / factorial(i);
}

// The constants of eq (11).
Rational p_m1_at_0(int m, int i) {
    return -Rational(m + 1) * factorial(2 * m + 1 - i) / (factorial(i) * factorial(m + 1 - i));
}
Rational p_m1_at_1(int m, int i) { return sign(m - 1) * factorial(2 * m + 1 - i) / (factorial(i) * factorial(m - i)); }
Rational q_m1_at_0(int m, int i) { return sign(m + i - 1) * p_m1_at_1(m, i); }
Rational q_m1_at_1(int m, int i) { return sign(m + i - 1) * p_m1_at_0(m, i); }

}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run("hosaka", "basis", "2", "Hosaka's generalised Hermite basis p_i(m, t), q_i(m, t) (eq 1-14)",
                           argc, argv);
    const auto zero_to_m = [](int m) { return m; };
    const auto from_0 = [](int) { return 0; };
    const auto above_m = [](int m) { return m + 1; };
    const auto to_2m1 = [](int m) { return 2 * m + 1; };
    const auto none_k = [](int) { return 0; };

    // (3), (4), (5): end derivatives up to order m.
    run.check("eq3.p_at_0", double(count_failures(from_0, zero_to_m, [](int m, int i, int k) {
                  return derivative_at(hosaka_p(m, i), k, kZero) == (i == k ? kOne : kZero);
              })));
    run.check("eq4.q_at_1", double(count_failures(from_0, zero_to_m, [](int m, int i, int k) {
                  return derivative_at(hosaka_q(m, i), k, kOne) == (i == k ? kOne : kZero);
              })));
    run.check("eq5.p_at_1_and_q_at_0", double(count_failures(from_0, zero_to_m, [](int m, int i, int k) {
                  return derivative_at(hosaka_p(m, i), k, kOne) == 0 && derivative_at(hosaka_q(m, i), k, kZero) == 0;
              })));
    // (1): the representation reproduces every polynomial of degree 2m+1 (checked on t^d, d ≤ 2m+1).
    long rep_failures = 0;
    for (int m = 0; m <= kMaxM; ++m)
        for (int d = 0; d <= 2 * m + 1; ++d) {
            const RationalPolynomial phi = RationalPolynomial::monomial(d);
            RationalPolynomial sum;
            for (int i = 0; i <= m; ++i)
                sum += hosaka_p(m, i) * derivative_at(phi, i, kZero) + hosaka_q(m, i) * derivative_at(phi, i, kOne);
            rep_failures += sum == phi ? 0 : 1;
        }
    run.check("eq1.representation", double(rep_failures));

    // (7): derivatives above m at the ends.
    const auto p0_printed = count_failures(above_m, to_2m1, [](int m, int i, int k) {
        return derivative_at(hosaka_p(m, i), k, kZero) == eq7_p0_printed(m, i, k);
    });
    const auto p0_corrected = count_failures(above_m, to_2m1, [](int m, int i, int k) {
        return derivative_at(hosaka_p(m, i), k, kZero) == eq7_p0_corrected(m, i, k);
    });
    run.check("eq7.p_high_at_0", double(p0_printed), double(p0_corrected));
    const auto p1_printed = count_failures(above_m, to_2m1, [](int m, int i, int k) {
        return derivative_at(hosaka_p(m, i), k, kOne) == eq7_p1(m, i, k, true);
    });
    const auto p1_corrected = count_failures(above_m, to_2m1, [](int m, int i, int k) {
        return derivative_at(hosaka_p(m, i), k, kOne) == eq7_p1(m, i, k, false);
    });
    run.check("eq7.p_high_at_1", double(p1_printed), double(p1_corrected));
    run.check("eq7.symmetry_at_0", double(count_failures(above_m, to_2m1, [](int m, int i, int k) {
                  return derivative_at(hosaka_p(m, i), k, kZero) ==
                         sign(i + k) * derivative_at(hosaka_q(m, i), k, kOne);
              })));
    run.check("eq7.symmetry_at_1", double(count_failures(above_m, to_2m1, [](int m, int i, int k) {
                  return derivative_at(hosaka_p(m, i), k, kOne) ==
                         sign(i + k) * derivative_at(hosaka_q(m, i), k, kZero);
              })));

    // (8), (9).
    run.check("eq8.reflection", double(count_failures(from_0, none_k, [](int m, int i, int) {
                  return hosaka_p(m, i) == hosaka_q(m, i).compose_one_minus() * sign(i) &&
                         hosaka_q(m, i) == hosaka_p(m, i).compose_one_minus() * sign(i);
              })));
    long eq9a = 0, eq9b = 0;
    for (int m = 0; m <= kMaxM; ++m) {
        eq9a += hosaka_p(m, 0) + hosaka_q(m, 0) == RationalPolynomial::constant(1) ? 0 : 1;
        if (m >= 1) eq9b += hosaka_q(m, 0) + hosaka_p(m, 1) + hosaka_q(m, 1) == RationalPolynomial::monomial(1) ? 0 : 1;
    }
    run.check("eq9.partition_of_unity", double(eq9a));
    run.check("eq9.reproduces_t", double(eq9b));

    // (10) with the constants of (11).
    const RationalPolynomial t = RationalPolynomial::monomial(1), t_minus_1 = RationalPolynomial::linear(-1, 1);
    long eq10a = 0;
    for (int m = 0; m <= kMaxM; ++m) {
        const RationalPolynomial rhs =
            t.power(m) * t_minus_1.power(m) * (sign(m - 1) * factorial(2 * m + 1) / (factorial(m) * factorial(m)));
        eq10a += hosaka_p(m, 0).derivative() == rhs && hosaka_q(m, 0).derivative() == rhs * Rational(-1) ? 0 : 1;
    }
    run.check("eq10.p0_derivative", double(eq10a));
    const auto pm = [](int m) { return hosaka_p(m, m); };
    const auto qm = [](int m) { return hosaka_q(m, m); };
    const auto p_prev = [](int m, int i) { return i == 0 ? RationalPolynomial() : hosaka_p(m, i - 1); };
    const auto q_prev = [](int m, int i) { return i == 0 ? RationalPolynomial() : hosaka_q(m, i - 1); };
    run.check("eq10.second", double(count_failures(from_0, none_k, [&](int m, int i, int) {
                  return (hosaka_p(m, i) * Rational(-i) + p_prev(m, i) + hosaka_p(m, i).derivative() * t_minus_1 +
                          pm(m) * p_m1_at_0(m, i))
                      .is_zero();
              })));
    run.check(
        "eq10.third", double(count_failures(from_0, none_k, [&](int m, int i, int) {
            return (hosaka_p(m, i) * Rational(i) - hosaka_p(m, i).derivative() * t + qm(m) * p_m1_at_1(m, i)).is_zero();
        })));
    // Fourth line as printed: −i p_i + q_i'(t − 1) + q_i^{(m+1)}(m, 0) p_m = 0; corrected: −i q_i.
    const auto fourth = [&](bool printed) {
        return count_failures(from_0, none_k, [&, printed](int m, int i, int) {
            const RationalPolynomial first = (printed ? hosaka_p(m, i) : hosaka_q(m, i)) * Rational(-i);
            return (first + hosaka_q(m, i).derivative() * t_minus_1 + pm(m) * q_m1_at_0(m, i)).is_zero();
        });
    };
    run.check("eq10.fourth", double(fourth(true)), double(fourth(false)));
    run.check("eq10.fifth", double(count_failures(from_0, none_k, [&](int m, int i, int) {
                  return (hosaka_q(m, i) * Rational(i) + q_prev(m, i) - hosaka_q(m, i).derivative() * t +
                          qm(m) * q_m1_at_1(m, i))
                      .is_zero();
              })));

    // (11): p_m, q_m and the (m+1)-th end derivatives.
    long eq11_pm = 0, eq11_const = 0;
    for (int m = 0; m <= kMaxM; ++m) {
        eq11_pm += pm(m) == t.power(m) * t_minus_1.power(m + 1) * (sign(m - 1) / factorial(m)) &&
                           qm(m) == t.power(m + 1) * t_minus_1.power(m) * (Rational(1) / factorial(m))
                       ? 0
                       : 1;
        for (int i = 0; i <= m; ++i) {
            eq11_const += derivative_at(hosaka_p(m, i), m + 1, kZero) == p_m1_at_0(m, i) ? 0 : 1;
            eq11_const += derivative_at(hosaka_p(m, i), m + 1, kOne) == p_m1_at_1(m, i) ? 0 : 1;
            eq11_const += derivative_at(hosaka_q(m, i), m + 1, kZero) == q_m1_at_0(m, i) ? 0 : 1;
            eq11_const += derivative_at(hosaka_q(m, i), m + 1, kOne) == q_m1_at_1(m, i) ? 0 : 1;
        }
    }
    run.check("eq11.pm_qm", double(eq11_pm));
    run.check("eq11.constants", double(eq11_const));

    // (12)–(14): the explicit polynomials for m = 0, 1, 2.
    const auto poly = [](std::initializer_list<int> c) {
        std::vector<Rational> v;
        for (int x : c) v.emplace_back(x);
        return RationalPolynomial(v);
    };
    const RationalPolynomial one = RationalPolynomial::constant(1);
    const auto same = [](const RationalPolynomial& a, const RationalPolynomial& b) { return a == b ? 0.0 : 1.0; };
    run.check("eq12.m0_p0", same(hosaka_p(0, 0), poly({1, -1})));
    run.check("eq12.m0_q0", same(hosaka_q(0, 0), t));
    const RationalPolynomial f = t.power(2) * poly({3, -2});
    run.check("eq12.m1_q0", same(hosaka_q(1, 0), f));
    run.check("eq12.m1_p0", same(hosaka_p(1, 0), one - f));
    run.check("eq12.m1_p1", same(hosaka_p(1, 1), t * t_minus_1.power(2)));
    run.check("eq12.m1_q1", same(hosaka_q(1, 1), t.power(2) * t_minus_1));
    const RationalPolynomial q20 = t.power(3) * poly({10, -15, 6});
    run.check("eq14.m2_q0", same(hosaka_q(2, 0), q20));
    run.check("eq14.m2_p0", same(hosaka_p(2, 0), one - q20));
    run.check("eq14.m2_p1", same(hosaka_p(2, 1), t * t_minus_1.power(3) * poly({1, 3}) * Rational(-1)));
    run.check("eq14.m2_q1", same(hosaka_q(2, 1), t.power(3) * t_minus_1 * poly({-4, 3}) * Rational(-1)));
    run.check("eq14.m2_p2", same(hosaka_p(2, 2), t.power(2) * t_minus_1.power(3) * Rational(-1, 2)));
    run.check("eq14.m2_q2", same(hosaka_q(2, 2), t.power(3) * t_minus_1.power(2) * Rational(1, 2)));

    // Validation: the double basis against the exact one.
    double worst = 0.0;
    for (int m = 0; m <= kMaxM; ++m) {
        const spline::HosakaBasis b(m);
        for (int i = 0; i <= m; ++i)
            for (int k = 0; k <= 2 * m + 1; ++k)
                for (int s = 0; s <= 16; ++s) {
                    const Rational tr(s, 16);
                    const double tt = s / 16.0;
                    worst = std::max(
                        {worst, std::abs(b.p(i, tt, k) - static_cast<double>(derivative_at(hosaka_p(m, i), k, tr))),
                         std::abs(b.q(i, tt, k) - static_cast<double>(derivative_at(hosaka_q(m, i), k, tr)))});
                }
    }
    run.validate("basis.double_vs_exact",
                 "HosakaBasis (double, Horner) vs the exact rational basis: max |difference| over m ≤ 5, all i, k ≤ "
                 "2m+1, t = s/16",
                 worst, 0.0, 1e-7, "rounding of coefficients up to 11!/… ≈ 1e6 in the 11th derivative, relative 1e-13");
    // Figure: the basis for m = 1 and m = 2 (what eq 12 and 14 print).
    {
        CsvWriter fig = run.table("fig_basis.csv", {"t", "m1_p0", "m1_q0", "m1_p1", "m1_q1", "m2_p0", "m2_q0", "m2_p1",
                                                    "m2_q1", "m2_p2", "m2_q2"});
        const spline::HosakaBasis b1(1), b2(2);
        for (int s = 0; s <= 200; ++s) {
            const double tt = s / 200.0;
            fig.row({tt, b1.p(0, tt), b1.q(0, tt), b1.p(1, tt), b1.q(1, tt), b2.p(0, tt), b2.q(0, tt), b2.p(1, tt),
                     b2.q(1, tt), b2.p(2, tt), b2.q(2, tt)});
        }
        run.figure("fig_basis",
                   "The generalised Hermite basis p_i(m, t), q_i(m, t) of eq (2) for m = 1 (cubic, eq 12) and m = 2 "
                   "(quintic, eq 14).");
    }
    run.note(
        "Exact rational arithmetic (Boost.Multiprecision cpp_rational) for m = 0..5; a claim counts the (m, i, k) "
        "cases where the printed statement fails.");
    return run.finish();
}
