#include "cagd/compare/curve_subject.hpp"

#include <algorithm>
#include <limits>
#include <memory>

#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/export/bspline_form.hpp"

namespace cagd::compare {

namespace {

constexpr double kPeerThroughPoint = 1e-9;  // a peer's piece starts at a point within this × D
// Requests per run of a peer's adapter: its output is bounded (run_program: 1 GiB), and a thousand
// curves of 64 points as plotutils's tension-5 writes them (16 quintic pieces a span) are 0.24 GB.
constexpr std::size_t kPeerRequestsPerRun = 1000;

DrawnCurve drawn(InterpolationAttempt a) {
    DrawnCurve d{.status = a.status, .note = std::move(a.note), .interpolant = std::nullopt};
    if (a.status == AttemptStatus::ok) d.interpolant = std::move(a.result.interpolant);
    return d;
}

// The first parameter t in (a, b] where `curve` passes within `tolerance` of p: Newton's method on
// (c(t) − p)·c′(t) = 0 (kept inside [a, b]) from each local minimum, in turn, of the distance at
// 65 equally spaced samples (a piece that loops passes near p more than once).
std::optional<double> first_pass_through(const Curve& curve, const Eigen::RowVectorXd& p, double a, double b,
                                         double tolerance) {
    constexpr int kSamples = 64, kNewtonSteps = 12;
    std::vector<double> t(kSamples + 1), d(kSamples + 1);
    for (int j = 0; j <= kSamples; ++j) {
        t[j] = j == kSamples ? b : a + (b - a) * j / kSamples;
        d[j] = (curve.jet(t[j], 0).row(0) - p).norm();
    }
    for (int j = 0; j <= kSamples; ++j) {
        if ((j > 0 && d[j - 1] < d[j]) || (j < kSamples && d[j + 1] < d[j])) continue;  // not a local minimum
        double u = t[j];
        for (int step = 0; step < kNewtonSteps; ++step) {
            const Eigen::MatrixXd jet = curve.jet(u, 2);
            const Eigen::RowVectorXd e = jet.row(0) - p;
            const double slope = jet.row(1).squaredNorm() + e.dot(jet.row(2));
            if (!(slope > 0.0)) break;
            u = std::clamp(u - e.dot(jet.row(1)) / slope, a, b);
        }
        if (u > a && (curve.jet(u, 0).row(0) - p).norm() <= tolerance) return u;
    }
    return std::nullopt;
}

}  // namespace

CurveSubject method_subject(const methods::Configuration& configuration, int threads) {
    return {
        .name = configuration.name,
        .kind = "method",
        .draw = [configuration, threads](const std::vector<CurveRequest>& requests) {
            std::vector<DrawnCurve> out(requests.size());
            parallel_for(static_cast<long>(requests.size()), threads > 0 ? threads : hardware_threads(), [&](long k) {
                const CurveRequest& r = requests[static_cast<std::size_t>(k)];
                out[static_cast<std::size_t>(k)] = drawn(attempt_interpolation(configuration, r.points, r.closed));
            });
            return out;
        }};
}

std::optional<methods::Interpolant> peer_interpolant(const exports::CurveDocument& document, const PointList& points,
                                                     bool closed, std::string& why) {
    const exports::BezierPieces& pieces = document.form.pieces;
    if (pieces.dimension() != points.cols() || pieces.pieces() < 1) {
        why = "the peer's curve has " + std::to_string(pieces.pieces()) + " pieces of dimension " +
              std::to_string(pieces.dimension()) + " for points of dimension " + std::to_string(points.cols());
        return std::nullopt;
    }
    methods::Interpolant in;
    try {
        in.curve = std::make_shared<const BSplineCurve>(exports::bezier_pieces_curve(pieces));
    } catch (const InvalidInput& e) {
        why = e.what();
        return std::nullopt;
    }
    const double tolerance = kPeerThroughPoint * bounding_box_diagonal(points);
    const int last = pieces.pieces();
    const auto start = [&](int k) -> Eigen::RowVectorXd {  // where piece k starts; k = last: the end
        return k < last ? pieces.control.row(static_cast<Eigen::Index>(k) * (pieces.degree + 1))
                        : pieces.control.row(pieces.control.rows() - 1);
    };
    const long n = points.rows(), nodes = n + (closed ? 1 : 0);
    // Each point where a piece starts at it, or else where a piece passes through it (a peer that
    // drops knots, as SISL's free ends do), after the point before.
    int k = 0;
    double after = -std::numeric_limits<double>::infinity();
    for (long i = 0; i < nodes; ++i) {
        const Eigen::RowVectorXd p = points.row(i % n);
        std::optional<double> node;
        for (int j = k; j <= last && !node; ++j)  // first where a piece starts (the usual peer)
            if (pieces.breaks[static_cast<std::size_t>(j)] > after && (start(j) - p).norm() <= tolerance)
                node = pieces.breaks[static_cast<std::size_t>(j)], k = j;
        for (int j = k; j < last && !node; ++j) {  // else inside a piece
            const double lo = std::max(pieces.breaks[static_cast<std::size_t>(j)], after);
            if (const auto t =
                    first_pass_through(*in.curve, p, lo, pieces.breaks[static_cast<std::size_t>(j) + 1], tolerance))
                node = *t, k = j;
        }
        if (!node) {
            why = "the peer's curve does not pass through " + point_label(i % n) + " after the one before";
            return std::nullopt;
        }
        in.node_parameters.push_back(after = *node);
    }
    if (in.node_parameters.front() != pieces.breaks.front() || in.node_parameters.back() != pieces.breaks.back()) {
        why = "the peer's curve runs on beyond its first or last point";
        return std::nullopt;
    }
    in.dtau_du.assign(static_cast<std::size_t>(nodes - 1), 1.0);
    return in;
}

DrawnCurve peer_drawn_curve(const PeerAnswer& answer, const std::string& peer, const PointList& points, bool closed) {
    if (!answer.curve) return {.status = AttemptStatus::no_result, .note = peer + ": " + answer.error};
    DrawnCurve d;
    if (d.interpolant = peer_interpolant(*answer.curve, points, closed, d.note); !d.interpolant)
        return {.status = AttemptStatus::no_result, .note = d.note};
    d.provenance = answer.curve->provenance;
    if (!answer.curve->form.exact) d.approximation = answer.curve->form.max_distance;
    return d;
}

CurveSubject drawn_subject(const std::string& name, const std::vector<DrawnCurve>& answers) {
    return {.name = name, .kind = "peer", .draw = [answers](const std::vector<CurveRequest>& requests) {
                std::vector<DrawnCurve> out;
                for (std::size_t k = 0; k < requests.size(); ++k)
                    out.push_back(k < answers.size()
                                      ? answers[k]
                                      : DrawnCurve{.status = AttemptStatus::no_result, .note = "not drawn"});
                return out;
            }};
}

CurveSubject peer_subject(const PeerLauncher& launcher, const PeerConfiguration& configuration) {
    return {.name = configuration.name(),
            .kind = "peer",
            .draw = [launcher, configuration](const std::vector<CurveRequest>& requests) {
                std::vector<DrawnCurve> out(requests.size());
                std::vector<PeerRequest> asked;
                std::vector<std::size_t> index;
                for (std::size_t k = 0; k < requests.size(); ++k) {
                    const bool closed = requests[k].closed;
                    if (closed ? !configuration.closed : !configuration.open) {
                        out[k] = {.status = AttemptStatus::not_applicable,
                                  .note = std::string("draws no ") + (closed ? "closed" : "open") + " curves"};
                        continue;
                    }
                    asked.push_back({configuration.configuration, requests[k].points, closed});
                    index.push_back(k);
                }
                for (std::size_t first = 0; first < asked.size(); first += kPeerRequestsPerRun) {
                    const std::size_t count = std::min(kPeerRequestsPerRun, asked.size() - first);
                    const PeerRun run = run_peer(
                        launcher, configuration.peer,
                        {asked.begin() + static_cast<long>(first), asked.begin() + static_cast<long>(first + count)});
                    for (std::size_t i = first; i < first + count; ++i) {
                        DrawnCurve& d = out[index[i]];
                        if (!run.installed || !run.reason.empty())
                            d = {.status = AttemptStatus::failed, .note = run.reason};
                        else
                            d = peer_drawn_curve(run.answers[i - first], configuration.peer, asked[i].points,
                                                 asked[i].closed);
                    }
                }
                return out;
            }};
}

InstalledPeers installed_peer_subjects(const PeerLauncher& launcher, const std::vector<PeerConfiguration>& manifest,
                                       const std::function<bool(const std::string&)>& wanted) {
    InstalledPeers out;
    std::vector<std::string> asked, missing;  // the peers asked for their version; those not installed
    for (const PeerConfiguration& c : manifest) {
        if (!wanted(c.name())) continue;
        if (std::find(asked.begin(), asked.end(), c.peer) == asked.end()) {
            asked.push_back(c.peer);
            if (const PeerRun probe = run_peer(launcher, c.peer, {}); !probe.installed) {
                out.skipped.push_back(probe.reason);
                missing.push_back(c.peer);
            }
        }
        if (std::find(missing.begin(), missing.end(), c.peer) == missing.end())
            out.subjects.push_back(peer_subject(launcher, c));
        else
            out.absent.push_back(c.name());
    }
    return out;
}

}  // namespace cagd::compare
