#include "cagd/compare/method_comparison.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "cagd/analysis/curvature_comb.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/compare/locality_footprint.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/parallel.hpp"

namespace cagd::compare {

std::optional<std::vector<std::pair<double, double>>> measured_span_integrals(const Interpolant& a,
                                                                              const analysis::FairnessMeasures& f) {
    const std::vector<double> br = a.curve->breakpoints();
    const std::vector<double>& nodes = a.node_parameters;
    if (!(f.piece_lengths.size() + 1 == br.size() && std::includes(br.begin(), br.end(), nodes.begin(), nodes.end())))
        return std::nullopt;
    std::vector<std::pair<double, double>> out;
    out.reserve(nodes.size());
    std::size_t b = 0;
    while (br[b] < nodes.front()) ++b;
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
        double L = 0.0, E = 0.0;
        for (; br[b] < nodes[k + 1]; ++b) L += f.piece_lengths[b], E += f.piece_energies[b];
        out.emplace_back(L, E);
    }
    return out;
}

namespace {

// Σ_k L_k² E_k over the data spans: the measured pieces summed per span where they are whole
// spans' (measured_span_integrals); otherwise each span is integrated afresh, split at the
// breakpoints inside it.
double span_pseudo_energy(const Interpolant& a, const analysis::FairnessMeasures& f, int pieces) {
    double total = 0.0;
    if (const auto spans = measured_span_integrals(a, f)) {
        for (const auto& [L, E] : *spans) total += L * L * E;
        return total;
    }
    const Curve& c = *a.curve;
    const std::vector<double> br = c.breakpoints();
    const std::vector<double>& nodes = a.node_parameters;
    std::size_t b = 0;
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
        const double t0 = nodes[k], t1 = nodes[k + 1];
        double L = 0.0, E = 0.0, from = t0;
        while (b < br.size() && br[b] <= t0) ++b;
        for (; b < br.size() && br[b] < t1; ++b) {
            const auto [l, e] = analysis::piece_length_and_bending_energy(c, from, br[b], pieces);
            L += l;
            E += e;
            from = br[b];
        }
        const auto [l, e] = analysis::piece_length_and_bending_energy(c, from, t1, pieces);
        L += l;
        E += e;
        total += L * L * E;
    }
    return total;
}

}  // namespace

analysis::FairnessSampling comparison_sampling(int pieces) {
    const int budget = 2'000'000 / std::max(pieces, 1);
    // Quadrature sub-pieces: up to 512 per piece for curves of few pieces. A single cubic that nearly
    // turns back (its speed nearly 0) needs them: with 16, its length was 2e-7 off (eigen-spline-3
    // on table 3's four points), outside what the table's 8 digits promise.
    return {std::clamp(budget, 8, 128), std::clamp(budget / 128, 2, 512)};
}

const MethodComparison& find_comparison(const std::vector<MethodComparison>& c, const std::string& configuration) {
    for (const MethodComparison& m : c)  // a peer's row, or a configuration by its own name
        if (m.method == configuration) return m;
    const std::string name = methods::find_configuration(configuration).name;
    for (const MethodComparison& m : c)
        if (m.method == name) return m;
    fail_input("cagd::compare::find_comparison", "the comparison has no row '" + name + "'");
}

