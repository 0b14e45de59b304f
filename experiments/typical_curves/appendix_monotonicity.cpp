// typical_curves section 3.4 and appendix A: curvature monotonicity of cubic B-spline segments.
// The printed coefficients C0 … C5 of h(t) (A.1) against h computed exactly from the Bézier points
// (Bernstein products, analysis::curvature_derivative_numerator); eq (29)–(30); which coefficient
// decides; Fig. 7's regions on a 1000 × 1000 grid of [0, π/2]² (figure data on a 401 × 401 grid)
// with a third, exact classification (sign of dκ/dt by Bernstein subdivision); the same over
// (0, π)²; the endpoint-interpolating rules of A.2 and the whole-curve checker.
// Data (ours; the paper gives none): angle grids as stated; for the checker, the scale-1 typical
// polygons of Fig. 1 (α = −0.5, L = 1, degrees 24, 49, 99) and 200 random unit-edge polygons.
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "cagd/aesthetic/cubic_bspline_monotonicity.hpp"
#include "cagd/aesthetic/typical_bezier.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::aesthetic;

namespace {

// The paper's formulas exactly as transcribed (the OCR closes the bracket of C2 after "− θ1"
// and of C3 after the 14-term; C3 ends in sin(θ0 + 3θ1/2)).
std::array<double, 6> printed_coefficients(double a, double b) {
    using std::cos;
    using std::sin;
    const double C0 = std::pow(cos(a / 2), 3) * (sin(a / 2 + b) - 3 * sin(a / 2));
    const double C1 = -0.4 * (2 - 4 * cos(a) + cos(b) + cos(a + b)) * sin(a) -
                      std::pow(cos(a / 2), 3) * (3 * sin(a / 2) - sin(a / 2 + b));
    const double C2 = (-22 * sin(a) + 7 * sin(2 * a) - 2 * cos(a / 2) * (32 * sin(a / 2) - b) + 14 * sin(a / 2 + b) -
                       6 * sin(1.5 * a + b) + sin(a / 2 + 2 * b) + sin(1.5 * a + 2 * b)) /
                      40;
    const double C3 = -(-22 * sin(b) + 7 * sin(2 * b) - 2 * cos(b / 2) * (-32 * sin(a - b / 2) + 14 * sin(a + b / 2)) -
                        6 * sin(a + 1.5 * b) + sin(2 * a + b / 2) + sin(a + 1.5 * b)) /
                      40;
    const double C4 = 0.4 * (2 + cos(a) - 4 * cos(b) + cos(a + b)) * sin(b) +
                      std::pow(cos(b / 2), 3) * (3 * sin(b / 2) - sin(a + b / 2));
    const double C5 = -std::pow(cos(b / 2), 3) * (sin(a + b / 2) - 3 * sin(b / 2));
    return {C0, C1, C2, C3, C4, C5};
}
// The damaged ones read with the bracket running to the end, and C3's last term sin(2θ0 + 3θ1/2).
double printed_c2_bracket_extended(double a, double b) {
    using std::cos;
    using std::sin;
    return (-22 * sin(a) + 7 * sin(2 * a) -
            2 * cos(a / 2) *
                (32 * sin(a / 2 - b) + 14 * sin(a / 2 + b) - 6 * sin(1.5 * a + b) + sin(a / 2 + 2 * b) +
                 sin(1.5 * a + 2 * b))) /
           40;
}
double printed_c3_corrected(double a, double b) {
    using std::cos;
    using std::sin;
    return -(-22 * sin(b) + 7 * sin(2 * b) -
             2 * cos(b / 2) *
                 (-32 * sin(a - b / 2) + 14 * sin(a + b / 2) - 6 * sin(a + 1.5 * b) + sin(2 * a + b / 2) +
                  sin(2 * a + 1.5 * b))) /
           40;
}
double printed_condition29(double a, double b) { return std::sin(a + b / 2) - 3 * std::sin(a / 2); }

// h of the unit-polygon segment, exactly from its Bézier points, with the factor k in f'g − k f g'.
std::vector<double> h_with_factor(double a, double b, double k, double scale = 1.0) {
    const BezierCurve seg(scale * uniform_segment_bezier(unit_edge_polygon(a, b)));
    const analysis::PlanarCurvatureParts p = analysis::planar_curvature_parts(seg);
    return (p.f.derivative() * p.g - k * (p.f * p.g.derivative())).coefficients();
}

}  // namespace

