#include "cagd/export/step_writer.hpp"

#if CAGD_WITH_OPENCASCADE
#include "cagd/core/detail/opencascade_plugin.hpp"
#endif

namespace cagd::exports {

#if CAGD_WITH_OPENCASCADE
bool step_available() { return true; }

// OpenCASCADE is loaded on the first write (core/detail/opencascade_plugin.hpp); it writes through a
// temporary file, and the text it wrote is copied to `out`.
Outcome write_step(std::ostream& out, const BSplineCurve& curve) {
    const cagd::detail::OpenCascadePlugin& occt = cagd::detail::opencascade_plugin("cagd::exports::write_step");
    const cagd::detail::OpenCascadeBSpline c{
        .degree = curve.degree(), .knots = curve.knots(), .poles = curve.control_points()};
    std::string step, message;
    if (!occt.step_curve(c, step, message)) return {Status::no_solution, message};
    out << step;
    return {};
}

Outcome write_step(std::ostream& out, const BSplineSurface& surface) {
    const char* who = "cagd::exports::write_step";
    const cagd::detail::OpenCascadePlugin& occt = cagd::detail::opencascade_plugin(who);
    if (surface.degree_u > occt.max_surface_degree || surface.degree_v > occt.max_surface_degree)
        fail_input(who, "a surface of degree " + std::to_string(surface.degree_u) + " x " +
                            std::to_string(surface.degree_v) + "; OpenCASCADE's B-spline surfaces take degree <= " +
                            std::to_string(occt.max_surface_degree) + " (json takes any degree)");
    std::string step, message;
    if (!occt.step_surface(surface.degree_u, surface.degree_v, surface.knots_u, surface.knots_v, surface.control[0],
                           surface.control[1], surface.control[2], step, message))
        return {Status::no_solution, message};
    out << step;
    return {};
}
#else
bool step_available() { return false; }

Outcome write_step(std::ostream&, const BSplineCurve&) {
    fail_input("cagd::exports::write_step",
               "STEP needs a cagd library built with OpenCASCADE (Debian libocct-data-exchange-dev); this one was "
               "built without it");
}

Outcome write_step(std::ostream&, const BSplineSurface&) {
    fail_input("cagd::exports::write_step",
               "STEP needs a cagd library built with OpenCASCADE (Debian libocct-data-exchange-dev); this one was "
               "built without it");
}
#endif

}  // namespace cagd::exports
