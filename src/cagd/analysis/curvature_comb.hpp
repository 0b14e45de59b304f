#pragma once
/// @file
/// The curvature comb of a planar curve: at sample points r_j a tooth from r_j to
///     r_j − c κ_j n_j,
/// n_j the left unit normal and κ_j the signed curvature (so a tooth points away from the centre of
/// curvature), with one length factor c for the whole comb. The default c draws the 95th percentile
/// of |κ| as 10 % of a length scale (the data's bounding-box diagonal): a spike shows as a long
/// tooth without flattening the rest. `cagd compare`'s figures and the SVG export use this rule.
#include <vector>

namespace cagd::analysis {

/// The fraction of the diagonal that the 95th percentile of |κ| draws.
inline constexpr double kCombPercentileLength = 0.1;

/// c for curvatures `kappa` (signed or not) and length scale `diagonal`; 0 when every κ is 0 or
/// there is none.
double comb_scale(std::vector<double> kappa, double diagonal);

}  // namespace cagd::analysis
