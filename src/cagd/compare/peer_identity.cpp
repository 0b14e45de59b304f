#include "cagd/compare/peer_identity.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::compare {

namespace {

constexpr int kSamples = 64;  // w = j/64, j = 0..64: the sampled lower bound of each piece's difference
constexpr const char* kOurs = "cagd:";

// One side of a claim: a configuration of the registry, or a peer's.
struct Side {
    bool ours = false;
    std::string peer{}, configuration{};
};
Side side_of(const std::string& name, const std::vector<PeerConfiguration>& manifest, const std::string& where) {
    const char* who = "cagd::compare::read_identity_claims";
    if (name.rfind(kOurs, 0) == 0) {
        const std::string configuration = name.substr(std::string(kOurs).size());
        methods::find_configuration(configuration);  // InvalidInput listing the configurations
        return {.ours = true, .configuration = configuration};
    }
    for (const PeerConfiguration& c : manifest)
        if (c.name() == name) return {.peer = c.peer, .configuration = c.configuration};
    fail_input(who, where + ": \"" + excerpt(name) +
                        "\" is neither cagd:<configuration> nor a peer's configuration of the manifest");
}

// The point of the Bézier curve with control points d (rows) at w (de Casteljau).
Eigen::RowVectorXd bezier_point(Eigen::MatrixXd d, double w) {
    for (Eigen::Index r = d.rows() - 1; r > 0; --r)
        for (Eigen::Index k = 0; k < r; ++k) d.row(k) = (1 - w) * d.row(k) + w * d.row(k + 1);
    return d.row(0);
}

std::string number(double v) { return format_number(v, 3); }

}  // namespace

PieceDifference piecewise_difference(const exports::BezierPieces& a, const exports::BezierPieces& b, double scale,
                                     int ends) {
    PieceDifference out;
    if (a.pieces() != b.pieces()) {
        out.incomparable = std::to_string(a.pieces()) + " and " + std::to_string(b.pieces()) + " pieces";
        return out;
    }
    if (a.dimension() != b.dimension()) {
        out.incomparable = "dimensions " + std::to_string(a.dimension()) + " and " + std::to_string(b.dimension());
        return out;
    }
    if (!(scale > 0))
        fail_input("cagd::compare::piecewise_difference", "scale " + std::to_string(scale) + " is not > 0");
    if (ends < 0) fail_input("cagd::compare::piecewise_difference", "ends = " + std::to_string(ends) + " is negative");
    if (a.pieces() <= 2 * ends) {
        out.incomparable =
            std::to_string(a.pieces()) + " pieces: none between the " + std::to_string(ends) + " left out at each end";
        return out;
    }
    const int degree = std::max(a.degree, b.degree);
    const exports::BezierPieces ea = a.degree < degree ? exports::elevate_degree(a, degree) : a;
    const exports::BezierPieces eb = b.degree < degree ? exports::elevate_degree(b, degree) : b;
    const int count = a.pieces();
    for (int i = ends; i < count - ends; ++i) {
        const Eigen::MatrixXd d = ea.piece(i) - eb.piece(i);
        const double bound = d.rowwise().norm().maxCoeff() / scale;
        out.bound = std::max(out.bound, bound);
        for (int j = 0; j <= kSamples; ++j)
            out.sampled = std::max(out.sampled, bezier_point(d, static_cast<double>(j) / kSamples).norm() / scale);
        ++out.compared;
        if (bound > kIdentityTolerance) ++out.over, out.farthest = std::max(out.farthest, std::min(i, count - 1 - i));
    }
    return out;
}

std::vector<IdentityClaim> read_identity_claims(const std::string& path) {
    const char* who = "cagd::compare::read_identity_claims";
    const TextTable t = read_text_table(path, {"left", "right", "closed", "ends", "expected", "reason"});
    std::vector<IdentityClaim> claims;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        IdentityClaim c{.left = t.at(r, "left"), .right = t.at(r, "right"), .reason = t.at(r, "reason")};
        const std::string &closed = t.at(r, "closed"), &expected = t.at(r, "expected");
        if (closed != "0" && closed != "1")
            fail_input(who, t.where(r) + ": closed \"" + excerpt(closed) + "\" is neither 0 nor 1");
        if (expected != "identical" && expected != "differs")
            fail_input(who, t.where(r) + ": expected \"" + excerpt(expected) + "\" is neither identical nor differs");
        if (c.reason.empty()) fail_input(who, t.where(r) + ": a claim needs its reason");
        c.closed = closed == "1", c.identical = expected == "identical";
        const std::string& ends = t.at(r, "ends");
        if (ends.size() != 1 || ends[0] < '0' || ends[0] > '9' || (c.closed && ends != "0"))
            fail_input(who, t.where(r) + ": ends \"" + excerpt(ends) + "\" is not a digit (0 for closed curves)");
        c.ends = ends[0] - '0';
        claims.push_back(std::move(c));
    }
    if (claims.empty()) fail_input(who, t.source + ": no claim");
    return claims;
}

