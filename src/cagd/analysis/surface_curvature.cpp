#include "cagd/analysis/surface_curvature.hpp"

#include "cagd/core/errors.hpp"

namespace cagd::analysis {

namespace {

double regular_area(const Eigen::Vector3d& su, const Eigen::Vector3d& sv) {
    const double area = su.cross(sv).norm();
    if (!(area > 1e-14 * su.norm() * sv.norm()) || !std::isfinite(area))
        fail_input("cagd::analysis::surface_curvatures",
                   "singular surface point: |S_u x S_v| = " + full_precision(area) +
                       " (|S_u| = " + full_precision(su.norm()) + ", |S_v| = " + full_precision(sv.norm()) + ")");
    return area;
}

SurfaceCurvatures from_fundamental_forms(const Eigen::Vector3d& su, const Eigen::Vector3d& sv, double l, double m,
                                         double nn) {
    const double area = su.cross(sv).norm();
    const double e = su.dot(su), f = su.dot(sv), g = sv.dot(sv), det = area * area;
    return {(l * nn - m * m) / det, (e * nn - 2.0 * f * m + g * l) / (2.0 * det)};
}

}  // namespace

Eigen::Vector3d unit_normal(const SurfaceJet2& j) { return j.su.cross(j.sv) / regular_area(j.su, j.sv); }

SurfaceCurvatures surface_curvatures(const SurfaceJet2& j) {
    const Eigen::Vector3d n = unit_normal(j);
    return from_fundamental_forms(j.su, j.sv, j.suu.dot(n), j.suv.dot(n), j.svv.dot(n));
}

SurfaceCurvatures surface_curvatures_weingarten(const Eigen::Vector3d& su, const Eigen::Vector3d& sv,
                                                const Eigen::Vector3d& nu, const Eigen::Vector3d& nv) {
    regular_area(su, sv);
    return from_fundamental_forms(su, sv, -su.dot(nu), -su.dot(nv), -sv.dot(nv));
}

}  // namespace cagd::analysis