int main(int argc, char** argv) {
    repro::ArtifactRun run("typical_curves", "appendix_monotonicity", "3.4",
                           "Curvature monotonicity of cubic B-spline segments: coefficients C0–C5, condition "
                           "(29)–(30), Fig. 7 regions, endpoint interpolation (section 3.4, appendix A)",
                           argc, argv);
    const double half_pi = std::numbers::pi / 2;

    // ---- A.1: the printed coefficients against the exact ones, on a 41 × 41 grid of [0, π/2]².
    double diff[6] = {0, 0, 0, 0, 0, 0}, diff_c2_ext = 0, diff_c3_cor = 0, diff_closed = 0, diff_two_thirds = 0,
           ratio_scaled = 0, ratio_unscaled = 0;
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) {
            const double a = half_pi * i / 40, b = half_pi * j / 40;
            const std::vector<double> h = h_with_factor(a, b, 1.5), h23 = h_with_factor(a, b, 2.0 / 3.0);
            const auto printed = printed_coefficients(a, b);
            const auto closed = monotonicity_coefficients(a, b);
            for (int k = 0; k < 6; ++k) {
                diff[k] = std::max(diff[k], std::abs(printed[k] - h[k]));
                diff_closed = std::max(diff_closed, std::abs(closed[k] - h[k]));
            }
            diff_c2_ext = std::max(diff_c2_ext, std::abs(printed_c2_bracket_extended(a, b) - h[2]));
            diff_c3_cor = std::max(diff_c3_cor, std::abs(printed_c3_corrected(a, b) - h[3]));
            diff_two_thirds = std::max(diff_two_thirds, std::abs(printed[1] - h23[1]));
            if (i == 20 && j == 10) {  // |Q1Q2| scaled to 1 (×3) as the text says, and unscaled
                ratio_scaled = h_with_factor(a, b, 1.5, 3.0)[0] / printed[0];
                ratio_unscaled = h[0] / printed[0];
            }
        }
    run.check("appendix.C0", diff[0]);
    run.check("appendix.C1", diff[1]);
    run.check("appendix.C2", diff[2], diff_c2_ext);
    run.check("appendix.C3", diff[3], diff_c3_cor);
    run.check("appendix.C4", diff[4]);
    run.check("appendix.C5", diff[5]);
    run.check("appendix.eq40_factor", diff_two_thirds, diff[1]);
    run.check("appendix.scaled_q1q2", ratio_scaled, ratio_unscaled);
    run.validate("closed_forms",
                 "library closed forms C0–C5 (monotonicity_coefficients) vs the Bernstein-product h, largest "
                 "difference on the grid",
                 diff_closed, 0.0, 1e-13, "rounding (measured ~1e-15)");

    // eq (39): dκ/dt against central differences of κ(t) at t = 0.1 … 0.9, one segment.
    {
        const BezierCurve seg(uniform_segment_bezier(unit_edge_polygon(1.0, 0.4)));
        const analysis::PlanarCurvatureParts p = analysis::planar_curvature_parts(seg);
        double err_printed = 0, err_corrected = 0;
        for (int k = 1; k <= 9; ++k) {
            const double t = 0.1 * k, e = 1e-5;
            const double fd =
                (analysis::signed_curvature(seg, t + e) - analysis::signed_curvature(seg, t - e)) / (2 * e);
            const double f = p.f(t), g = p.g(t), df = p.f.derivative()(t), dg = p.g.derivative()(t);
            const double printed = (df * g - 2.0 / 3.0 * f * dg) / std::pow(f, 1.5);
            const double corrected = (df * g - 1.5 * f * dg) / std::pow(g, 2.5);
            err_printed = std::max(err_printed, std::abs(printed - fd) / std::abs(fd));
            err_corrected = std::max(err_corrected, std::abs(corrected - fd) / std::abs(fd));
        }
        run.check("appendix.eq39", err_printed, err_corrected);
    }

    // ---- (29), (30) and the deciding coefficient, on the Fig. 7 domain (1000 × 1000 grid).
    const int n = 1000;
    const std::vector<RegionPoint> region = monotonicity_region(n, 0.0, half_pi);
    double c5 = 0, c5_all = 0, p29 = 0, p29_c4 = 0, p29_mono = 0, agree29_c5 = 0, agree_printed29_c5 = 0,
           agree_c0_all = 0, agree_c5_all = 0, exact_mono = 0, all_neg = 0;
    double p29_c1 = 0, differ = 0, exact_inc = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double a = half_pi * i / (n - 1), b = half_pi * j / (n - 1);
            const RegionPoint& r = region[static_cast<std::size_t>(i) * n + j];
            const bool mono = r.exact == analysis::Trend::decreasing;
            c5 += r.c5_negative;
            c5_all += r.c5_negative && r.all_negative;
            p29 += r.condition29;
            p29_c4 += r.condition29 && r.c4_negative;
            p29_c1 += r.condition29 && monotonicity_coefficients(a, b)[1] < 0.0;
            p29_mono += r.condition29 && mono;
            agree29_c5 += r.condition29 == r.c5_negative;
            agree_printed29_c5 += (printed_condition29(a, b) > 0.0) == r.c5_negative;
            agree_c0_all += r.c0_negative == r.all_negative;
            agree_c5_all += r.c5_negative == r.all_negative;
            exact_mono += mono;
            exact_inc += r.exact == analysis::Trend::increasing;
            differ += mono != r.condition29;
            all_neg += r.all_negative;
        }
    const double total = static_cast<double>(n) * n;
    run.check("eq29.is_c5_negative", agree_printed29_c5 / total, agree29_c5 / total);
    double bound_printed = 0, bound_c5 = 0;
    for (int i = 1; i <= 100; ++i) {
        const double a = half_pi * i / 100, b = theta1_bound(a);
        bound_printed = std::max(bound_printed, std::abs(printed_condition29(a, b)));
        bound_c5 = std::max(bound_c5, std::abs(monotonicity_coefficients(a, b)[5]));
    }
    run.check("eq30.boundary", bound_printed, bound_c5);
    run.check("appendix.c5_negative_implies_all", static_cast<double>(c5_all) / static_cast<double>(c5));
    run.check("appendix.c4_negative_where_29", static_cast<double>(p29_c4) / static_cast<double>(p29));
    run.check("fig7.caption_c1_negative_where_29", static_cast<double>(p29_c1) / static_cast<double>(p29));
    run.check("appendix.deciding_coefficient", agree_c0_all / total, agree_c5_all / total);
    run.check("sec3.4.condition29_monotone", static_cast<double>(p29_mono) / static_cast<double>(p29));
    run.note("Fig. 7 domain [0, π/2]², " + std::to_string(n) + " × " + std::to_string(n) + " grid: (29) holds on " +
             format_number(100.0 * p29 / total, 4) + " % of it, every C_i < 0 on " +
             format_number(100.0 * all_neg / total, 4) + " %, dκ/dt ≤ 0 on [0, 1] by the exact sign on " +
             format_number(100.0 * exact_mono / total, 4) + " % (dκ/dt ≥ 0, the mirrored case θ1 > θ0, on " +
             format_number(100.0 * exact_inc / total, 4) +
             " %). Grid points where 'decreasing' and (29) disagree: " + format_number(differ, 6) +
             ". (29) is necessary as well as sufficient for decreasing curvature, because C5 = h(1): if C5 > 0 the "
             "curvature increases at the segment's end.");
    // The same tests over (0, π)² (the paper states (29) for any θ0 > 0).
    {
        const int m = 600;
        const std::vector<RegionPoint> wide = monotonicity_region(m, 0.0, std::numbers::pi * (1.0 - 1e-9));
        double w29 = 0, w29_all = 0, w29_mono = 0;
        double worst_a = -1, worst_b = -1;
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                const RegionPoint& r = wide[static_cast<std::size_t>(i) * m + j];
                if (!r.condition29) continue;
                ++w29;
                w29_all += r.all_negative;
                w29_mono += r.exact == analysis::Trend::decreasing;
                if (!r.all_negative && worst_a < 0) {
                    worst_a = std::numbers::pi * (1.0 - 1e-9) * i / (m - 1);
                    worst_b = std::numbers::pi * (1.0 - 1e-9) * j / (m - 1);
                }
            }
        run.check("sec3.4.condition29_all_negative_wide", static_cast<double>(w29_all) / static_cast<double>(w29));
        run.note("Over (0, π)² (" + std::to_string(m) + " × " + std::to_string(m) +
                 " grid): where (29) holds, every C_i < 0 at " +
                 format_number(100.0 * w29_all / static_cast<double>(w29), 6) +
                 " % of the points and dκ/dt ≤ 0 (exact) at " +
                 format_number(100.0 * w29_mono / static_cast<double>(w29), 6) + " %" +
                 (worst_a >= 0 ? "; first counterexample to 'all C_i < 0' at (θ0, θ1) = (" + format_number(worst_a, 6) +
                                     ", " + format_number(worst_b, 6) + ")."
                               : "; no counterexample."));
    }

    // Figure data: 301 × 301 classification codes as a matrix (row i: θ0 = 0.3° i, column j: θ1 = 0.3° j;
    // the header names the columns) and the boundary (30).
    {
        const int m = 301;
        const std::vector<RegionPoint> grid = monotonicity_region(m, 0.0, half_pi);
        std::vector<std::string> header;
        for (int j = 0; j < m; ++j) header.push_back("theta1_" + format_number(90.0 * j / (m - 1), 6));
        CsvWriter codes = run.table("fig7_regions.csv", header);
        std::array<long, 6> cells{};  // grid cells per class, for the caption
        for (int i = 0; i < m; ++i) {
            std::vector<std::string> line;
            for (int j = 0; j < m; ++j) {
                const RegionPoint& r = grid[static_cast<std::size_t>(i) * m + j];
                // 0: not monotone; 1: monotone (exact) only; 2: all C_i < 0 without (29); 3: (29) (and all C_i < 0);
                // 4: (29) without all C_i < 0 (a counterexample); 5: increasing (the mirrored case).
                const int cls = r.condition29                            ? (r.all_negative ? 3 : 4)
                                : r.all_negative                         ? 2
                                : r.exact == analysis::Trend::decreasing ? 1
                                : r.exact == analysis::Trend::increasing ? 5
                                                                         : 0;
                line.push_back(std::to_string(cls));
                ++cells[static_cast<std::size_t>(cls)];
            }
            codes.row_text(line);
        }
        CsvWriter bound = run.table("fig7_bound.csv", {"theta0_deg", "theta1_bound_deg"});
        for (int i = 0; i <= 90; ++i)
            bound.row({static_cast<double>(i), theta1_bound(half_pi * i / 90) * 180 / std::numbers::pi});
        // The caption says how many of the grid's cells each class has, and which classes are empty.
        const std::array<const char*, 6> names{"not monotone",
                                               "monotone only by the exact sign of dκ/dt",
                                               "every C_i < 0 without (29)",
                                               "(29) holds (then every C_i < 0)",
                                               "(29) holds but some C_i ≥ 0",
                                               "κ increasing (the mirrored case)"};
        std::string shown, empty;
        for (std::size_t k = 0; k < cells.size(); ++k) {
            std::string& to = cells[k] > 0 ? shown : empty;
            to += (to.empty() ? "" : "; ") + std::string(names[k]) +
                  (cells[k] > 0 ? " (" + std::to_string(cells[k]) + " cells)" : "");
        }
        run.figure("fig7_regions", "Fig. 7 redrawn as regions of the unit polygon's (θ0, θ1) ∈ [0°, 90°]² on a " +
                                       std::to_string(m) + " × " + std::to_string(m) + " grid: " + shown +
                                       "; the line is eq (30). Empty on this grid (in the legend, marked so): " +
                                       (empty.empty() ? "none" : empty) + ".");
    }

    // ---- A.2: endpoint-interpolating cubic B-splines.
    {
        Eigen::MatrixXd q(8, 2);  // unit edges, turns 0.5, 0.35, 0.25, 0.18, 0.12, 0.08 (ours)
        const double turns[] = {0.0, 0.5, 0.35, 0.25, 0.18, 0.12, 0.08};
        double dir = 0.0;
        q.row(0) << 0, 0;
        for (int i = 0; i < 7; ++i) {
            dir += turns[i];
            q.row(i + 1) = q.row(i) + Eigen::RowVector2d(std::cos(dir), std::sin(dir));
        }
        const Eigen::MatrixXd p = endpoint_interpolating_polygon(q);
        const BSplineCurve curve = endpoint_interpolating_cubic_bspline(p);
        const std::vector<BezierCurve> segs = bezier_segments(curve);
        Eigen::MatrixXd q0(4, 2), q1(4, 2);
        q0 << p.row(0), p.row(1), (p.row(1) + p.row(2)) / 2, (3 * p.row(1) + 7 * p.row(2) + 2 * p.row(3)) / 12;
        q1 << (3 * p.row(1) + 7 * p.row(2) + 2 * p.row(3)) / 12, (2 * p.row(2) + p.row(3)) / 3,
            (p.row(2) + 2 * p.row(3)) / 3, (p.row(2) + 4 * p.row(3) + p.row(4)) / 6;
        run.check("A2.first_segment_bezier", (segs[0].control_points() - q0).cwiseAbs().maxCoeff());
        run.check("A2.second_segment_bezier", (segs[1].control_points() - q1).cwiseAbs().maxCoeff());
        CubicPoints second_uniform;
        second_uniform << (3 * p.row(1) - p.row(2)) / 2, p.row(2), p.row(3), p.row(4);
        run.check("A2.p1_prime", (uniform_segment_bezier(second_uniform) - q1).cwiseAbs().maxCoeff());
        const MonotonicityReport rep = cubic_bspline_curvature_monotonicity(curve);
        const SegmentVerdict& first = rep.segments[0];
        const double edge_dev =
            std::max({std::abs(first.edges[0] - 1), std::abs(first.edges[1] - 1), std::abs(first.edges[2] - 1)});
        run.check("sec3.4.first_segment_twice_angle", std::max(std::abs(first.turn0 - 2 * turns[1]), edge_dev));
        run.check("A2.r2_is_p1_moved", std::abs((first.polygon.row(1) - p.row(0)).norm() - 1.0 / 3.0),
                  std::abs((first.polygon.row(1) - p.row(1)).norm() - 1.0 / 3.0));
        run.check("A2.r0_r2_p2_p3",
                  (uniform_segment_bezier(first.polygon) - segs[0].control_points()).cwiseAbs().maxCoeff());
    }

    // ---- The whole-curve checker against dense sampling of dκ/dt (2001 samples per segment).
    {
        std::mt19937 rng(17);
        std::uniform_real_distribution<double> turn(0.02, 0.6);
        int segments = 0, agree = 0, guaranteed = 0, guaranteed_and_monotone = 0;
        auto sample_trend = [](const BezierCurve& seg) {
            bool pos = false, neg = false;
            const analysis::PlanarCurvatureParts p = analysis::planar_curvature_parts(seg);
            double scale = 0.0;
            std::vector<double> v;
            for (int k = 0; k <= 2000; ++k) {
                const double t = k / 2000.0;
                v.push_back(p.f.derivative()(t) * p.g(t) - 1.5 * p.f(t) * p.g.derivative()(t));
                scale = std::max(scale, std::abs(v.back()));
            }
            for (double x : v) {
                pos = pos || x > 1e-9 * scale;
                neg = neg || x < -1e-9 * scale;
            }
            return pos && neg ? analysis::Trend::not_monotone
                   : pos      ? analysis::Trend::increasing
                              : analysis::Trend::decreasing;
        };
        CsvWriter table =
            run.table("checker_typical_polygons.csv", {"degree", "knots", "segments", "condition29_monotone",
                                                       "bernstein_monotone", "exact_monotone", "whole_curve_monotone"});
        auto tally = [&](const BSplineCurve& c) {
            const MonotonicityReport rep = cubic_bspline_curvature_monotonicity(c);
            std::vector<BezierCurve> segs = bezier_segments(c);
            int k29 = 0, kb = 0, ke = 0;
            for (std::size_t s = 0; s < rep.segments.size(); ++s) {
                const SegmentVerdict& v = rep.segments[s];
                const analysis::Trend sampled = sample_trend(BezierCurve(segs[s].control_points()));
                ++segments;
                agree += sampled == v.exact;
                if (v.condition29_verdict == Guarantee::monotone || v.bernstein_verdict == Guarantee::monotone) {
                    ++guaranteed;
                    guaranteed_and_monotone += sampled != analysis::Trend::not_monotone;
                }
                k29 += v.condition29_verdict == Guarantee::monotone;
                kb += v.bernstein_verdict == Guarantee::monotone;
                ke += v.exact != analysis::Trend::not_monotone;
            }
            return std::array<double, 4>{static_cast<double>(k29), static_cast<double>(kb), static_cast<double>(ke),
                                         rep.whole_curve != analysis::Trend::not_monotone ? 1.0 : 0.0};
        };
        for (int degree : {24, 49, 99}) {
            const TypicalPolygon poly = scale_one_typical_polygon(-0.5, 1.0, degree);
            const auto u = tally(uniform_cubic_bspline(poly.points));
            table.row_text({std::to_string(degree), "uniform", std::to_string(poly.points.rows() - 3),
                            format_number(u[0], 6), format_number(u[1], 6), format_number(u[2], 6),
                            format_number(u[3], 6)});
            const Eigen::MatrixXd ends = endpoint_interpolating_polygon(poly.points * degree);  // unit edges
            const auto e = tally(endpoint_interpolating_cubic_bspline(ends));
            table.row_text({std::to_string(degree), "endpoint_interpolating", std::to_string(ends.rows() - 3),
                            format_number(e[0], 6), format_number(e[1], 6), format_number(e[2], 6),
                            format_number(e[3], 6)});
        }
        for (int trial = 0; trial < 200; ++trial) {
            Eigen::MatrixXd q(9, 2);
            double dir = 0.0;
            q.row(0) << 0, 0;
            for (int i = 0; i < 8; ++i) {
                if (i > 0) dir += (trial % 3 == 0 ? -1.0 : 1.0) * turn(rng) * (i % 2 == 0 || trial % 2 ? 1.0 : 0.5);
                q.row(i + 1) = q.row(i) + Eigen::RowVector2d(std::cos(dir), std::sin(dir));
            }
            tally(endpoint_interpolating_cubic_bspline(endpoint_interpolating_polygon(q)));
        }
        run.validate(
            "checker_vs_sampling",
            "per-segment exact verdict (Bernstein subdivision) equals the verdict of 2001 samples of h (fraction of " +
                std::to_string(segments) + " segments)",
            static_cast<double>(agree) / segments, 1.0, 0.0, "yes/no per segment");
        run.validate(
            "guarantee_sound",
            "segments guaranteed monotone by (29) or by the Bernstein signs are monotone by sampling (fraction of " +
                std::to_string(guaranteed) + ")",
            static_cast<double>(guaranteed_and_monotone) / guaranteed, 1.0, 0.0, "yes/no per segment");
    }
    return run.finish();
}