IdentityResults measure_identities(const std::vector<IdentityClaim>& claims, const std::vector<ClassicDataSet>& sets,
                                   const std::vector<PeerConfiguration>& manifest, const PeerLauncher& launcher) {
    // Every side's curve on every data set: the peers' as requests, one run per peer.
    struct Pending {
        std::size_t claim;
        const ClassicDataSet* set;
        Side side[2];
        std::size_t request[2];  // index into the peer's requests (peer sides)
    };
    std::vector<Pending> pending;
    std::map<std::string, std::vector<PeerRequest>> requests;
    for (std::size_t c = 0; c < claims.size(); ++c) {
        const std::string where = "claim " + std::to_string(c + 1);
        const Side left = side_of(claims[c].left, manifest, where), right = side_of(claims[c].right, manifest, where);
        for (const ClassicDataSet& set : sets) {
            if (set.closed != claims[c].closed) continue;
            Pending p{.claim = c, .set = &set, .side = {left, right}, .request = {0, 0}};
            for (int s = 0; s < 2; ++s)
                if (!p.side[s].ours) {
                    std::vector<PeerRequest>& list = requests[p.side[s].peer];
                    p.request[s] = list.size();
                    list.push_back(
                        {.configuration = p.side[s].configuration, .points = set.points, .closed = set.closed});
                }
            pending.push_back(std::move(p));
        }
    }
    IdentityResults results;
    std::map<std::string, PeerRun> runs;
    for (const PeerConfiguration& c : manifest) {
        if (runs.count(c.peer)) continue;
        PeerRun run = run_peer(launcher, c.peer, requests[c.peer]);
        results.peers.push_back(
            {.peer = c.peer, .installed = run.installed, .version = run.version, .reason = run.reason});
        runs.emplace(c.peer, std::move(run));
    }
    for (const Pending& p : pending) {
        IdentityMeasure m{.claim = p.claim, .data_set = p.set->name};
        exports::BezierPieces curve[2];
        for (int s = 0; s < 2 && m.failure.empty(); ++s) {
            const std::string label = s == 0 ? "left: " : "right: ";
            if (p.side[s].ours) {
                const InterpolationAttempt a = attempt_interpolation(
                    methods::find_configuration(p.side[s].configuration), p.set->points, p.set->closed);
                if (a.status != AttemptStatus::ok)
                    m.failure = label + to_string(a.status) + ": " + a.note;
                else if (a.result.interpolant->curve->polynomial_degree() < 0)
                    m.failure = label + "not a polynomial curve";
                else
                    curve[s] = exports::exact_bezier_pieces(*a.result.interpolant->curve);
                continue;
            }
            const PeerRun& run = runs.at(p.side[s].peer);
            if (!run.installed) {
                m.failure = label + "skipped: " + run.reason;
                continue;
            }
            const PeerAnswer& answer = run.answers[p.request[s]];
            if (!answer.curve)
                m.failure = label + answer.error;
            else if (!answer.curve->form.exact)
                m.failure = label + "the peer gives samples, not its pieces";
            else if (const PointList& echoed = answer.curve->provenance.points;
                     echoed.rows() != p.set->points.rows() || echoed.cols() != p.set->points.cols() ||
                     echoed != p.set->points || answer.curve->provenance.closed != p.set->closed)
                m.failure = label + "the peer answered with the curve of other points";
            else
                curve[s] = answer.curve->form.pieces;
        }
        if (m.failure.empty()) {
            const PointList& q = p.set->points;
            m.difference = piecewise_difference(
                curve[0], curve[1], (q.colwise().maxCoeff() - q.colwise().minCoeff()).norm(), claims[p.claim].ends);
            m.failure = m.difference.incomparable.empty() ? "" : "not comparable: " + m.difference.incomparable;
        }
        results.measures.push_back(std::move(m));
    }
    return results;
}

