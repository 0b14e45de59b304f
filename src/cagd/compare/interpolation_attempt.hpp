#pragma once
/// @file
/// One configuration of the registry tried on one set of points, and what became of it: the one
/// classification the benchmark's truth runs, classic runs and random sets share.
///
///   ok              a curve
///   not applicable  the method's claims exclude the input (methods::method_applicability: too few points,
///                   closed curves unsupported, 3-D); the method is not called
///   refused         the method's own input check threw InvalidInput (a reversal where no tangent
///                   exists, a degenerate span): the message is the note
///   no result       a returned status without a curve (no solution, no convergence, not
///                   representable): its message is the note
///   cusp            a curve, but with a point of zero speed where its curvature is undefined (set
///                   by the caller that measures the curve: attempt_interpolation never returns it)
///   loops           a closed planar curve, measured, but flagged: its turning number differs from
///                   its polygon's, or it is much longer than the polygon (analysis::closed_curve_anomaly,
///                   the reason the note); set by the caller that measures the curve
///   failed          the method, or its curve when measured, threw what no valid input should make
///                   it throw (an evaluation outside the range it states, memory): a defect of the
///                   method, its message the note; the callers that measure set it, one row each
#include <optional>
#include <string>

#include "cagd/core/points.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::compare {

/// What became of one interpolation (see above).
enum class AttemptStatus { ok, not_applicable, refused, no_result, cusp, loops, failed };
/// "ok", "not applicable", "refused", "no result", "cusp", "loops", "failed": the one text of each,
/// written only where text is written (tables, parts, the viewer, Python).
const char* to_string(AttemptStatus status);
/// The status whose to_string is `text`; nothing for any other text (a reader names its file).
std::optional<AttemptStatus> attempt_status_from_string(const std::string& text);

/// One interpolation tried (see above).
struct InterpolationAttempt {
    AttemptStatus status = AttemptStatus::ok;  ///< its outcome
    std::string note;                          ///< why not ok (empty when ok)
    methods::InterpolationResult result;       ///< the curve when ok
    /// Wall time of Method::prepare: the tables a method shares between builds, loaded from the
    /// user's cache or built (not deterministic; 0 when not applicable).
    double prepare_seconds = 0.0;
    /// Wall time of the build itself (not deterministic; 0 when not applicable or refused).
    double build_seconds = 0.0;
};
/// `configuration` on `points` (open or closed), classified; never throws for a method's refusal.
/// With `start` (an earlier build's solver_state for as many points), the solve starts there
/// (methods::interpolate_from).
/// The points are validated first (a refusal when they are not valid: non-finite, coincident
/// neighbours).
InterpolationAttempt attempt_interpolation(const methods::Configuration& configuration, const PointList& points,
                                           bool closed, const Eigen::VectorXd* start = nullptr);
/// The same on points validated already, closed as they were validated: a comparison validates them
/// once for all its configurations.
InterpolationAttempt attempt_interpolation(const methods::Configuration& configuration, const ValidPoints& points,
                                           const Eigen::VectorXd* start = nullptr);

}  // namespace cagd::compare
