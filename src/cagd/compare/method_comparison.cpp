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
#include <sstream>
#include <stdexcept>

#include "cagd/analysis/curvature_comb.hpp"
#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/intrinsic/intrinsic_curve.hpp"
#include "cagd/spline/bspline.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace cagd::compare {

namespace {

// The parameter at fraction f of span k.
double span_parameter(const Interpolant& a, std::size_t k, double f) {
    const double t0 = a.node_parameters[k], t1 = a.node_parameters[k + 1];
    return f == 1.0 ? t1 : t0 + f * (t1 - t0);
}

// Rows j = 0..samples_per_span of span k's samples (span_samples) into out's rows first + j.
void sample_span(const Interpolant& a, std::size_t k, int samples_per_span, Eigen::MatrixXd& out, Eigen::Index first) {
    JetMatrix p;
    for (int j = 0; j <= samples_per_span; ++j) {
        a.curve->jet_into(span_parameter(a, k, static_cast<double>(j) / samples_per_span), 0, p);
        out.row(first + j) = p.row(0);
    }
}

// The samples per span of the locality footprint.
constexpr int kFootprintSamplesPerSpan = 8;

// Whether span k of the curvature-profile curves a and b (one segment per span, as the footprint's
// builds have) cannot have moved by more than half the tolerance: IntrinsicCurve's bound of the
// offset at equal fractions of the segment, plus the rounding of the sample parameters
// s = w_k + f·d_k (a few ulps of w_k + d_k, at unit speed a distance as large) — so the sampled
// distance, which that bound covers, stays below the tolerance.
bool intrinsic_span_within_half(const intrinsic::IntrinsicCurve& a, const intrinsic::IntrinsicCurve& b, const Interpolant& of_a, const Interpolant& of_b, std::size_t k,
                                double tolerance) {
    const double parameter_rounding = 16.0 * std::numeric_limits<double>::epsilon() *
                                      (std::abs(of_a.node_parameters[k]) + std::abs(of_a.node_parameters[k + 1]) + std::abs(of_b.node_parameters[k]) + std::abs(of_b.node_parameters[k + 1]));
    return a.segment_offset_bound(b, static_cast<int>(k)) + parameter_rounding <= 0.5 * tolerance;
}

// Rows first..last (clamped to the matrices) of a and b are equal, entry by entry.
bool same_rows(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, Eigen::Index first, Eigen::Index last) {
    last = std::min({last, a.rows() - 1, b.rows() - 1});
    return first > last || a.middleRows(first, last - first + 1) == b.middleRows(first, last - first + 1);
}

// Which spans of a and b the footprint need not sample, or none when no rule knows the curves
// (then every span is sampled). A span is skipped only when its sampled distance cannot exceed the
// tolerance: the curvature profile's by its offset bound (intrinsic_span_within_half); a Hermite-
// form or B-spline curve's when the span is computed from equal data in both — the same node
// parameters, and the nodes and derivatives of spans k and k + 1 (the sample at the span's end is
// node k + 1, which span k + 1 evaluates), or the knots and control points of every knot span its
// samples fall in — so that every sample is the same and the distance 0.
std::function<bool(std::size_t)> footprint_skip_rule(const Interpolant& a, const Interpolant& b, double tolerance) {
    const std::size_t spans = a.node_parameters.empty() ? 0 : a.node_parameters.size() - 1;
    if (b.node_parameters.size() != a.node_parameters.size()) return {};
    const auto same_nodes = [&a, &b](std::size_t k) { return a.node_parameters[k] == b.node_parameters[k] && a.node_parameters[k + 1] == b.node_parameters[k + 1]; };
    if (const auto *ca = dynamic_cast<const intrinsic::IntrinsicCurve*>(a.curve.get()), *cb = dynamic_cast<const intrinsic::IntrinsicCurve*>(b.curve.get()); ca && cb) {
        if (ca->tangent_angle().segments() != static_cast<int>(spans) || cb->tangent_angle().segments() != static_cast<int>(spans) ||
            ca->tangent_angle().degree() != cb->tangent_angle().degree())
            return {};
        return [ca, cb, &a, &b, tolerance](std::size_t k) { return intrinsic_span_within_half(*ca, *cb, a, b, k, tolerance); };
    }
    if (const auto *ha = dynamic_cast<const spline::PiecewiseHermiteCurve*>(a.curve.get()), *hb = dynamic_cast<const spline::PiecewiseHermiteCurve*>(b.curve.get()); ha && hb) {
        if (ha->spans() != hb->spans() || ha->dimension() != hb->dimension() || ha->holds_node_slopes() != hb->holds_node_slopes() ||
            ha->span_scales().size() != hb->span_scales().size())
            return {};
        // The slope form's m_k and h_k, or the pair form's d0_k and d1_k (formed once here).
        auto pairs = std::make_shared<std::array<Eigen::MatrixXd, 4>>();  // d0 of a, of b; d1 of a, of b
        if (!ha->holds_node_slopes()) *pairs = {ha->start_derivatives(), hb->start_derivatives(), ha->end_derivatives(), hb->end_derivatives()};
        return [ha, hb, pairs, same_nodes](std::size_t k) {
            const auto i = static_cast<Eigen::Index>(k);
            if (!same_nodes(k) || !same_rows(ha->nodes(), hb->nodes(), i, i + 2)) return false;
            if (!ha->holds_node_slopes()) return same_rows((*pairs)[0], (*pairs)[1], i, i + 1) && same_rows((*pairs)[2], (*pairs)[3], i, i + 1);
            const std::vector<double>&sa = ha->span_scales(), &sb = hb->span_scales();
            for (std::size_t j = k; j < std::min(k + 2, sa.size()); ++j)
                if (!(sa[j] == sb[j])) return false;
            return same_rows(ha->node_slopes(), hb->node_slopes(), i, i + 2);
        };
    }
    if (const auto *ba = dynamic_cast<const BSplineCurve*>(a.curve.get()), *bb = dynamic_cast<const BSplineCurve*>(b.curve.get()); ba && bb) {
        if (ba->degree() != bb->degree() || ba->knots().size() != bb->knots().size() || ba->control_points().rows() != bb->control_points().rows() ||
            ba->control_points().cols() != bb->control_points().cols())
            return {};
        return [ba, bb, &a, same_nodes](std::size_t k) {
            if (!same_nodes(k)) return false;
            // The knot spans of the samples t0 ≤ t ≤ t1, and what A2.3 and the tables read for them.
            const int p = ba->degree(), s0 = ba->find_span(a.node_parameters[k]), s1 = ba->find_span(a.node_parameters[k + 1]);
            const std::vector<double>&U = ba->knots(), &V = bb->knots();
            for (int i = s0 - p; i <= s1 + p + 1; ++i)
                if (!(U[static_cast<std::size_t>(i)] == V[static_cast<std::size_t>(i)])) return false;
            return same_rows(ba->control_points(), bb->control_points(), s0 - p, s1);
        };
    }
    return {};
}

// Spans of a and b (same points but one moved) that differ by more than `tolerance` somewhere:
// span_displacements counted, skipping the spans footprint_skip_rule shows cannot count and
// sampling the others as span_displacements does — the same count, without sampling the spans a
// local method left unchanged, or 16 sines and cosines per sample on every span of the curvature
// profile (at 10^5 points, 1.1 of the 2 CPU-s its footprint took).
int spans_moved(const Interpolant& a, const Interpolant& b, double tolerance) {
    const std::function<bool(std::size_t)> skip = footprint_skip_rule(a, b, tolerance);
    if (!skip) {
        const std::vector<double> moved = span_displacements(a, b, kFootprintSamplesPerSpan);
        return static_cast<int>(std::count_if(moved.begin(), moved.end(), [&](double d) { return d > tolerance; }));
    }
    const std::size_t spans = a.node_parameters.size() - 1;
    const Eigen::Index per = kFootprintSamplesPerSpan + 1;
    Eigen::MatrixXd sa(per, a.curve->dimension()), sb(per, b.curve->dimension());
    int moved = 0;
    for (std::size_t k = 0; k < spans; ++k) {
        if (skip(k)) continue;
        sample_span(a, k, kFootprintSamplesPerSpan, sa, 0);
        sample_span(b, k, kFootprintSamplesPerSpan, sb, 0);
        if (span_displacements(sa, sb, kFootprintSamplesPerSpan).front() > tolerance) ++moved;
    }
    return moved;
}

// Per data span k, the length L_k and bending energy E_k that fairness_measures integrated, summed
// over its pieces — where every node parameter is a breakpoint (every method but Eigen's spline
// fits, whose knots average the node parameters); nothing otherwise.
std::optional<std::vector<std::pair<double, double>>> measured_span_integrals(const Interpolant& a, const analysis::FairnessMeasures& f) {
    const std::vector<double> br = a.curve->breakpoints();
    const std::vector<double>& nodes = a.node_parameters;
    if (!(f.piece_lengths.size() + 1 == br.size() && std::includes(br.begin(), br.end(), nodes.begin(), nodes.end()))) return std::nullopt;
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

std::vector<double> span_displacements(const Interpolant& a, const Interpolant& b, int samples_per_span) {
    if (a.node_parameters.size() != b.node_parameters.size())
        fail_input("cagd::compare::span_displacements",
                   "the curves have " + std::to_string(a.node_parameters.size()) + " and " + std::to_string(b.node_parameters.size()) + " node parameters; they must agree");
    return span_displacements(span_samples(a, samples_per_span), span_samples(b, samples_per_span), samples_per_span);
}

Eigen::MatrixXd span_samples(const Interpolant& a, int samples_per_span) {
    if (samples_per_span < 1) fail_input("cagd::compare::span_samples", "samples_per_span must be >= 1, got " + std::to_string(samples_per_span));
    const Eigen::Index spans = a.node_parameters.empty() ? 0 : static_cast<Eigen::Index>(a.node_parameters.size()) - 1;
    Eigen::MatrixXd out(spans * (samples_per_span + 1), a.curve->dimension());
    for (Eigen::Index k = 0; k < spans; ++k) sample_span(a, static_cast<std::size_t>(k), samples_per_span, out, k * (samples_per_span + 1));
    return out;
}

std::vector<double> span_displacements(const Eigen::MatrixXd& a_samples, const Eigen::MatrixXd& b_samples, int samples_per_span) {
    const char* who = "cagd::compare::span_displacements";
    if (samples_per_span < 1) fail_input(who, "samples_per_span must be >= 1, got " + std::to_string(samples_per_span));
    const Eigen::Index per = samples_per_span + 1;
    if (a_samples.rows() != b_samples.rows() || a_samples.cols() != b_samples.cols() || a_samples.rows() % per != 0)
        fail_input(who, "samples of " + std::to_string(a_samples.rows()) + " x " + std::to_string(a_samples.cols()) + " and " + std::to_string(b_samples.rows()) + " x " +
                            std::to_string(b_samples.cols()) + " are not the same whole number of spans of " + std::to_string(per) + " rows");
    std::vector<double> moved(static_cast<std::size_t>(a_samples.rows() / per), 0.0);
    for (Eigen::Index r = 0; r < a_samples.rows(); ++r) {
        double& m = moved[static_cast<std::size_t>(r / per)];
        m = std::max(m, (a_samples.row(r) - b_samples.row(r)).norm());
    }
    return moved;
}

std::string method_applicability(const methods::MethodClaims& m, const PointList& points, bool closed) {
    if (closed && !m.supports_closed) return "open curves only";
    const int need = closed ? m.min_points_closed : m.min_points;
    if (points.rows() < need) return "needs at least " + std::to_string(need) + " points";
    if (m.max_points > 0 && points.rows() > m.max_points) return "takes at most " + std::to_string(m.max_points) + " points";
    if (points.cols() > m.max_dimension) return m.max_dimension == 2 ? "planar points only" : "at most " + std::to_string(m.max_dimension) + " dimensions";
    return "";
}

analysis::FairnessSampling comparison_sampling(int pieces) {
    const int budget = 2'000'000 / std::max(pieces, 1);
    // Quadrature sub-pieces: up to 512 per piece for curves of few pieces. A single cubic that nearly
    // turns back (its speed nearly 0) needs them: with 16, its length was 2e-7 off (eigen-spline-3
    // on table 3's four points), outside what the table's 8 digits promise.
    return {std::clamp(budget, 8, 128), std::clamp(budget / 128, 2, 512)};
}

const MethodComparison& find_comparison(const std::vector<MethodComparison>& c, const std::string& configuration) {
    const std::string name = methods::find_configuration(configuration).name;
    for (const MethodComparison& m : c)
        if (m.method == name) return m;
    fail_input("cagd::compare::find_comparison", "the comparison has no row '" + name + "'");
}

std::vector<MethodComparison> compare_methods(const PointList& points, const ComparisonOptions& options) {
    const char* who = "cagd::compare::compare_methods";
    if (points.cols() != 2 && points.cols() != 3) fail_input(who, "compares planar or space curves: needs 2 or 3 columns (x, y[, z]), got " + std::to_string(points.cols()));
    if (points.rows() < 2) fail_input(who, "needs at least 2 points, got " + std::to_string(points.rows()));
    // What no method could accept is bad input of the whole comparison (finite coordinates, no two
    // consecutive points equal); what one method refuses beyond that is that method's row.
    require_valid_points(points, 2, true, options.closed, who);
    std::vector<methods::Configuration> configurations = options.configurations;
    if (configurations.empty()) {
        for (const std::string& name : options.methods) configurations.push_back(methods::find_configuration(name));
        if (options.methods.empty()) configurations = methods::configurations();
    }
    const double diagonal = bounding_box_diagonal(points);
    const auto measure_unguarded = [&](const methods::Configuration& configuration) {
        MethodComparison c;
        c.method = configuration.name;
        c.note = method_applicability(configuration.claims, points, options.closed);
        if (!c.note.empty()) {
            c.status = "not applicable";
            return c;
        }
        // What builds share (the pseudo-spline's tables) is loaded outside the timing, so that
        // `seconds` does not charge it to whichever configuration runs first.
        const auto prepared = std::chrono::steady_clock::now();
        if (configuration.method->prepare) configuration.method->prepare(configuration.values, static_cast<int>(points.cols()));
        const auto start = std::chrono::steady_clock::now();
        c.shared_seconds = std::chrono::duration<double>(start - prepared).count();
        InterpolationResult r;
        try {
            const auto start_state = options.starts.find(configuration.name);
            if (start_state != options.starts.end()) {
                r = methods::interpolate_from(configuration, points, options.closed, start_state->second);
            } else {
                r = methods::interpolate(configuration, points, options.closed);
            }
        } catch (const InvalidInput& e) {  // this method refuses these points (Boost's Catmull–Rom on 1e-40 spacing): its row says why
            c.status = "refused";
            c.note = one_line(e.what());
            return c;
        }
        c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!r.outcome.ok() || !r.interpolant) {
            c.status = "no result";
            c.note = one_line(r.outcome.message);
            return c;
        }
        c.solver_state = std::move(r.solver_state);  // also the start of the footprint's build (below)
        c.interpolant = std::move(r.interpolant);
        const Curve& curve = *c.interpolant->curve;
        c.spans = static_cast<int>(c.interpolant->node_parameters.size()) - 1;
        if (!options.measures) {
            c.status = "ok";
            return c;
        }
        const analysis::FairnessSampling sampling = comparison_sampling(static_cast<int>(curve.breakpoints().size()) - 1);
        if (options.closed && points.cols() == 2) c.area = analysis::enclosed_area(curve);
        try {
            c.fairness = analysis::fairness_measures(curve, points, sampling);
            c.length = c.fairness->length;
            c.pseudo_energy = span_pseudo_energy(*c.interpolant, *c.fairness, sampling.quadrature_pieces);
            c.status = "ok";
            // A closed planar curve that loops where its polygon does not is measured, but flagged.
            if (options.closed && points.cols() == 2)
                if (std::string anomaly = analysis::closed_curve_anomaly(curve, points, c.length); !anomaly.empty()) {
                    c.status = to_string(AttemptStatus::loops);
                    c.note = std::move(anomaly);
                }
        } catch (const InvalidInput& e) {  // a sample of zero speed: κ undefined there
            c.length = analysis::arc_length(curve, sampling.quadrature_pieces);
            c.status = "cusp";
            c.note = one_line(e.what());
        }
        if (options.locality && points.rows() >= 3) {
            PointList moved = points;
            moved(points.rows() / 2, 1) += 1e-3 * diagonal;
            try {
                // From this build's final iterate (continuation: fewer Newton iterations, and the
                // same solution branch); a direct method builds anew.
                const InterpolationResult m = methods::interpolate_from(configuration, moved, options.closed, c.solver_state);
                if (m.outcome.ok() && m.interpolant) c.locality_footprint = spans_moved(*c.interpolant, *m.interpolant, 1e-9 * diagonal);
            } catch (const InvalidInput&) {  // the moved point made the input invalid for this method
            }
        }
        return c;
    };
    // Whatever one configuration throws beyond a refusal (its curve failing to evaluate inside its
    // own range, memory) is that configuration's row, never the end of the comparison.
    const auto measure = [&](const methods::Configuration& configuration) {
        try {
            return measure_unguarded(configuration);
        } catch (const std::exception& e) {
            MethodComparison c;
            c.method = configuration.name;
            c.status = to_string(AttemptStatus::failed);
            c.note = "the method failed (a defect of the method, not of the points): " + one_line(e.what());
            return c;
        }
    };
    // The iterative methods are started first; the rows keep the configurations' order.
    std::vector<std::size_t> order(configurations.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_partition(order.begin(), order.end(), [&](std::size_t k) { return configurations[k].method->iterative; });
    std::vector<MethodComparison> out(configurations.size());
    std::mutex report;
    const int threads = options.threads > 0 ? options.threads : hardware_threads();
    parallel_for(static_cast<long>(order.size()), threads, [&](long slot) {
        const std::size_t k = order[static_cast<std::size_t>(slot)];
        out[k] = measure(configurations[k]);
        const std::lock_guard<std::mutex> lock(report);
        if (options.on_method) options.on_method(out[k]);
    });
    return out;
}

std::vector<std::string> comparison_header(bool closed, bool timing, int dimension) {
    std::vector<std::string> h{"method", "status", "spans", "length"};
    if (closed && dimension == 2) h.push_back("area");
    if (dimension == 2)
        for (const char* n : {"bending_energy", "pseudo_energy", "inflections", "max_abs_curvature", "max_abs_dcurvature_ds", "overshoot", "locality_footprint"}) h.push_back(n);
    else
        for (const char* n : {"bending_energy", "pseudo_energy", "max_abs_curvature", "max_abs_dcurvature_ds", "max_abs_torsion", "overshoot", "locality_footprint"})
            h.push_back(n);
    if (timing) h.push_back("seconds"), h.push_back("shared_seconds");
    h.push_back("note");
    return h;
}

std::vector<std::vector<std::string>> comparison_rows(const std::vector<MethodComparison>& cs, bool closed, bool timing, int digits, int dimension) {
    std::vector<std::vector<std::string>> rows;
    const auto num = [&](double v) { return format_number(v, digits); };
    for (const MethodComparison& c : cs) {
        const bool built = c.interpolant.has_value();
        std::vector<std::string> r{c.method, c.status, built ? std::to_string(c.spans) : "", built ? num(c.length) : ""};
        if (closed && dimension == 2) r.push_back(built ? num(c.area) : "");
        if (c.fairness && dimension == 2) {
            const analysis::FairnessMeasures& f = *c.fairness;
            for (const std::string& v : {num(f.bending_energy), num(c.pseudo_energy), std::to_string(f.curvature_sign_changes), num(f.max_abs_curvature),
                                         num(f.max_abs_curvature_derivative), num(f.overshoot)})
                r.push_back(v);
        } else if (c.fairness) {
            const analysis::FairnessMeasures& f = *c.fairness;
            for (const std::string& v :
                 {num(f.bending_energy), num(c.pseudo_energy), num(f.max_abs_curvature), num(f.max_abs_curvature_derivative), num(f.max_abs_torsion), num(f.overshoot)})
                r.push_back(v);
        } else {
            r.insert(r.end(), 6, "");
        }
        r.push_back(c.locality_footprint ? std::to_string(*c.locality_footprint) : "");
        if (timing) r.push_back(built ? format_number(c.seconds, 3) : ""), r.push_back(c.status == "not applicable" ? "" : format_number(c.shared_seconds, 3));
        r.push_back(c.note);
        rows.push_back(std::move(r));
    }
    return rows;
}

std::string comparison_markdown(const std::vector<MethodComparison>& cs, bool closed, bool timing, int digits, int dimension) {
    const std::vector<std::string> header = comparison_header(closed, timing, dimension);
    std::ostringstream md;
    md << "|";
    for (const std::string& h : header) md << " " << h << " |";
    md << "\n|";
    for (std::size_t i = 0; i < header.size(); ++i) md << (i == 0 || i + 1 == header.size() || i == 1 ? "---|" : "---:|");
    md << "\n";
    for (const auto& row : comparison_rows(cs, closed, timing, digits, dimension)) {
        md << "|";
        for (std::string f : row) {
            std::replace(f.begin(), f.end(), '|', '/');
            md << " " << f << " |";
        }
        md << "\n";
    }
    return md.str();
}

FigureSampling figure_sampling(int spans, int budget) {
    if (spans < 1 || budget < 2) fail_input("cagd::compare::figure_sampling", "needs spans >= 1 and budget >= 2, got " + std::to_string(spans) + " and " + std::to_string(budget));
    // A sampled span yields per_span + 1 samples (both ends).
    const long total = static_cast<long>(spans), b = budget;
    if (total * 33 <= b) return {32, 1};
    if (total * 2 <= b) return {static_cast<int>(b / total) - 1, 1};
    return {1, static_cast<int>((2 * total + b - 1) / b)};
}

FigureData comparison_figure_data(const std::vector<MethodComparison>& cs, const PointList& points, const FigureSampling& sampling) {
    const int per_span = sampling.per_span, stride = sampling.span_stride;
    if (per_span < 1 || stride < 1)
        fail_input("cagd::compare::comparison_figure_data", "per_span and span_stride must be >= 1, got " + std::to_string(per_span) + " and " + std::to_string(stride));
    const bool trapezoid = sampling.arc_length == FigureSampling::ArcLength::trapezoid;
    if (trapezoid && stride != 1) fail_input("cagd::compare::comparison_figure_data", "the trapezoid arc length needs every span sampled (span_stride 1), got " + std::to_string(stride));
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
                s += measured ? (*measured)[k].first : analysis::piece_arc_length(*a.curve, a.node_parameters[k], a.node_parameters[k + 1], 1);
                continue;
            }
            double previous = a.node_parameters[k], previous_speed = 0.0;
            for (int j = 0; j <= per_span; ++j) {
                const double t = span_parameter(a, k, double(j) / per_span);
                const Eigen::MatrixXd J = j == per_span && t > a.curve->t_min() ? a.curve->jet_from_left(t, space ? 3 : 2) : a.curve->jet(t, space ? 3 : 2);
                // The step's arc length: by quadrature, or the trapezoid rule on the speeds at its ends.
                const double speed = J.row(1).norm();
                const auto step_length = [&] { return trapezoid ? 0.5 * (t - previous) * (previous_speed + speed) : analysis::piece_arc_length(*a.curve, previous, t, 1); };
                if (space) {
                    if (j < per_span || last) d.curves.push_back({index, J(0, 0), J(0, 1), J(0, 2)});
                    if (t > previous) s += step_length();
                    previous = t;
                    previous_speed = speed;
                    if (cs[i].status == "cusp" || !(J.row(1).norm() > 0)) continue;
                    const Eigen::Vector3d d1 = J.row(1).transpose(), d2 = J.row(2).transpose();
                    const Eigen::Vector3d cr = d1.cross(d2);
                    const double v = d1.norm(), cn = cr.norm();
                    // τ is undefined where κ = 0 (a straight point): left at 0 there, as the table's maximum skips it.
                    const double kappa = cn / (v * v * v), tau = kappa * diagonal > analysis::kFlatCurvature ? cr.dot(J.row(3).transpose()) / (cn * cn) : 0.0;
                    d.profiles.push_back({index, s, kappa, tau});
                    continue;
                }
                if (j < per_span || last) d.curves.push_back({index, J(0, 0), J(0, 1)});
                // One 20-point rule per sample step (analysis::arc_length would search all breakpoints
                // per call: O(n²) on long inputs); a step across a breakpoint costs plot accuracy only.
                if (t > previous) s += step_length();
                previous = t;
                previous_speed = speed;
                const double v = std::hypot(J(1, 0), J(1, 1));
                if (cs[i].status == "cusp" || !(v > 0)) continue;
                const double kappa = (J(1, 0) * J(2, 1) - J(1, 1) * J(2, 0)) / (v * v * v);
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
        const std::size_t teeth_stride = (samples.size() + kMaxCombTeeth - 2) / (kMaxCombTeeth - 1);  // ≤ kMaxCombTeeth − 1 strided teeth, and the last
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

std::vector<std::string> figure_methods_header() {
    return {"index", "method", "curves_first", "curves_count", "curvature_first", "curvature_count", "combs_first", "combs_count", "comb_stride", "comb_scale", "status"};
}

std::vector<std::vector<std::string>> figure_methods_rows(const std::vector<MethodComparison>& cs, const FigureData& d) {
    std::vector<std::vector<std::string>> out;
    for (std::size_t i = 0; i < cs.size(); ++i) out.push_back({std::to_string(i), cs[i].method});
    for (const std::vector<std::vector<double>>* rows : {&d.curves, &d.profiles, &d.combs}) {
        std::vector<std::size_t> first(cs.size(), 0), count(cs.size(), 0);
        for (std::size_t r = 0; r < rows->size(); ++r) {
            const auto m = static_cast<std::size_t>((*rows)[r][0]);
            if (count[m] == 0)
                first[m] = r;
            else if (first[m] + count[m] != r)
                throw std::logic_error("cagd::compare::figure_methods_rows: rows of method " + std::to_string(m) + " are not consecutive");
            ++count[m];
        }
        for (std::size_t i = 0; i < cs.size(); ++i) {
            out[i].push_back(std::to_string(first[i]));
            out[i].push_back(std::to_string(count[i]));
        }
    }
    for (std::size_t i = 0; i < cs.size(); ++i) {
        const bool comb = i < d.comb_stride.size() && d.comb_stride[i] > 0;
        out[i].push_back(comb ? std::to_string(d.comb_stride[i]) : "0");  // 0 (not empty): the plot script reads the column as words
        out[i].push_back(comb ? format_number(d.comb_scale[i], 6) : "0");
        std::string status = cs[i].status;  // one word for the plot script: "not applicable" → "not-applicable"
        std::replace(status.begin(), status.end(), ' ', '-');
        out[i].push_back(status);
    }
    return out;
}

}  // namespace cagd::compare
