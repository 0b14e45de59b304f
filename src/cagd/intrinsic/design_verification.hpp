#pragma once
/// @file
/// Independent checks of a designed curve (curvature_profile, "claims beyond the figures"): they use
/// the B-spline (de Boor) evaluation of ψ and Boost.Math's adaptive Gauss–Kronrod quadrature
/// (31 points, relative tolerance 1e−14 on (cos ψ + 2, sin ψ + 2)), not the Bézier form and Gauss–Legendre rule the
/// solver uses.
///   interpolation_error   max_i |r(s_i) − P_i| with r(s_i) = P_0 + Σ ∫ (cos ψ, sin ψ) ds
///                         accumulated span by span (closed: also the return to P_0);
///   line_curvature        max |κ| at 20 interior samples of every line segment;
///   arc_curvature_spread  max |κ − κ(mid)| at the same samples of every arc segment;
///   angle_jump            max |ψ(w_g^+) − ψ(w_g^−)| over interior breakpoints (G1 everywhere);
///   g2_curvature_jump     max |κ(w_g^+) − κ(w_g^−)| over breakpoints of continuity ≥ G2;
///   g1_curvature_jump     max |κ(w_g^+) − κ(w_g^−)| over G1 breakpoints (may be large: κ may jump);
///   closing_angle, closing_curvature   ψ(L) − ψ(0) − 2π·turns and κ(L) − κ(0) (closed; else 0).
#include "cagd/intrinsic/curvature_profile_design.hpp"

namespace cagd::intrinsic {

/// The checks above, each a largest deviation (0 where it does not apply).
struct DesignVerification {
    double interpolation_error = 0;   ///< max_i |r(s_i) − P_i|
    double line_curvature = 0;        ///< max |κ| on line segments
    double arc_curvature_spread = 0;  ///< max |κ − κ(mid)| on arc segments
    double angle_jump = 0;            ///< max |ψ jump| at interior breakpoints
    double g2_curvature_jump = 0;     ///< max |κ jump| at breakpoints of continuity ≥ G2
    double g1_curvature_jump = 0;     ///< max |κ jump| at G1 breakpoints (κ may jump there)
    double closing_angle = 0;         ///< closed: ψ(L) − ψ(0) − 2π·turns
    double closing_curvature = 0;     ///< closed: κ(L) − κ(0)
};

/// The checks of a solution of `problem`, computed independently of the solver.
DesignVerification verify_design(const CurvatureProfileProblem& problem, const IntrinsicCurve& curve);

}  // namespace cagd::intrinsic
