#include "cagd/compare/locality_footprint.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "cagd/core/errors.hpp"
#include "cagd/intrinsic/intrinsic_curve.hpp"
#include "cagd/spline/bspline.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace cagd::compare {

double span_parameter(const Interpolant& a, std::size_t k, double f) {
    const double t0 = a.node_parameters[k], t1 = a.node_parameters[k + 1];
    return f == 1.0 ? t1 : t0 + f * (t1 - t0);
}

namespace {

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
bool intrinsic_span_within_half(const intrinsic::IntrinsicCurve& a, const intrinsic::IntrinsicCurve& b,
                                const Interpolant& of_a, const Interpolant& of_b, std::size_t k, double tolerance) {
    const double parameter_rounding = 16.0 * std::numeric_limits<double>::epsilon() *
                                      (std::abs(of_a.node_parameters[k]) + std::abs(of_a.node_parameters[k + 1]) +
                                       std::abs(of_b.node_parameters[k]) + std::abs(of_b.node_parameters[k + 1]));
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
    const auto same_nodes = [&a, &b](std::size_t k) {
        return a.node_parameters[k] == b.node_parameters[k] && a.node_parameters[k + 1] == b.node_parameters[k + 1];
    };
    if (const auto* ca = dynamic_cast<const intrinsic::IntrinsicCurve*>(a.curve.get()),
        *cb = dynamic_cast<const intrinsic::IntrinsicCurve*>(b.curve.get());
        ca && cb) {
        if (ca->tangent_angle().segments() != static_cast<int>(spans) ||
            cb->tangent_angle().segments() != static_cast<int>(spans) ||
            ca->tangent_angle().degree() != cb->tangent_angle().degree())
            return {};
        return [ca, cb, &a, &b, tolerance](std::size_t k) {
            return intrinsic_span_within_half(*ca, *cb, a, b, k, tolerance);
        };
    }
    if (const auto* ha = dynamic_cast<const spline::PiecewiseHermiteCurve*>(a.curve.get()),
        *hb = dynamic_cast<const spline::PiecewiseHermiteCurve*>(b.curve.get());
        ha && hb) {
        if (ha->spans() != hb->spans() || ha->dimension() != hb->dimension()) return {};
        return [ha, hb, same_nodes](std::size_t k) {
            const auto i = static_cast<Eigen::Index>(k);
            return same_nodes(k) && same_rows(ha->nodes(), hb->nodes(), i, i + 2) &&
                   same_rows(ha->start_derivatives(), hb->start_derivatives(), i, i + 1) &&
                   same_rows(ha->end_derivatives(), hb->end_derivatives(), i, i + 1);
        };
    }
    if (const auto* ba = dynamic_cast<const BSplineCurve*>(a.curve.get()),
        *bb = dynamic_cast<const BSplineCurve*>(b.curve.get());
        ba && bb) {
        if (ba->degree() != bb->degree() || ba->knots().size() != bb->knots().size() ||
            ba->control_points().rows() != bb->control_points().rows() ||
            ba->control_points().cols() != bb->control_points().cols())
            return {};
        return [ba, bb, &a, same_nodes](std::size_t k) {
            if (!same_nodes(k)) return false;
            // The knot spans of the samples t0 ≤ t ≤ t1, and what A2.3 and the tables read for them.
            const int p = ba->degree(), s0 = ba->find_span(a.node_parameters[k]),
                      s1 = ba->find_span(a.node_parameters[k + 1]);
            const std::vector<double>&U = ba->knots(), &V = bb->knots();
            for (int i = s0 - p; i <= s1 + p + 1; ++i)
                if (!(U[static_cast<std::size_t>(i)] == V[static_cast<std::size_t>(i)])) return false;
            return same_rows(ba->control_points(), bb->control_points(), s0 - p, s1);
        };
    }
    return {};
}

}  // namespace

// Spans of a and b (same points but one moved) that differ by more than `tolerance` somewhere:
// span_displacements counted, skipping the spans footprint_skip_rule shows cannot count and
// sampling the others as span_displacements does — the same count, without sampling the spans a
// local method left unchanged, or 16 sines and cosines per sample on every span of the curvature
// profile.
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

std::vector<double> span_displacements(const Interpolant& a, const Interpolant& b, int samples_per_span) {
    if (a.node_parameters.size() != b.node_parameters.size())
        fail_input("cagd::compare::span_displacements", "the curves have " + std::to_string(a.node_parameters.size()) +
                                                            " and " + std::to_string(b.node_parameters.size()) +
                                                            " node parameters; they must agree");
    return span_displacements(span_samples(a, samples_per_span), span_samples(b, samples_per_span), samples_per_span);
}

Eigen::MatrixXd span_samples(const Interpolant& a, int samples_per_span) {
    if (samples_per_span < 1)
        fail_input("cagd::compare::span_samples",
                   "samples_per_span must be >= 1, got " + std::to_string(samples_per_span));
    const Eigen::Index spans = a.node_parameters.empty() ? 0 : static_cast<Eigen::Index>(a.node_parameters.size()) - 1;
    Eigen::MatrixXd out(spans * (samples_per_span + 1), a.curve->dimension());
    for (Eigen::Index k = 0; k < spans; ++k)
        sample_span(a, static_cast<std::size_t>(k), samples_per_span, out, k * (samples_per_span + 1));
    return out;
}

std::vector<double> span_displacements(const Eigen::MatrixXd& a_samples, const Eigen::MatrixXd& b_samples,
                                       int samples_per_span) {
    const char* who = "cagd::compare::span_displacements";
    if (samples_per_span < 1) fail_input(who, "samples_per_span must be >= 1, got " + std::to_string(samples_per_span));
    const Eigen::Index per = samples_per_span + 1;
    if (a_samples.rows() != b_samples.rows() || a_samples.cols() != b_samples.cols() || a_samples.rows() % per != 0)
        fail_input(who, "samples of " + std::to_string(a_samples.rows()) + " x " + std::to_string(a_samples.cols()) +
                            " and " + std::to_string(b_samples.rows()) + " x " + std::to_string(b_samples.cols()) +
                            " are not the same whole number of spans of " + std::to_string(per) + " rows");
    std::vector<double> moved(static_cast<std::size_t>(a_samples.rows() / per), 0.0);
    for (Eigen::Index r = 0; r < a_samples.rows(); ++r) {
        double& m = moved[static_cast<std::size_t>(r / per)];
        m = std::max(m, (a_samples.row(r) - b_samples.row(r)).norm());
    }
    return moved;
}

}  // namespace cagd::compare
