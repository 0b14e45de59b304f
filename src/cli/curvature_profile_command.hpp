#pragma once
// `cagd interpolate --method curvature-profile` (curvature_profile): the Newton design of sections
// 2–4 on the user's points; main.cpp parses the options and calls run_curvature_profile.
#include <string>

#include "core/points.hpp"

namespace cagd::cli {

struct CurvatureProfileArgs {
    std::string spans;   // "line,free,arc,…" (one per span); empty: all free
    std::string knots;   // a knot-difference list; empty: the span layout (degree 2)
    int degree = 2;      // of ψ, for --knots
    bool degree_given = false, closed = false;
    int samples = 16;
    std::string out;
};

// Prints the converged knot-difference list and the Newton history on stdout; returns 0, or 1 with
// the outcome's message on stderr when no curve exists or Newton does not converge. Bad input throws.
int run_curvature_profile(const PointList& points, const CurvatureProfileArgs& args);

}  // namespace cagd::cli
