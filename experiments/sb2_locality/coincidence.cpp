// sb2_locality, eq (9)–(11): when the S-/B2-spline equals the conventional cubic B-spline
// interpolant, and the series (11) for the extra control point. Data: 12 points on the
// closed curve (2cos θ + 0.3cos 3θ, sin θ + 0.2 sin 2θ), θ = 2πk/12 (chosen; the paper gives
// none) — closed, so no end condition enters.
#include <cmath>
#include <numbers>

#include "cagd/locality/locality_spline.hpp"
#include "cagd/spline/bspline.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::locality;

namespace {
// Control point of `c` whose local knots are exactly `local` (degree+2 values), or −1.
Eigen::Index control_with_knots(const BSplineCurve& c, const std::vector<double>& local) {
    const auto& k = c.knots();
    for (std::size_t j = 0; j + local.size() <= k.size(); ++j) {
        bool same = true;
        for (std::size_t r = 0; r < local.size() && same; ++r) same = std::abs(k[j + r] - local[r]) < 1e-12;
        if (same) return static_cast<Eigen::Index>(j);
    }
    return -1;
}
}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run("sb2_locality", "coincidence", "2.3",
                           "Coincidence with the conventional interpolant (eq 9–11)", argc, argv);
    const int n = 12;
    PointList p(n, 2);
    for (int k = 0; k < n; ++k) {
        const double t = 2 * std::numbers::pi * k / n;
        p.row(k) << 2 * std::cos(t) + 0.3 * std::cos(3 * t), std::sin(t) + 0.2 * std::sin(2 * t);
    }
    const double diag = bounding_box_diagonal(p);
    run.note(
        "Data: 12 points (2cos θ + 0.3cos 3θ, sin θ + 0.2 sin 2θ), θ = 2πk/12, closed; residuals divided by the "
        "bounding-box diagonal " +
        format_number(diag, 6) + ".");

    // α measured from eq (10): impulse response of the (1,4,1)/6 system, far from the ends.
    PointList impulse = PointList::Zero(201, 2);
    for (int i = 0; i < 201; ++i) impulse(i, 0) = i;
    impulse(100, 1) = 1.0;
    const BSplineCurve ci = cubic_bspline_interpolant(impulse, false);
    const double ratio = ci.control_points()(1 + 106, 1) / ci.control_points()(1 + 105, 1);
    run.check("eq11.alpha", ratio);
    run.validate("eq11.alpha_root", "α from the impulse response vs the root −2+√3 of α² + 4α + 1 = 0", ratio, alpha(),
                 1e-12, "SparseLU solve of a diagonally dominant system; rounding");
    run.check("eq11.constant", std::abs(std::sqrt(3.0) * (1 + alpha()) - (1 - alpha())));

    // The conventional interpolant, its B2 form (knot insertion) and S form (degree elevation).
    const BSplineCurve cubic = cubic_bspline_interpolant(p, true);
    const auto c = [&](int i) -> Eigen::RowVector2d {  // c_i, periodic; control i+1 of `cubic`
        return cubic.control_points().row(((i % n) + n) % n + 1);
    };
    BSplineCurve b2 = cubic;
    for (int i = 0; i < n; ++i) b2 = insert_knot(b2, i + 0.5);
    const auto d = [&](int j) -> Eigen::RowVector2d {  // d_j: local knots (j−2)/2 … (j+2)/2
        std::vector<double> local;
        for (int r = -2; r <= 2; ++r) local.push_back((j + r) / 2.0);
        const Eigen::Index idx = control_with_knots(b2, local);
        return idx < 0 ? Eigen::RowVector2d(NAN, NAN) : Eigen::RowVector2d(b2.control_points().row(idx));
    };
    const BSplineCurve s = elevate_degree(cubic);
    const auto dhat_odd = [&](int i) -> Eigen::RowVector2d {  // d̂_{2i+1}: knots i−1, i, i, i+1, i+1, i+2
        const Eigen::Index idx = control_with_knots(s, {i - 1.0, double(i), double(i), i + 1.0, i + 1.0, i + 2.0});
        return idx < 0 ? Eigen::RowVector2d(NAN, NAN) : Eigen::RowVector2d(s.control_points().row(idx));
    };
    double printed = 0, corrected = 0, b2_mid = 0, s_mid = 0, eq3 = 0;
    for (int i = 1; i + 2 < n; ++i) {
        const Eigen::RowVector2d rhs = 3.0 * (p.row(i) + p.row(i + 1));
        printed = std::max(printed, (d(2 * i - 1) + 4 * d(2 * i) + d(2 * i + 1) - rhs).norm() / diag);
        corrected = std::max(corrected, (d(2 * i - 1) + 4 * d(2 * i + 1) + d(2 * i + 3) - rhs).norm() / diag);
        eq3 = std::max(eq3,
                       (d(2 * i - 1) + 4 * d(2 * i) + d(2 * i + 1) - 6.0 * Eigen::RowVector2d(p.row(i))).norm() / diag);
        b2_mid = std::max(b2_mid, (d(2 * i + 1) - 0.5 * (c(i) + c(i + 1))).norm() / diag);
        s_mid = std::max(s_mid, (dhat_odd(i) - 0.5 * (c(i) + c(i + 1))).norm() / diag);
    }
    run.check("eq9.b2_condition", printed, corrected);
    run.validate("eq3.on_b2_form",
                 "eq (3) d_{2i−1} + 4d_{2i} + d_{2i+1} = 6p_i on the knot-inserted interpolant (max residual / diag)",
                 eq3, 0.0, 1e-12, "rounding of knot insertion");
    run.check("eq9.b2_midpoint", b2_mid);
    run.check("eq9.s_midpoint", s_mid);

    // eq (11): printed (p_{i−j} + p_{i+j})/2 against corrected q_{i,j} = (p_{i−j} + p_{i+j+1})/2.
    const auto P = [&](int k) -> Eigen::RowVector2d { return p.row(((k % n) + n) % n); };
    double series_printed = 0, series_corrected = 0;
    for (int i = 0; i < n; ++i) {
        Eigen::RowVector2d a = Eigen::RowVector2d::Zero(), b = Eigen::RowVector2d::Zero();
        double power = 1.0;
        for (int j = 0; j <= 60; ++j, power *= alpha()) {
            a += power * 0.5 * (P(i - j) + P(i + j));
            b += power * 0.5 * (P(i - j) + P(i + j + 1));
        }
        const Eigen::RowVector2d target = 0.5 * (c(i) + c(i + 1));
        series_printed = std::max(series_printed, (std::sqrt(3.0) * (1 + alpha()) * a - target).norm() / diag);
        series_corrected = std::max(series_corrected, (std::sqrt(3.0) * (1 + alpha()) * b - target).norm() / diag);
    }
    run.check("eq11.series", series_printed, series_corrected);
    run.note("With the corrections of errata E1 and E2: eq (9) residual " + format_number(corrected, 3) +
             ", eq (11) deviation " + format_number(series_corrected, 3) + " (relative to the diagonal).");
    return run.finish();
}
