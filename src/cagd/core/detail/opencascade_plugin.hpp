#pragma once
// OpenCASCADE behind a plugin: the library's calls into OpenCASCADE (GeomAPI_Interpolate for the
// occt-interpolate peer, STEPControl_Writer for STEP export) live in a separate shared object,
// libcagd_occt.so (src/occt_plugin/), which the library loads with dlopen the first time one of
// them is needed. A program that never interpolates with OpenCASCADE nor writes STEP never loads
// OpenCASCADE's fourteen shared libraries, whose relocation and static initialisation every process
// would otherwise pay at start-up.
//
// The plugin is searched for, first match wins (each must report kOpenCascadePluginInterface):
//   1. the file named by the environment variable CAGD_OCCT_PLUGIN;
//   2. libcagd_occt.so beside the binary that contains the library (the cagd command in a build
//      tree, the Python module in its package);
//   3. <that binary's folder>/../<libdir>/cagd/libcagd_occt.so (an installed, relocated prefix);
//   4. the install path and 5. the build tree's path, both fixed when the library was built.
// Not found, or found from another build: InvalidInput naming every place looked at.
//
// Only types of the standard library and Eigen cross the boundary, and no exception: the plugin
// catches OpenCASCADE's and returns false with the message. Both sides are compiled by the same
// build (the interface string carries the library's version and the layout's revision).
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cagd::detail {

#ifdef CAGD_LIBRARY_VERSION  // defined by the build for the library's and the plugin's own sources
/// What both sides must agree on; a plugin reporting anything else is not loaded.
inline constexpr const char* kOpenCascadePluginInterface = "cagd-occt-plugin 4 " CAGD_LIBRARY_VERSION;
#endif

/// A B-spline in OpenCASCADE's terms: degree, the full knot vector (values repeated by
/// multiplicity, clamped), poles one per row (x, y[, z]).
struct OpenCascadeBSpline {
    int degree = 0;
    std::vector<double> knots;
    Eigen::MatrixXd poles;
};

/// The plugin's entry points (all thread-safe; the STEP writers serialise on a mutex of their own,
/// since OpenCASCADE's interface parameters are process-wide).
struct OpenCascadePlugin {
    const char* interface = nullptr;  ///< kOpenCascadePluginInterface of the plugin's build
    /// GeomAPI_Interpolate through the rows of `points` (3 columns; 2 columns: Geom2dAPI_Interpolate,
    /// the same curve bit for bit as with z = 0) mapped to (point − centre) / scale (`centre` has a coordinate per
    /// column), periodic when `closed`, mapped points closer than `tolerance` coincident; the curve is mapped back
    /// (knots · scale, poles · scale + centre) and a periodic one returned in its clamped form (SetNotPeriodic). The
    /// maps are done here, point by point, so that neither side holds a mapped copy of every point. False with
    /// `message` when OpenCASCADE fails.
    bool (*interpolate)(const Eigen::MatrixXd& points, const Eigen::RowVectorXd& centre, double scale, bool closed,
                        double tolerance, OpenCascadeBSpline& curve, std::string& message) = nullptr;
    /// Writes the STEP (AP214) file of one edge on the curve to `path` (OpenCASCADE writes only to
    /// paths: the caller's registered temporary file); false with `message` when OpenCASCADE fails.
    bool (*step_curve)(const OpenCascadeBSpline& curve, const char* path, std::string& message) = nullptr;
    /// The same for one face on the B-spline surface of degrees (du, dv), knot vectors ku, kv and
    /// control coordinates x, y, z (each nu × nv).
    bool (*step_surface)(int du, int dv, const std::vector<double>& ku, const std::vector<double>& kv,
                         const Eigen::MatrixXd& x, const Eigen::MatrixXd& y, const Eigen::MatrixXd& z, const char* path,
                         std::string& message) = nullptr;
    int max_surface_degree = 0;  ///< Geom_BSplineSurface::MaxDegree()
};

/// The plugin, loaded on the first call (see above); InvalidInput naming `who` and the places
/// looked at when it cannot be loaded. Only in a library built with OpenCASCADE.
const OpenCascadePlugin& opencascade_plugin(const std::string& who);

}  // namespace cagd::detail

/// The plugin's one exported symbol (extern "C", so that dlsym finds it by this name).
extern "C" const cagd::detail::OpenCascadePlugin* cagd_opencascade_plugin();
