#pragma once
/// @file
/// The optional dependencies a build of the library has, and the one error for a function whose
/// dependency is missing.
///
/// Every registry method needs only Eigen and Boost, with one exception: occt-interpolate needs
/// OpenCASCADE (and is registered only where it is built in). The others serve the reference
/// cross-checks and the functions named here:
/// - Ceres (CMake option CAGD_WITH_CERES, default ON): the reference pseudo-energy minimisers
///   (Romberg + Ceres conjugate gradients: `minimize_pseudo_energy_reference`, its space form, the
///   tables of method "reference"), the curvature-profile Levenberg–Marquardt cross-check and
///   Hosaka's elastic space curve. Ceres' header-only `ceres::Jet` (automatic differentiation of the
///   curvature-profile Jacobian) is used in either case, so Ceres' headers are always needed.
/// - NLopt (CAGD_WITH_NLOPT, default ON): the independent second minimiser
///   (`minimize_pseudo_energy_nlopt`, tables of method "nlopt") and `local_minima_multistart`.
/// - OpenCASCADE (CAGD_WITH_OPENCASCADE, default ON when found): STEP export, occt-interpolate.
/// Without one of them those functions throw InvalidInput saying which dependency is missing. The
/// reproduction harness and the tests need all of them; the WebAssembly build has none.
#include <string>

namespace cagd {

/// The dependencies that a build of the library may leave out.
enum class OptionalDependency { ceres, nlopt, opencascade };

/// "Ceres", "NLopt" or "OpenCASCADE".
const char* to_string(OptionalDependency d);
/// True when this build of the library has the dependency.
bool built_with(OptionalDependency d);
/// Throws InvalidInput "<who>: needs a cagd library built with <dependency> (…); this one was built
/// without it" unless built_with(d).
void require_built_with(OptionalDependency d, const std::string& who);

}  // namespace cagd
