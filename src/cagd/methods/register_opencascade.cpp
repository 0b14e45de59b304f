// OpenCASCADE's GeomAPI_Interpolate as a peer: the interpolating B-spline that CAD users get from
// FreeCAD, CadQuery and build123d. Registered only in a library built with OpenCASCADE, which
// it loads through its plugin on the first use (core/detail/opencascade_plugin.hpp).
//
// What it computes (measured here: tests/methods/test_opencascade_peer.cpp): chord-length
// parameters from 0, a B-spline of degree min(3, n − 1) with a knot at every parameter. Open n ≥ 4:
// simple knots, n + 2 poles (two end conditions of OpenCASCADE's own), C2 at every interior point.
// Closed: OpenCASCADE's periodic B-spline, simple knots except a double knot at the closing point,
// so C2 at the interior points and only C1 where the curve closes (its documentation says periodic
// interpolation is C1). The periodic curve is converted to its clamped form by OpenCASCADE itself
// (SetNotPeriodic, exact knot insertion), then copied knot for knot and pole for pole.
//
// The points are moved to their bounding box's centre and scaled to unit diagonal first, and the
// poles and knots scaled back: OpenCASCADE's coincidence test is absolute (its Tolerance), so the
// peer then treats small and large data alike, and the curve commutes with similarities as its
// chord-length parameter does.
#include "cagd/methods/detail/registration.hpp"

#if CAGD_WITH_OPENCASCADE
#include <string>
#include <utility>

#include "cagd/core/detail/opencascade_plugin.hpp"
#include "cagd/spline/bspline.hpp"
#endif

namespace cagd::methods::detail {

#if CAGD_WITH_OPENCASCADE
namespace {

// Points closer than this (after scaling to unit diagonal) are coincident for OpenCASCADE; the
// registry has already refused equal consecutive points.
constexpr double kOpenCascadeCoincidence = 1e-13;

InterpolationResult opencascade_interpolant(const PointList& p, bool closed) {
    // OpenCASCADE itself is loaded here, on the first use (core/detail/opencascade_plugin.hpp).
    const cagd::detail::OpenCascadePlugin& occt = cagd::detail::opencascade_plugin("occt-interpolate");
    const Eigen::RowVectorXd lo = p.colwise().minCoeff(), hi = p.colwise().maxCoeff();
    const Eigen::RowVectorXd centre = 0.5 * (lo + hi);
    const double scale = (hi - lo).norm();
    InterpolationResult r;
    // OpenCASCADE interpolates the points mapped to a unit diagonal about the box's centre, and
    // maps its curve back (knots · scale, poles · scale + centre).
    cagd::detail::OpenCascadeBSpline curve;
    if (!occt.interpolate(p, centre, scale, closed, kOpenCascadeCoincidence, curve, r.outcome.message)) {
        r.outcome.status = Status::no_solution;
        return r;
    }
    auto spline = std::make_shared<BSplineCurve>(curve.degree, std::move(curve.knots), std::move(curve.poles));
    // OpenCASCADE puts a knot at every point's chord-length parameter, summed from the scaled points:
    // the node parameters are the distinct knots of the curve's domain [t_min, t_max] themselves, so
    // that the first and last node are the domain's ends to the bit (a chord-length sum of our own
    // differs from OpenCASCADE's by rounding that grows with n: 1.6e-7 at 10^5 points, more than
    // the shortest chord when chords vary 10^6-fold). The clamped form of a closed, periodic curve
    // has further knots beyond its domain.
    Interpolant in;
    const Eigen::Index nodes = node_count(p, closed);
    in.node_parameters.reserve(static_cast<std::size_t>(nodes));
    for (double k : spline->knots())
        if (k >= spline->t_min() && k <= spline->t_max() &&
            (in.node_parameters.empty() || k != in.node_parameters.back()))
            in.node_parameters.push_back(k);
    if (std::cmp_not_equal(in.node_parameters.size(), nodes)) {
        r.outcome = {Status::no_solution, "OpenCASCADE's curve has " + std::to_string(in.node_parameters.size()) +
                                              " distinct knots on its domain for " + std::to_string(nodes) +
                                              " points (it took some points as coincident)"};
        return r;
    }
    in.dtau_du = unit_lengths(p, closed);
    in.curve = std::move(spline);
    return result_of(std::move(in));
}

}  // namespace

std::vector<Method> opencascade_methods() {
    return {{
        .name = "occt-interpolate",
        .paper = "OpenCASCADE",
        .source = "GeomAPI_Interpolate, chord length; periodic for closed curves",
        .summary = "OpenCASCADE's interpolating cubic B-spline, as FreeCAD and CadQuery build it (a peer; closed: C1 "
                   "where it closes)",
        .claims = fixed({.parametric_continuity = 1,
                         .parameter = "chord length",
                         .invariance = Invariance::similarity,
                         .min_points = 2,
                         .min_points_closed = 3,
                         .max_dimension = 3}),
        .build = [](const ValidPoints& p,
                    const ParameterValues&) { return opencascade_interpolant(p.points(), p.closed()); },
    }};
}
#else
std::vector<Method> opencascade_methods() { return {}; }
#endif

}  // namespace cagd::methods::detail
