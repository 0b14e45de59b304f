#pragma once
/// @file
/// What draws curves for the scorecard (scorecard.hpp) and the peers' truth runs (peer_truths.hpp): a
/// configuration of the registry or a peer's configuration (peer_curves.hpp), behind one call that
/// draws a batch of curves, each an interpolant or the reason there is none (the classification of
/// interpolation_attempt.hpp).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/compare/peer_curves.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::compare {

/// A curve a subject drew, or why there is none.
struct DrawnCurve {
    AttemptStatus status = AttemptStatus::ok;           ///< ok, not applicable, refused, no result or failed
    std::string note{};                                 ///< why not ok
    std::optional<methods::Interpolant> interpolant{};  ///< when ok
    /// What made it, as a peer's adapter wrote it in its curve document (empty for a method's curve).
    std::optional<exports::CurveProvenance> provenance{};
    /// A peer that gives samples only: its pieces approximate its curve, within this distance (its
    /// document's max_distance, exact false); empty for the peer's own pieces and a method's curve.
    std::optional<double> approximation{};
};
/// One curve to draw.
struct CurveRequest {
    PointList points{};   ///< its points
    bool closed = false;  ///< closed
};
/// A configuration of the registry or of a peer, drawing curves in batches (a peer's adapter runs
/// once per thousand requests of a batch).
struct CurveSubject {
    std::string name{};  ///< the configuration's name; a peer's "peer:configuration"
    std::string kind{};  ///< "method" or "peer"
    /// One answer per request, in order.
    std::function<std::vector<DrawnCurve>(const std::vector<CurveRequest>&)> draw;
};
/// A configuration of the registry as a subject: attempt_interpolation on each request, `threads` at
/// once (0: the hardware's).
CurveSubject method_subject(const methods::Configuration& configuration, int threads = 0);
/// A peer's configuration as a subject: run_peer once per batch of at most a thousand requests (an
/// adapter's output is bounded; the answers do not depend on the split); an answer with an error is no
/// result (the peer's message the note), a run that failed is failed; a curve that does not pass
/// through the points is no result (peer_interpolant).
CurveSubject peer_subject(const PeerLauncher& launcher, const PeerConfiguration& configuration);
/// A peer's answer to a request for a curve through `points` as a drawn curve: its pieces as an
/// interpolant (peer_interpolant) with the document's provenance (and its bound where the pieces
/// approximate the peer's curve: DrawnCurve::approximation); or no result, its note the peer's
/// refusal ("peer: message") or why the pieces are not an interpolant through the points.
DrawnCurve peer_drawn_curve(const PeerAnswer& answer, const std::string& peer, const PointList& points, bool closed);
/// Curves drawn elsewhere as a subject (the viewer's JavaScript peers, drawn in the browser):
/// request k is answered by answers[k], a request beyond them with no result ("not drawn").
CurveSubject drawn_subject(const std::string& name, const std::vector<DrawnCurve>& answers);
/// The installed peers among a manifest's configurations, as subjects (installed_peer_subjects).
struct InstalledPeers {
    std::vector<CurveSubject> subjects{};  ///< the wanted configurations of the installed peers, in order
    std::vector<std::string> skipped{};    ///< for each peer not installed here, why ("peer: reason")
    std::vector<std::string> absent{};     ///< the wanted configurations of those peers ("peer:configuration")
};
/// The configurations of `manifest` that `wanted` accepts (by "peer:configuration"), as peer_subject
/// subjects of the peers installed here: each peer is asked once for its version (run_peer with no
/// request), and one that is not installed is skipped with its reason, never an error.
InstalledPeers installed_peer_subjects(const PeerLauncher& launcher, const std::vector<PeerConfiguration>& manifest,
                                       const std::function<bool(const std::string&)>& wanted);
/// A peer's pieces as an interpolant through `points` (closed: and back to the first): each node
/// parameter is the first break after the previous node where a piece starts at the point (within
/// 10⁻⁹ D), so a peer may draw several pieces per span; or, where none does, the parameter inside a
/// piece where the curve first passes through the point (Newton's method from each local minimum
/// of the distance at 65 samples, again within 10⁻⁹ D), so a peer may drop knots (SISL's free ends:
/// one cubic through four points). Each dτ/du 1. Nothing, with `why` set, when the curve does not
/// pass through a point after the one before, or its pieces do not join.
std::optional<methods::Interpolant> peer_interpolant(const exports::CurveDocument& document, const PointList& points,
                                                     bool closed, std::string& why);

}  // namespace cagd::compare
