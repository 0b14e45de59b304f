#pragma once
/// @file
/// What made a curve of the registry, as the curve document records it (export/curve_json.hpp):
/// the method's name, its parameters as text, what its parameter t is (MethodClaims::parameter),
/// the points, and the registry's fingerprint, so that a reader can rebuild the curve and tell
/// whether the registry that built it is its own.
#include <string>

#include "cagd/core/points.hpp"
#include "cagd/export/curve_json.hpp"
#include "cagd/methods/method_parameters.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::methods {

/// The registry's fingerprint: FNV-1a 64 of registry_listing(), 16 hex digits.
std::string registry_fingerprint();

/// The provenance of a curve that `method` built under `values` through `points`, in the method's
/// own parameter (MethodClaims::parameter): what `cagd interpolate`, `cagd compare --export`,
/// Python and the viewer write.
exports::CurveProvenance method_provenance(const Method& method, const ParameterValues& values, const PointList& points,
                                           bool closed);

}  // namespace cagd::methods
