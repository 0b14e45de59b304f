#include "cagd/compare/interpolation_attempt.hpp"

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

InterpolationAttempt attempt_interpolation(const methods::Configuration& configuration, const PointList& points, bool closed) {
    InterpolationAttempt a;
    a.note = method_applicability(configuration.claims, points, closed);
    if (!a.note.empty()) {
        a.status = AttemptStatus::not_applicable;
        return a;
    }
    try {
        a.result = methods::interpolate(configuration, points, closed);
    } catch (const InvalidInput& e) {
        a.status = AttemptStatus::refused;
        a.note = in_user_terms(one_line(e.what()));
        return a;
    }
    if (!a.result.outcome.ok() || !a.result.interpolant) {
        a.status = AttemptStatus::no_result;
        a.note = in_user_terms(one_line(a.result.outcome.message));
    }
    return a;
}

}  // namespace cagd::compare
