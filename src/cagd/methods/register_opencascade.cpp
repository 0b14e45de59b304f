// OpenCASCADE's GeomAPI_Interpolate as a peer: the interpolating B-spline that CAD users get from
// FreeCAD, CadQuery and build123d. Registered only in a library built with OpenCASCADE.
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
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_HArray1OfPnt.hxx>

#include <algorithm>
#include <cmath>

#include "cagd/spline/bspline.hpp"
#endif

namespace cagd::methods::detail {

#if CAGD_WITH_OPENCASCADE
namespace {

// Points closer than this (after scaling to unit diagonal) are coincident for OpenCASCADE; the
// registry has already refused equal consecutive points.
constexpr double kOpenCascadeCoincidence = 1e-13;

InterpolationResult opencascade_interpolant(const PointList& p, bool closed) {
    const Eigen::Index n = p.rows(), dim = p.cols();
    const Eigen::RowVectorXd lo = p.colwise().minCoeff(), hi = p.colwise().maxCoeff();
    const Eigen::RowVectorXd centre = 0.5 * (lo + hi);
    const double scale = (hi - lo).norm();
    InterpolationResult r;
    try {
        Message::DefaultMessenger()->ChangePrinters().Clear();
        Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, static_cast<int>(n));
        for (Eigen::Index i = 0; i < n; ++i) {
            const Eigen::RowVectorXd q = (p.row(i) - centre) / scale;
            points->SetValue(static_cast<int>(i) + 1, gp_Pnt(q(0), q(1), dim > 2 ? q(2) : 0.0));
        }
        GeomAPI_Interpolate interpolate(points, closed, kOpenCascadeCoincidence);
        interpolate.Perform();
        if (!interpolate.IsDone()) {
            r.outcome = {Status::no_solution, "OpenCASCADE's GeomAPI_Interpolate did not find a curve"};
            return r;
        }
        Handle(Geom_BSplineCurve) curve = Handle(Geom_BSplineCurve)::DownCast(interpolate.Curve()->Copy());
        if (curve->IsPeriodic()) curve->SetNotPeriodic();
        std::vector<double> knots;
        for (int k = 1; k <= curve->NbKnots(); ++k) knots.insert(knots.end(), static_cast<std::size_t>(curve->Multiplicity(k)), curve->Knot(k) * scale);
        Eigen::MatrixXd poles(curve->NbPoles(), dim);
        for (int i = 1; i <= curve->NbPoles(); ++i) {
            const gp_Pnt q = curve->Pole(i);
            const double xyz[3] = {q.X(), q.Y(), q.Z()};
            for (Eigen::Index c = 0; c < dim; ++c) poles(i - 1, c) = centre(c) + scale * xyz[c];
        }
        // The chord-length parameters, each snapped onto the knot OpenCASCADE put there (they
        // differ by rounding; the curve's pieces start at the knots).
        Interpolant in;
        in.node_parameters.push_back(0.0);
        for (Eigen::Index i = 1; i < node_count(p, closed); ++i) in.node_parameters.push_back(in.node_parameters.back() + (p.row(i % n) - p.row(i - 1)).norm());
        // Both ascend: one merged walk, O(n).
        auto knot = knots.begin();
        for (double& u : in.node_parameters) {
            knot = std::lower_bound(knot, knots.end(), u);
            for (auto k : {knot == knots.begin() ? knot : knot - 1, knot == knots.end() ? knot - 1 : knot})
                if (std::abs(*k - u) <= 1e-12 * knots.back()) {
                    u = *k;
                    break;
                }
        }
        in.dtau_du = unit_lengths(p, closed);
        in.curve = std::make_shared<BSplineCurve>(curve->Degree(), std::move(knots), std::move(poles));
        return result_of(std::move(in));
    } catch (const Standard_Failure& e) {
        r.outcome = {Status::no_solution, std::string("OpenCASCADE's GeomAPI_Interpolate: ") + e.GetMessageString()};
        return r;
    }
}

}  // namespace

std::vector<Method> opencascade_methods() {
    return {{
        .name = "occt-interpolate",
        .paper = "OpenCASCADE",
        .source = "GeomAPI_Interpolate, chord length; periodic for closed curves",
        .summary = "OpenCASCADE's interpolating cubic B-spline, as FreeCAD and CadQuery build it (a peer; closed: C1 where it closes)",
        .claims = fixed({.parametric_continuity = 1,
                         .parameter = "chord length",
                         .invariance = Invariance::similarity,
                         .min_points = 2,
                         .min_points_closed = 3,
                         .max_dimension = 3}),
        .build = [](const PointList& p, bool closed, const ParameterValues&) { return opencascade_interpolant(p, closed); },
    }};
}
#else
std::vector<Method> opencascade_methods() { return {}; }
#endif

}  // namespace cagd::methods::detail
