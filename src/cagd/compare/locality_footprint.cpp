#include "cagd/compare/locality_footprint.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "cagd/core/errors.hpp"

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

}  // namespace

// Spans of a and b (same points but one moved) that differ by more than `tolerance` somewhere:
// span_displacements counted, skipping the spans whose Curve::span_offset_bound is at most half the
// tolerance (a local method's spans computed from equal data, bound 0; the curvature profile's by its
// offset bound; the half a margin over the bound's own rounding) and sampling the others as
// span_displacements does — the same count, without sampling what cannot have moved.
int spans_moved(const Interpolant& a, const Interpolant& b, double tolerance) {
    if (a.node_parameters.size() != b.node_parameters.size())
        fail_input("cagd::compare::spans_moved", "the curves have " + std::to_string(a.node_parameters.size()) +
                                                     " and " + std::to_string(b.node_parameters.size()) +
                                                     " node parameters; they must agree");
    const std::size_t spans = a.node_parameters.empty() ? 0 : a.node_parameters.size() - 1;
    const Eigen::Index per = kFootprintSamplesPerSpan + 1;
    Eigen::MatrixXd sa(per, a.curve->dimension()), sb(per, b.curve->dimension());
    int moved = 0;
    for (std::size_t k = 0; k < spans; ++k) {
        const std::optional<double> bound = a.curve->span_offset_bound(
            *b.curve, a.node_parameters[k], a.node_parameters[k + 1], b.node_parameters[k], b.node_parameters[k + 1]);
        if (bound && *bound <= 0.5 * tolerance) continue;
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
