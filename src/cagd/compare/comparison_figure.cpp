#include "cagd/compare/comparison_figure.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "cagd/analysis/curvature_comb.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/frenet_jet.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/compare/locality_footprint.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"

namespace cagd::compare {

FigureSampling figure_sampling(int spans, int budget) {
    if (spans < 1 || budget < 2)
        fail_input("cagd::compare::figure_sampling",
                   "needs spans >= 1 and budget >= 2, got " + std::to_string(spans) + " and " + std::to_string(budget));
    // A sampled span yields per_span + 1 samples (both ends).
    const long total = static_cast<long>(spans), b = budget;
    if (total * 33 <= b) return {32, 1};
    if (total * 2 <= b) return {static_cast<int>(b / total) - 1, 1};
    return {1, static_cast<int>((2 * total + b - 1) / b)};
}

FigureData comparison_figure_data(const std::vector<MethodComparison>& cs, const PointList& points,
                                  const FigureSampling& sampling) {
    const int per_span = sampling.per_span, stride = sampling.span_stride;
    if (per_span < 1 || stride < 1)
        fail_input("cagd::compare::comparison_figure_data", "per_span and span_stride must be >= 1, got " +
                                                                std::to_string(per_span) + " and " +
                                                                std::to_string(stride));
    const bool trapezoid = sampling.arc_length == FigureSampling::ArcLength::trapezoid;
    if (trapezoid && stride != 1)
        fail_input("cagd::compare::comparison_figure_data",
                   "the trapezoid arc length needs every span sampled (span_stride 1), got " + std::to_string(stride));
    const double diagonal = bounding_box_diagonal(points);
    const bool space = points.cols() == 3;  // curves x, y, z; profiles s, κ, τ; no combs
    // One part per method, computed in parallel and joined in the methods' order.
    std::vector<FigureData> parts(cs.size());
    std::vector<double> comb_scale(cs.size(), 0.0);
    std::vector<int> comb_stride(cs.size(), 0);
    // A comb tooth's foot: position, unit normal, κ.
    struct CombSample {
        double x, y, nx, ny, kappa;
    };
    std::vector<std::vector<CombSample>> comb_samples(cs.size());
    parallel_for(static_cast<long>(cs.size()), hardware_threads(), [&](long method) {
        const auto i = static_cast<std::size_t>(method);
        FigureData& d = parts[i];
        if (!cs[i].interpolant) return;
        const Interpolant& a = *cs[i].interpolant;
        const double index = static_cast<double>(i);
        std::vector<CombSample> samples;
        // A span not sampled adds its length to s: the one the measures integrated, where they did
        // (comparison_sampling's sub-pieces, at least two 20-point rules per piece), else one
        // 20-point rule — not 20 more evaluations per span for every method (at 10^5 points, most
        // of the figure data's time).
        const std::optional<std::vector<std::pair<double, double>>> measured =
            stride > 1 && cs[i].fairness ? measured_span_integrals(a, *cs[i].fairness) : std::nullopt;
        double s = 0.0;
        for (std::size_t k = 0; k + 1 < a.node_parameters.size(); ++k) {
            const bool last = k + 2 == a.node_parameters.size();
            if (k % static_cast<std::size_t>(stride) != 0 && !last) {
                s += measured ? (*measured)[k].first
                              : analysis::piece_arc_length(*a.curve, a.node_parameters[k], a.node_parameters[k + 1], 1);
                continue;
            }
            double previous = a.node_parameters[k], previous_speed = 0.0;
            for (int j = 0; j <= per_span; ++j) {
                const double t = span_parameter(a, k, double(j) / per_span);
                const Eigen::MatrixXd J = j == per_span && t > a.curve->t_min()
                                              ? a.curve->jet_from_left(t, space ? 3 : 2)
                                              : a.curve->jet(t, space ? 3 : 2);
                // The step's arc length: by quadrature, or the trapezoid rule on the speeds at its ends.
                const double speed = J.row(1).norm();
                const auto step_length = [&] {
                    return trapezoid ? 0.5 * (t - previous) * (previous_speed + speed)
                                     : analysis::piece_arc_length(*a.curve, previous, t, 1);
                };
                if (space) {
                    if (j < per_span || last) d.curves.push_back({index, J(0, 0), J(0, 1), J(0, 2)});
                    if (t > previous) s += step_length();
                    previous = t;
                    previous_speed = speed;
                    if (cs[i].status == AttemptStatus::cusp || !(J.row(1).norm() > 0)) continue;
                    const analysis::FrenetJet f = analysis::frenet_jet(J.bottomRows(3));
                    // τ is undefined at a straight point (the flatness policy): plotted at 0 there,
                    // as the table's largest |τ| skips it.
                    const double kappa = f.curvature, tau = analysis::is_straight(kappa, diagonal) ? 0.0 : f.torsion;
                    d.profiles.push_back({index, s, kappa, tau});
                    continue;
                }
                if (j < per_span || last) d.curves.push_back({index, J(0, 0), J(0, 1)});
                // One 20-point rule per sample step (analysis::arc_length would search all breakpoints
                // per call: O(n²) on long inputs); a step across a breakpoint costs plot accuracy only.
                if (t > previous) s += step_length();
                previous = t;
                previous_speed = speed;
                const analysis::FrenetJet f = analysis::frenet_jet(J.bottomRows(2));
                if (cs[i].status == AttemptStatus::cusp || !f.regular) continue;
                const double kappa = f.curvature, v = f.speed;
                d.profiles.push_back({index, s, kappa});
                samples.push_back({J(0, 0), J(0, 1), -J(1, 1) / v, J(1, 0) / v, kappa});
            }
        }
        comb_samples[i] = std::move(samples);
    });
    // One comb scale for every panel: the 95th percentile of |κ| over all methods' samples draws
    // 10 % of the diagonal, so that equal teeth are equal curvature across panels.
    std::vector<double> pooled;
    for (const auto& samples : comb_samples)
        for (const CombSample& q : samples) pooled.push_back(q.kappa);
    const double scale = pooled.empty() ? 0.0 : analysis::comb_scale(std::move(pooled), diagonal);
    for (std::size_t i = 0; i < cs.size(); ++i) {
        const std::vector<CombSample>& samples = comb_samples[i];
        if (samples.empty()) continue;
        const double index = static_cast<double>(i);
        const std::size_t teeth_stride = (samples.size() + kMaxCombTeeth - 2) /
                                         (kMaxCombTeeth - 1);  // ≤ kMaxCombTeeth − 1 strided teeth, and the last
        comb_scale[i] = scale;
        comb_stride[i] = static_cast<int>(std::max<std::size_t>(teeth_stride, 1));
        for (std::size_t k = 0; k < samples.size(); ++k) {
            if (k % static_cast<std::size_t>(comb_stride[i]) != 0 && k + 1 != samples.size()) continue;
            const CombSample& q = samples[k];
            parts[i].combs.push_back({index, q.x, q.y, q.x - scale * q.kappa * q.nx, q.y - scale * q.kappa * q.ny});
        }
    }
    FigureData d;
    d.comb_scale = std::move(comb_scale);
    d.comb_stride = std::move(comb_stride);
    for (FigureData& part : parts) {
        std::move(part.curves.begin(), part.curves.end(), std::back_inserter(d.curves));
        std::move(part.profiles.begin(), part.profiles.end(), std::back_inserter(d.profiles));
        std::move(part.combs.begin(), part.combs.end(), std::back_inserter(d.combs));
    }
    return d;
}

}  // namespace cagd::compare
