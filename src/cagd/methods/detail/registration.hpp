#pragma once
// What the registration files share (not installed: only the methods/ .cpp files include it).
//
// The registry (methods/method_registry.hpp) is assembled from one registration file per paper or
// family, each a function returning its methods in the order of the tables:
//   register_pseudo_energy.cpp      pseudo-spline, cubic-a, cubic-b, hermite-a, hermite-b
//   register_sb2_locality.cpp       s-spline, b2-spline
//   register_hosaka.cpp             hosaka
//   register_curvature_profile.cpp  curvature-profile, spiro (its degree-4 member; a peer)
//   register_boost_math.cpp         boost-pchip, boost-makima, boost-catmull-rom (peers)
//   register_eigen.cpp              eigen-spline (a peer; at most 2,000 points)
//   register_opencascade.cpp        occt-interpolate (a peer; only with OpenCASCADE)
// A new method of an existing family is one entry in its file; a new family is a new file and one
// name in registry() (method_registry.cpp). Helpers for the builders follow.
#include <Eigen/Dense>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/core/points.hpp"
#include "cagd/methods/method_parameters.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::methods::detail {

std::vector<Method> pseudo_energy_methods();
std::vector<Method> sb2_locality_methods();
std::vector<Method> hosaka_methods();
std::vector<Method> curvature_profile_methods();
std::vector<Method> boost_math_methods();
std::vector<Method> eigen_methods();
std::vector<Method> opencascade_methods();  // empty in a library built without OpenCASCADE

using P = ParameterType;

// A curve whose data points sit at u = 0, 1, …, nodes − 1, with dτ/du per span: the form in which
// the builders hand their curves to the registry.
inline Interpolant unit_span_interpolant(std::shared_ptr<const Curve> curve, Eigen::Index nodes,
                                         std::vector<double> dtau_du) {
    std::vector<double> u(static_cast<std::size_t>(nodes));
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = static_cast<double>(i);
    return {std::move(curve), std::move(u), std::move(dtau_du)};
}

// Data points (closed: n + 1, the first repeated at the end).
inline Eigen::Index node_count(const PointList& p, bool closed) { return closed ? p.rows() + 1 : p.rows(); }

// dτ/du = 1 on every span: the curve's parameter is its own τ.
inline std::vector<double> unit_lengths(const PointList& p, bool closed) {
    return std::vector<double>(static_cast<std::size_t>(node_count(p, closed) - 1), 1.0);
}

inline InterpolationResult result_of(Interpolant i) {
    InterpolationResult r;
    r.interpolant = std::move(i);
    return r;
}

// Claims that do not depend on the parameter values.
inline std::function<MethodClaims(const ParameterValues&)> fixed(MethodClaims c) {
    return [c](const ParameterValues&) { return c; };
}

// End tangents shared by the S-/B2-splines and hosaka: given only with --end tangent, then both.
std::vector<Parameter> tangent_parameters();
// Throws InvalidInput naming `who` unless both tangents are given exactly when --end is tangent.
void require_tangent_pair(const std::string& who, const ParameterValues& v);

}  // namespace cagd::methods::detail
