// hosaka section 3, eq (21)–(24): the explicit form y(x), z(x) of the C2 spline, its slope equations
// (23), and the claim that it minimises ∫ (y''² + z''²) dx (eq 24; the paper proves it in section 6).
// Data (ours; the paper gives none): x = 0, 0.5, 1.7, 2.0, 3.1, 4.5, 5.0 (uneven steps),
// y = sin 1.3x, z = cos 0.8x.
// Minimality is checked by perturbation: every C2 piecewise quintic with the same values at the
// abscissae (Hosaka's m = 2 segments, eq 15, with end data y, y', y'' at each abscissa) is an
// admissible competitor; 2000 random ones (slopes and second derivatives perturbed, seeded) must
// all have at least the spline's energy. The spline itself is such a quintic (its own y', y'').
#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "cagd/numeric/gauss_legendre.hpp"
#include "cagd/spline/hosaka_spline.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::spline;

namespace {

// ∫ |y''(x)|² dx of the C2 quintic through (x_i, Y_i) with slopes S_i and second derivatives C_i.
double quintic_energy(const std::vector<double>& x, const Eigen::MatrixXd& Y, const Eigen::MatrixXd& S,
                      const Eigen::MatrixXd& C) {
    static const HosakaBasis b(2);
    static const numeric::GaussLegendreRule rule(6);  // exact: y''² has degree 6
    double e = 0.0;
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
        const Eigen::Index a = static_cast<Eigen::Index>(i), c = a + 1;
        const double l = x[i + 1] - x[i];
        e += rule.integrate(
            [&](double u) {
                const Eigen::RowVectorXd y2 = (b.p(0, u, 2) * Y.row(a) + b.q(0, u, 2) * Y.row(c) +
                                               l * (b.p(1, u, 2) * S.row(a) + b.q(1, u, 2) * S.row(c)) +
                                               l * l * (b.p(2, u, 2) * C.row(a) + b.q(2, u, 2) * C.row(c))) /
                                              (l * l);
                return y2.squaredNorm() * l;
            },
            0.0, 1.0);
    }
    return e;
}

