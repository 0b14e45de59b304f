#include "cagd/compare/interpolation_attempt.hpp"

#include <chrono>

#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::compare {

const char* to_string(AttemptStatus status) {
    switch (status) {
        case AttemptStatus::ok: return "ok";
        case AttemptStatus::not_applicable: return "not applicable";
        case AttemptStatus::refused: return "refused";
        case AttemptStatus::no_result: return "no result";
        case AttemptStatus::cusp: return "cusp";
        case AttemptStatus::loops: return "loops";
        case AttemptStatus::failed: return "failed";
    }
    return "?";
}

std::optional<AttemptStatus> attempt_status_from_string(const std::string& text) {
    for (const AttemptStatus s :
         {AttemptStatus::ok, AttemptStatus::not_applicable, AttemptStatus::refused, AttemptStatus::no_result,
          AttemptStatus::cusp, AttemptStatus::loops, AttemptStatus::failed})
        if (text == to_string(s)) return s;
    return std::nullopt;
}

InterpolationAttempt attempt_interpolation(const methods::Configuration& configuration, const ValidPoints& points,
                                           const Eigen::VectorXd* start) {
    InterpolationAttempt a;
    a.note = methods::method_applicability(configuration.claims, points.points(), points.closed());
    if (!a.note.empty()) {
        a.status = AttemptStatus::not_applicable;
        return a;
    }
    // What builds share (the pseudo-spline's tables) is loaded apart, so that build_seconds does
    // not charge it to whichever configuration runs first.
    const auto prepared = std::chrono::steady_clock::now();
    if (configuration.method->prepare)
        configuration.method->prepare(configuration.values, static_cast<int>(points.points().cols()));
    const auto built = std::chrono::steady_clock::now();
    a.prepare_seconds = std::chrono::duration<double>(built - prepared).count();
    try {
        a.result = methods::interpolate_from(configuration, points, start ? *start : Eigen::VectorXd());
    } catch (const InvalidInput& e) {
        // this method refuses these points (Boost's Catmull–Rom on 1e-40 spacing): its row says why
        a.status = AttemptStatus::refused;
        a.note = in_user_terms(one_line(e.what()));
        return a;
    }
    a.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - built).count();
    if (!a.result.outcome.ok() || !a.result.interpolant) {
        a.status = AttemptStatus::no_result;
        a.note = in_user_terms(one_line(a.result.outcome.message));
    }
    return a;
}

InterpolationAttempt attempt_interpolation(const methods::Configuration& configuration, const PointList& points,
                                           bool closed, const Eigen::VectorXd* start) {
    InterpolationAttempt a;
    a.note = methods::method_applicability(configuration.claims, points, closed);
    if (!a.note.empty()) {
        a.status = AttemptStatus::not_applicable;
        return a;
    }
    const int need = closed ? configuration.claims.min_points_closed : configuration.claims.min_points;
    try {
        const ValidPoints valid =
            validate_points(points, need, closed, methods::interpolate_who(*configuration.method));
        return attempt_interpolation(configuration, valid, start);
    } catch (const InvalidInput& e) {  // no method takes these points: this one refuses them
        a.status = AttemptStatus::refused;
        a.note = in_user_terms(one_line(e.what()));
        return a;
    }
}

}  // namespace cagd::compare