std::vector<MethodComparison> compare_methods(const PointList& points, const ComparisonOptions& options) {
    const char* who = "cagd::compare::compare_methods";
    if (points.cols() != 2 && points.cols() != 3)
        fail_input(who, "compares planar or space curves: needs 2 or 3 columns (x, y[, z]), got " +
                            std::to_string(points.cols()));
    if (points.rows() < 2) fail_input(who, "needs at least 2 points, got " + std::to_string(points.rows()));
    // What no method could accept is bad input of the whole comparison (finite coordinates, no two
    // consecutive points equal); what one method refuses beyond that is that method's row.
    const ValidPoints valid = validate_points(points, 2, options.closed, who);
    std::vector<methods::Configuration> configurations = options.configurations;
    if (configurations.empty()) {
        for (const std::string& name : options.methods) configurations.push_back(methods::find_configuration(name));
        if (options.methods.empty() && options.peers.empty()) configurations = methods::configurations();
    }
    const double diagonal = bounding_box_diagonal(points);
    // The locality footprint's input: the middle point moved by 1e-3 of the diagonal, validated once
    // (nothing when it made the points invalid: no footprint).
    PointList moved = points;
    if (points.rows() >= 3) moved(points.rows() / 2, 1) += 1e-3 * diagonal;
    const std::optional<ValidPoints> moved_valid = [&]() -> std::optional<ValidPoints> {
        if (!options.locality || points.rows() < 3) return std::nullopt;
        try {
            return validate_points(moved, 2, options.closed, who);
        } catch (const InvalidInput&) {
            return std::nullopt;
        }
    }();
    // The measures of c's curve (c.interpolant): its spans and, with options.measures, length, area,
    // fairness, pseudo-energy, and whether a closed planar curve loops.
    const auto measure_curve = [&](MethodComparison& c) {
        const Curve& curve = *c.interpolant->curve;
        c.spans = static_cast<int>(c.interpolant->node_parameters.size()) - 1;
        if (!options.measures) return;
        const analysis::FairnessSampling sampling =
            comparison_sampling(static_cast<int>(curve.breakpoints().size()) - 1);
        if (options.closed && points.cols() == 2) c.area = analysis::enclosed_area(curve);
        try {
            c.fairness = analysis::fairness_measures(curve, points, sampling);
            c.length = c.fairness->length;
            c.pseudo_energy = span_pseudo_energy(*c.interpolant, *c.fairness, sampling.quadrature_pieces);
            // A closed planar curve that loops where its polygon does not is measured, but flagged.
            if (options.closed && points.cols() == 2)
                if (std::string anomaly = analysis::closed_curve_anomaly(curve, points, c.length); !anomaly.empty()) {
                    c.status = AttemptStatus::loops;
                    c.note = std::move(anomaly);
                }
        } catch (const InvalidInput& e) {  // a sample of zero speed: κ undefined there
            c.length = analysis::arc_length(curve, sampling.quadrature_pieces);
            c.status = AttemptStatus::cusp;
            c.note = in_user_terms(one_line(e.what()));
        }
    };
    const auto measure_configuration = [&](const methods::Configuration& configuration) {
        MethodComparison c;
        c.method = configuration.name;
        const auto start_state = options.starts.find(configuration.name);
        InterpolationAttempt attempt = attempt_interpolation(
            configuration, valid, start_state != options.starts.end() ? &start_state->second : nullptr);
        c.status = attempt.status;
        c.note = std::move(attempt.note);
        c.shared_seconds = attempt.prepare_seconds;
        c.seconds = attempt.build_seconds;
        if (attempt.status != AttemptStatus::ok) return c;
        InterpolationResult& r = attempt.result;
        c.solver_state = std::move(r.solver_state);  // also the start of the footprint's build (below)
        c.interpolant = std::move(r.interpolant);
        measure_curve(c);
        if (options.measures && moved_valid) {
            try {
                // From this build's final iterate (continuation: fewer Newton iterations, and the
                // same solution branch); a direct method builds anew.
                const InterpolationResult m = methods::interpolate_from(configuration, *moved_valid, c.solver_state);
                if (m.outcome.ok() && m.interpolant)
                    c.locality_footprint = spans_moved(*c.interpolant, *m.interpolant, 1e-9 * diagonal);
            } catch (const InvalidInput&) {  // the moved point made the input invalid for this method
            }
        }
        return c;
    };
    // A peer draws the points and the moved ones in one run of its adapter.
    const auto measure_peer = [&](const CurveSubject& peer) {
        MethodComparison c;
        c.method = peer.name;
        c.peer = true;
        std::vector<CurveRequest> requests{{.points = points, .closed = options.closed}};
        if (options.measures && moved_valid) requests.push_back({.points = moved, .closed = options.closed});
        const auto start = std::chrono::steady_clock::now();
        std::vector<DrawnCurve> drawn = peer.draw(requests);
        c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        c.status = drawn.front().status;
        c.note = std::move(drawn.front().note);
        if (c.status != AttemptStatus::ok) return c;
        c.interpolant = std::move(drawn.front().interpolant);
        c.provenance = std::move(drawn.front().provenance);
        measure_curve(c);
        if ((c.approximation = drawn.front().approximation))
            c.note += (c.note.empty() ? "" : "; ") + std::string("its pieces approximate ") + peer.name +
                      "'s curve within " + format_number(*c.approximation, 3) + " (the peer gives samples only)";
        if (drawn.size() > 1 && drawn[1].interpolant)
            c.locality_footprint = spans_moved(*c.interpolant, *drawn[1].interpolant, 1e-9 * diagonal);
        return c;
    };
    // Whatever one configuration or peer throws beyond a refusal (its curve failing to evaluate inside
    // its own range, memory) is that row's, never the end of the comparison.
    const auto guarded = [&](const std::string& name, const char* kind,
                             const std::function<MethodComparison()>& measure) {
        try {
            return measure();
        } catch (const std::exception& e) {
            MethodComparison c;
            c.method = name;
            c.status = AttemptStatus::failed;
            c.note = std::string("the ") + kind + " failed (a defect of the " + kind +
                     ", not of the points): " + in_user_terms(one_line(e.what()));
            return c;
        }
    };
    // The iterative methods are started first, then the peers (each a process of its own); the rows
    // keep the configurations' order, then the peers'.
    const std::size_t rows = configurations.size() + options.peers.size();
    std::vector<std::size_t> order(rows);
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto rank = [&](std::size_t k) {
        return k >= configurations.size() ? 1 : configurations[k].method->iterative ? 0 : 2;
    };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return rank(i) < rank(j); });
    std::vector<MethodComparison> out(rows);
    std::mutex report;
    const int threads = options.threads > 0 ? options.threads : hardware_threads();
    parallel_for(static_cast<long>(order.size()), threads, [&](long slot) {
        const std::size_t k = order[static_cast<std::size_t>(slot)];
        if (k < configurations.size())
            out[k] =
                guarded(configurations[k].name, "method", [&] { return measure_configuration(configurations[k]); });
        else {
            const CurveSubject& peer = options.peers[k - configurations.size()];
            out[k] = guarded(peer.name, "peer", [&] { return measure_peer(peer); });
            out[k].peer = true;
        }
        const std::lock_guard<std::mutex> lock(report);
        if (options.on_method) options.on_method(out[k]);
    });
    return out;
}

}  // namespace cagd::compare
