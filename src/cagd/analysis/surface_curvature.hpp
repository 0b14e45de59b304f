#pragma once
/// @file
/// Gaussian and mean curvature of a parametric surface S(u, v) from its derivatives to 2nd order
/// (typical_curves Fig. 6; any textbook, e.g. do Carmo §3.3):
///   E = S_u·S_u, F = S_u·S_v, G = S_v·S_v;  N = S_u × S_v / |S_u × S_v|;
///   L = S_uu·N, M = S_uv·N, N_ = S_vv·N;
///   K = (L N_ − M²)/(EG − F²),   H = (E N_ − 2F M + G L)/(2(EG − F²)).
/// H is signed with the normal S_u × S_v (H > 0 where the surface bends towards N); K does not
/// depend on the orientation. EG − F² = |S_u × S_v|².
/// surface_curvatures_weingarten: the same from S_u, S_v and the derivatives N_u, N_v of the unit
/// normal (Weingarten: L = −S_u·N_u, M = −S_u·N_v, N_ = −S_v·N_v) — a second route, used with N_u,
/// N_v by differences of unit_normal to check the second-derivative route.
/// Precondition (InvalidInput): a regular point, |S_u × S_v| > 0 (relative to |S_u||S_v|, 1e-14).
#include <Eigen/Dense>

namespace cagd::analysis {

/// S and its derivatives to second order at one (u, v).
struct SurfaceJet2 {
    Eigen::Vector3d s;    ///< S
    Eigen::Vector3d su;   ///< S_u
    Eigen::Vector3d sv;   ///< S_v
    Eigen::Vector3d suu;  ///< S_uu
    Eigen::Vector3d suv;  ///< S_uv
    Eigen::Vector3d svv;  ///< S_vv
};

/// Gaussian and mean curvature at a point.
struct SurfaceCurvatures {
    double gaussian = 0.0;  ///< K
    double mean = 0.0;      ///< H, signed with S_u × S_v
};

/// K and H from the second-derivative route above.
SurfaceCurvatures surface_curvatures(const SurfaceJet2& jet);
/// K and H by Weingarten's equations from S_u, S_v and the unit normal's derivatives N_u, N_v.
SurfaceCurvatures surface_curvatures_weingarten(const Eigen::Vector3d& su, const Eigen::Vector3d& sv,
                                                const Eigen::Vector3d& nu, const Eigen::Vector3d& nv);
Eigen::Vector3d unit_normal(const SurfaceJet2& jet);  ///< S_u × S_v / |S_u × S_v|

}  // namespace cagd::analysis