// Largest jump of y'' across the interior abscissae for given slopes, relative to max |y''|.
double second_derivative_jump(const std::vector<double>& x, const Eigen::MatrixXd& Y, const Eigen::MatrixXd& slopes) {
    const ExplicitSpline s{x, Y, slopes};
    double jump = 0.0, size = 0.0;
    for (std::size_t i = 1; i + 1 < x.size(); ++i) {
        // y'' at x_i from the left interval and from the right one.
        const Eigen::RowVectorXd left = s.evaluate_in(static_cast<int>(i) - 1, 1.0, 2),
                                 right = s.evaluate_in(static_cast<int>(i), 0.0, 2);
        jump = std::max(jump, (left - right).norm());
        size = std::max({size, left.norm(), right.norm()});
    }
    return jump / size;
}

}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run("hosaka", "explicit_form", "3",
                           "The explicit form y(x), z(x) and its minimum property (eq 21-24)", argc, argv);
    const std::vector<double> x{0, 0.5, 1.7, 2.0, 3.1, 4.5, 5.0};
    const int n = static_cast<int>(x.size());
    Eigen::MatrixXd Y(n, 2);
    for (int i = 0; i < n; ++i)
        Y.row(i) << std::sin(1.3 * x[static_cast<std::size_t>(i)]), std::cos(0.8 * x[static_cast<std::size_t>(i)]);
    const ExplicitSpline spline = hosaka_explicit_spline(x, Y);

    // Eq (23) as printed: right-hand side 3/(x_i − x_{i−1}) (y_i − y_{i−1}) + 3/(x_{i+1} − x_i) (y_{i+1} − y_i),
    // the natural end rows as in the library.
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n), rhs(n, 2);
    const auto h = [&](int i) { return x[static_cast<std::size_t>(i + 1)] - x[static_cast<std::size_t>(i)]; };
    M(0, 0) = 2;
    M(0, 1) = 1;
    rhs.row(0) = 3 * (Y.row(1) - Y.row(0)) / h(0);
    for (int i = 1; i + 1 < n; ++i) {
        M(i, i - 1) = 1 / h(i - 1);
        M(i, i) = 2 * (1 / h(i - 1) + 1 / h(i));
        M(i, i + 1) = 1 / h(i);
        rhs.row(i) = 3 / h(i - 1) * (Y.row(i) - Y.row(i - 1)) + 3 / h(i) * (Y.row(i + 1) - Y.row(i));
    }
    M(n - 1, n - 2) = 1;
    M(n - 1, n - 1) = 2;
    rhs.row(n - 1) = 3 * (Y.row(n - 1) - Y.row(n - 2)) / h(n - 2);
    const Eigen::MatrixXd printed_slopes = M.partialPivLu().solve(rhs);
    run.check("eq23.c2_at_joins", second_derivative_jump(x, Y, printed_slopes),
              second_derivative_jump(x, Y, spline.slopes));

    // Natural ends and interpolation.
    double ends = std::max(spline.evaluate(x.front(), 2).norm(), spline.evaluate(x.back(), 2).norm());
    run.check("eq23.natural_ends", ends / spline.evaluate(x[3], 2).norm());

    // Eq (24) by perturbation.
    Eigen::MatrixXd C(n, 2);
    for (int i = 0; i < n; ++i) C.row(i) = spline.evaluate(x[static_cast<std::size_t>(i)], 2);
    const double e_spline = spline.bending_energy();
    run.validate("eq24.quintic_energy_of_the_spline",
                 "the spline written as a C2 quintic (its own y', y'') has the spline's energy: relative difference",
                 std::abs(quintic_energy(x, Y, spline.slopes, C) - e_spline) / e_spline, 0.0, 1e-12,
                 "Gauss-Legendre exact for the degree, rounding");
    std::mt19937 rng(24);
    std::normal_distribution<double> g(0.0, 1.0);
    int lower = 0;
    double min_increase = INFINITY;
    for (int trial = 0; trial < 2000; ++trial) {
        const double eps = std::pow(10.0, -3.0 + 3.0 * (trial % 4) / 3.0);  // 1e-3, 1e-2, 1e-1, 1
        Eigen::MatrixXd S = spline.slopes, Cp = C;
        for (int i = 0; i < n; ++i)
            for (int d = 0; d < 2; ++d) {
                S(i, d) += eps * g(rng);
                Cp(i, d) += eps * g(rng);
            }
        const double e = quintic_energy(x, Y, S, Cp);
        if (e < e_spline * (1 - 1e-12)) ++lower;
        min_increase = std::min(min_increase, (e - e_spline) / e_spline);
    }
    run.check("eq24.no_lower_energy", lower);
    run.note(
        "Eq (24): 2000 C2 quintic interpolants of the same data with slopes and second derivatives perturbed by ε·N(0, "
        "1), ε = 1e-3, 1e-2, 0.1, 1 (seeded); the smallest relative "
        "energy increase was " +
        format_number(min_increase, 3) +
        " (ε = 1e-3 gives increases of order ε², as a minimum should). Spline energy ∫(y''² + z''²) dx = " +
        format_number(e_spline, 10) + ".");

    CsvWriter fig = run.table("fig_explicit.csv", {"x", "y", "z", "y2", "z2"});
    for (int k = 0; k <= 500; ++k) {
        const double xx = x.front() + (x.back() - x.front()) * k / 500.0;
        const Eigen::RowVectorXd v = spline.evaluate(xx), v2 = spline.evaluate(xx, 2);
        fig.row({xx, v(0), v(1), v2(0), v2(1)});
    }
    run.figure("fig_explicit",
               "The explicit form y(x), z(x) of eq (21)-(23) through our data (left) and its second derivatives, "
               "continuous and zero at the ends (right).");
    return run.finish();
}
