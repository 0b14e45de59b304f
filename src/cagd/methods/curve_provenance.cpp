#include "cagd/methods/curve_provenance.hpp"

#include <cstdio>

#include "cagd/core/checksum.hpp"

namespace cagd::methods {

std::string registry_fingerprint() {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a64(registry_listing())));
    return hex;
}

exports::CurveProvenance method_provenance(const Method& method, const ParameterValues& values, const PointList& points,
                                           bool closed) {
    return {.method = method.name,
            .parameters = values.as_text(),
            .parameter = method.claims(values).parameter,
            .closed = closed,
            .points = points,
            .registry = registry_fingerprint()};
}

}  // namespace cagd::methods
