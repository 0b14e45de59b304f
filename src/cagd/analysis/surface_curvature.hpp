#pragma once
// Gaussian and mean curvature of a parametric surface S(u, v) from its derivatives to 2nd order
// (typical_curves Fig. 6; any textbook, e.g. do Carmo §3.3):
//   E = S_u·S_u, F = S_u·S_v, G = S_v·S_v;  N = S_u × S_v / |S_u × S_v|;
//   L = S_uu·N, M = S_uv·N, N_ = S_vv·N;
//   K = (L N_ − M²)/(EG − F²),   H = (E N_ − 2F M + G L)/(2(EG − F²)).
// H is signed with the normal S_u × S_v (H > 0 where the surface bends towards N); K does not
// depend on the orientation. EG − F² = |S_u × S_v|².
// surface_curvatures_weingarten: the same from S_u, S_v and the derivatives N_u, N_v of the unit
// normal (Weingarten: L = −S_u·N_u, M = −S_u·N_v, N_ = −S_v·N_v) — a second route, used with N_u,
// N_v by differences of unit_normal to check the second-derivative route.
// Precondition (InvalidInput): a regular point, |S_u × S_v| > 0 (relative to |S_u||S_v|, 1e-14).
#include <Eigen/Dense>

namespace cagd::analysis {

struct SurfaceJet2 {
    Eigen::Vector3d s, su, sv, suu, suv, svv;
};

struct SurfaceCurvatures {
    double gaussian = 0.0, mean = 0.0;
};

SurfaceCurvatures surface_curvatures(const SurfaceJet2& jet);
SurfaceCurvatures surface_curvatures_weingarten(const Eigen::Vector3d& su, const Eigen::Vector3d& sv, const Eigen::Vector3d& nu, const Eigen::Vector3d& nv);
Eigen::Vector3d unit_normal(const SurfaceJet2& jet);  // S_u × S_v / |S_u × S_v|

}  // namespace cagd::analysis