std::string identity_measures_csv(const std::vector<IdentityClaim>& claims, const IdentityResults& results) {
    std::string out = "left,right,closed,ends,expected,data_set,status,sampled,bound,pieces,pieces_over,farthest\n";
    for (const IdentityMeasure& m : results.measures) {
        const IdentityClaim& c = claims.at(m.claim);
        const bool measured = m.failure.empty();
        for (const std::string& f :
             {c.left, c.right, std::string(c.closed ? "1" : "0"), std::to_string(c.ends),
              std::string(c.identical ? "identical" : "differs"), m.data_set,
              measured ? std::string("measured") : m.failure, measured ? number(m.difference.sampled) : std::string(),
              measured ? number(m.difference.bound) : std::string(),
              measured ? std::to_string(m.difference.compared) : std::string(),
              measured ? std::to_string(m.difference.over) : std::string(),
              measured ? std::to_string(m.difference.farthest) : std::string()})
            (out += csv_field(f)) += ',';
        out.back() = '\n';
    }
    return out;
}

std::string peers_markdown(const std::vector<IdentityClaim>& claims, const std::vector<PeerConfiguration>& manifest,
                           const IdentityResults& results) {
    std::ostringstream o;
    o << "# The peers\n\nOther libraries' interpolants, each run as its users run it by an adapter of its own "
         "(peers/, docs/peers.md). Written by `cagd peers`; its configurations: docs/methods.md. A configuration "
         "marked *samples* comes from a peer that gives samples only: its adapter's pieces approximate the peer's "
         "curve within the bound each of its documents states (max_distance), and every measure of it is of "
         "those pieces.\n\n"
      << "| peer | version | configurations |\n|---|---|---|\n";
    for (const PeerStatus& s : results.peers) {
        std::string configurations;
        for (const PeerConfiguration& c : manifest)
            if (c.peer == s.peer)
                configurations += (configurations.empty() ? "" : ", ") + c.configuration +
                                  (c.output == "samples" ? " (*samples*)" : "");
        o << "| " << s.peer << " | " << (s.installed ? s.version : "skipped: " + s.reason) << " | " << configurations
          << " |\n";
    }
    o << "\n## Identities\n\nEach pair on every classic data set of its closedness; the difference of the two "
         "curves piece by piece, relative to the points' bounding-box diagonal: the largest sampled value (a lower "
         "bound of the supremum) and the largest control-point difference (an upper bound). `identical` holds when "
         "every bound is at most "
      << number(kIdentityTolerance)
      << "; `differs` is confirmed when a sampled value exceeds it. Where: the pieces whose bound exceeds it, and how "
         "far from an end (open) or the seam (closed) the farthest lies. Ends: pieces left out at each end.\n\n"
      << "| left | right | curves | ends | expected | data sets | sampled | bound | where | verdict | why |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (std::size_t c = 0; c < claims.size(); ++c) {
        PieceDifference all;
        int measured = 0, total = 0;
        std::string first_failure;
        for (const IdentityMeasure& m : results.measures) {
            if (m.claim != c) continue;
            ++total;
            if (!m.failure.empty()) {
                if (first_failure.empty()) first_failure = m.data_set + ": " + m.failure;
                continue;
            }
            const PieceDifference& d = m.difference;
            ++measured, all.sampled = std::max(all.sampled, d.sampled), all.bound = std::max(all.bound, d.bound);
            all.compared += d.compared, all.over += d.over, all.farthest = std::max(all.farthest, d.farthest);
        }
        const IdentityClaim& k = claims[c];
        const std::string verdict = measured == 0 ? "not measured"
                                    : k.identical ? (all.bound <= kIdentityTolerance ? "holds" : "does not hold")
                                    : all.sampled > kIdentityTolerance ? "differs"
                                                                       : "does not differ";
        const std::string end = k.closed ? "the seam" : "an end";
        const std::string where =
            measured == 0   ? ""
            : all.over == 0 ? "nowhere"
                            : std::to_string(all.over) + " of " + std::to_string(all.compared) + " pieces, " +
                                  (all.farthest == 0 ? "at " + end + " only"
                                                     : "up to " + std::to_string(all.farthest) + " from " + end);
        o << "| " << k.left << " | " << k.right << " | " << (k.closed ? "closed" : "open") << " | " << k.ends << " | "
          << (k.identical ? "identical" : "differs") << " | " << measured << " of " << total << " | "
          << (measured ? number(all.sampled) : "") << " | " << (measured ? number(all.bound) : "") << " | " << where
          << " | " << verdict << " | " << k.reason
          << (first_failure.empty() ? "" : " (not measured: " + first_failure + ")") << " |\n";
    }
    return o.str();
}

}  // namespace cagd::compare
