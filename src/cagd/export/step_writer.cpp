#include "cagd/export/step_writer.hpp"

#if CAGD_WITH_OPENCASCADE
#include <filesystem>
#include <fstream>

#include "cagd/core/detail/opencascade_plugin.hpp"
#include "cagd/io/temporary_file.hpp"
#endif

namespace cagd::exports {

#if CAGD_WITH_OPENCASCADE
bool step_available() { return true; }

namespace {
// OpenCASCADE (loaded on the first write: core/detail/opencascade_plugin.hpp) writes only to paths:
// it writes a registered temporary file (io/temporary_file.hpp: a signal removes it), whose bytes
// are then streamed to `out`; the text is never held in memory.
template <class Write>
Outcome step_through_file(std::ostream& out, const char* who, Write write) {
    const TemporaryFile file((std::filesystem::temp_directory_path() / "cagd-step-").string(), who);
    std::string message;
    if (!write(file.path().c_str(), message)) return {Status::no_solution, message};
    std::ifstream in(file.path(), std::ios::binary);
    if (!(in && out << in.rdbuf()) || in.bad())
        return {Status::no_solution, std::string("OpenCASCADE's STEP file could not be read back from ") + file.path()};
    return {};
}
}  // namespace

Outcome write_step(std::ostream& out, const BSplineCurve& curve) {
    const char* who = "cagd::exports::write_step";
    if (curve.control_points().rows() > kMaxStepControlPoints)
        fail_input(who, "the curve has " + std::to_string(curve.control_points().rows()) +
                            " control points; STEP takes at most " + std::to_string(kMaxStepControlPoints) +
                            " (OpenCASCADE holds its whole model in memory): write JSON, SVG or DXF");
    const cagd::detail::OpenCascadePlugin& occt = cagd::detail::opencascade_plugin(who);
    const cagd::detail::OpenCascadeBSpline c{
        .degree = curve.degree(), .knots = curve.knots(), .poles = curve.control_points()};
    return step_through_file(out, who,
                             [&](const char* path, std::string& message) { return occt.step_curve(c, path, message); });
}

int step_max_surface_degree() {
    return cagd::detail::opencascade_plugin("cagd::exports::step_max_surface_degree").max_surface_degree;
}

Outcome write_step(std::ostream& out, const BSplineSurface& surface) {
    const char* who = "cagd::exports::write_step";
    const cagd::detail::OpenCascadePlugin& occt = cagd::detail::opencascade_plugin(who);
    if (surface.degree_u > occt.max_surface_degree || surface.degree_v > occt.max_surface_degree)
        fail_input(who, "a surface of degree " + std::to_string(surface.degree_u) + " x " +
                            std::to_string(surface.degree_v) + "; OpenCASCADE's B-spline surfaces take degree <= " +
                            std::to_string(occt.max_surface_degree) + " (json takes any degree)");
    return step_through_file(out, who, [&](const char* path, std::string& message) {
        return occt.step_surface(surface.degree_u, surface.degree_v, surface.knots_u, surface.knots_v,
                                 surface.control[0], surface.control[1], surface.control[2], path, message);
    });
}
#else
bool step_available() { return false; }

int step_max_surface_degree() {
    fail_input("cagd::exports::step_max_surface_degree",
               "STEP needs a cagd library built with OpenCASCADE (Debian libocct-data-exchange-dev); this one was "
               "built without it");
}

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
