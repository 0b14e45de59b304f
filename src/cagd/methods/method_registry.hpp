#pragma once
/// @file
/// THE registry of interpolation methods: the one place a method is named. Each entry holds its
/// name, the paper and equations, what it claims (continuity, invariance, dimensions, closed
/// curves, minimum points), its typed parameters (methods/method_parameters.hpp) and the function
/// that builds the curve. `cagd interpolate` (--method, per-method options, --list-methods),
/// `cagd analyze --in`, `cagd compare`, the property tests, the fuzz targets and docs/methods.md's
/// method table all read it; nothing else compares method names.
///
/// The methods themselves, with their papers, parameters and claims, are listed by
/// registry_markdown() (docs/methods.md) and `cagd interpolate --list-methods`; each paper or
/// family registers its methods in one file, `methods/register_<family>.cpp`.
///
/// "C^k in τ": the derivatives of orders ≤ k with respect to the method's own parameter τ agree
/// at every interior data point; on span k (between data points k and k + 1) τ is an affine
/// function of the curve's parameter u with dτ/du = dtau_du[k], so d/dτ = (1/dtau_du[k]) d/du.
/// "G^k": the unit tangent (k ≥ 1) and curvature vector (k = 2) agree. Invariance: every method
/// commutes with translations, rotations and uniform scalings (similarity) except Boost's pchip and
/// makima, which act on x and y separately (translation and scaling only). The pseudo-spline's
/// optimised modes are invariant up to rounding because each decides its ties and its non-convex
/// case against rounding: the exact mode evaluates every breakpoint of its piecewise-linear w, the
/// approximate mode judges its parabola's convexity against 1e-10 of w
/// (fairness/pseudo_spline.hpp). Methods linear in the points with a fixed parameter (cubic-a, the
/// S-/B2-splines, hosaka with unit scale) also commute with every affine map. Claims may depend on
/// the parameter values (Method::claims takes them).
///
/// Boost's interpolants are converted, exactly, into our piecewise cubic Hermite form (values and
/// τ-derivatives at the nodes, times the span's τ-length), so one evaluator serves every curve.
///
/// Configurations: `cagd compare` and the property tests run each method under named parameter
/// values (its presets, e.g. s-spline-m2 = s-spline with m = 2); a method without presets runs
/// under its own name with its defaults, so a new method is compared and tested by itself.
///
/// Preconditions (InvalidInput naming the point): finite coordinates; at least min_points (open) or
/// min_points_closed, at most max_points where a method states it; no two consecutive points equal (closed: also last
/// and first); dimension 2 (or 3 where `max_dimension` allows). A method that does not support closed curves throws
/// when asked for one. Outcomes: the curvature-profile Newton can fail for valid points (returned, not thrown); every
/// other method always returns a curve.
#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/points.hpp"
#include "cagd/methods/method_parameters.hpp"

namespace cagd::methods {

/// Which maps a method commutes with (see above).
enum class Invariance { none, translation_scale, similarity, affine };
/// A phrase for help texts ("similarity (translation, rotation, uniform scaling)", …).
const char* to_string(Invariance i);

/// What a method claims under given parameter values (see above).
struct MethodClaims {
    int parametric_continuity = 0;             ///< k of "C^k in τ" (0: not claimed)
    int geometric_continuity = 0;              ///< k of "G^k" (0: not claimed)
    std::string parameter{};                   ///< what τ is
    Invariance invariance = Invariance::none;  ///< the maps the method commutes with
    bool supports_closed = true;               ///< draws closed curves
    int min_points = 2;                        ///< fewest points of an open curve
    int min_points_closed = 3;                 ///< fewest points of a closed curve
    int max_points = 0;                        ///< most points (0: no limit), where the method's cost forbids more
    int max_dimension = 2;                     ///< 2 or 3
    /// A curve exists for every valid point set. False where the method's equations have no solution
    /// for some points and several for others (Spiro): the outcome is then no_convergence, and the
    /// solution found may depend on the rounding of the input.
    bool always_solves = true;
};

/// A curve from the registry with the parameter of each data point.
struct Interpolant {
    std::shared_ptr<const Curve> curve;   ///< the curve
    std::vector<double> node_parameters;  ///< u of each data point (closed: n + 1 values, the last = t_max)
    std::vector<double> dtau_du;          ///< one per span (see above)
};

/// What an interpolation gives: the outcome, the curve when ok, and what the method reported.
struct InterpolationResult {
    Outcome
        outcome;  ///< ok, or the numerical reason there is no curve (a solver's: Newton, Hosaka's order m, OpenCASCADE)
    std::optional<Interpolant> interpolant;  ///< present when outcome.ok()
    /// What the method reports besides the curve, as (quantity, value) text in the order computed:
    /// the curvature-profile Newton history (`newton_<i>_residual`, `newton_<i>_rank`), equations,
    /// unknowns, rank, and its knot-difference list.
    std::vector<std::pair<std::string, std::string>> report;
    /// Quantities the method computes along the way, by name (the pseudo-spline's length, area
    /// and pseudo-energy from its tables, eq 16–21).
    std::vector<std::pair<std::string, double>> quantities;
    /// A method with a rebuild (Method::rebuild): the solver's final iterate, from which a build on
    /// moved points of the same number may start (interpolate_from); empty otherwise.
    Eigen::VectorXd solver_state;
};

/// A named set of parameter values of a method: a configuration of the comparison.
struct Preset {
    std::string name{};      ///< e.g. "s-spline-m2"
    ParameterText values{};  ///< the parameters' text, as on the command line
};

/// A registered interpolation method (see above).
struct Method {
    std::string name{};                                            ///< the name `--method` takes
    std::vector<std::string> aliases{};                            ///< older names still accepted
    std::string paper{};                                           ///< paper id, or "Boost.Math"
    std::string source{};                                          ///< equations and sections, or the Boost.Math class
    std::string summary{};                                         ///< one line for help texts and docs/methods.md
    std::vector<Parameter> parameters{};                           ///< its typed parameters
    std::function<MethodClaims(const ParameterValues&)> claims{};  ///< what it claims, given the parameter values
    /// Builds the curve through points already checked against the claims (ValidPoints: the points,
    /// whether the curve is closed, and the proof that they passed require_valid_points with the
    /// claims' least number of points, so that the constructions it calls need not check them again).
    std::function<InterpolationResult(const ValidPoints& points, const ParameterValues&)> build{};
    std::vector<Preset> presets{};  ///< the comparison's configurations; none: the defaults, by name
    /// Builds by an iterative nonlinear solve, several times the cost of the direct methods on long
    /// inputs: a parallel comparison starts these first so that they do not finish last alone.
    bool iterative = false;
    /// Loads what the method's builds share (the pseudo-spline's tables), given the points'
    /// dimension: a timing of one build (compare's `seconds`) then excludes it. Empty for methods
    /// that share nothing.
    std::function<void(const ParameterValues&, int dimension)> prepare{};
    /// Builds as `build` does, but with the iterative solve started from `start`, the solver_state
    /// of a build on nearby points of the same number (continuation: the locality footprint's moved
    /// point, a drag). The result meets the same tolerance as a build's, on the solution branch of
    /// the start. Empty for the direct methods (interpolate_from then builds).
    std::function<InterpolationResult(const ValidPoints& points, const ParameterValues&, const Eigen::VectorXd& start)>
        rebuild{};
};

/// Every method, in the order of the tables.
const std::vector<Method>& registry();
/// By name or alias; throws InvalidInput listing the known names.
const Method& find_method(const std::string& name);
std::vector<std::string> method_names();  ///< names and aliases, for a command line's choices

/// Why a method with these claims does not take the points (open or closed): "open curves only",
/// "needs at least 4 points", "takes at most 2000 points", "planar points only", or "" when it
/// does. The one check of the claims: interpolate() throws it as InvalidInput, and compare reports
/// the method as not applicable with it.
std::string method_applicability(const MethodClaims& claims, const PointList& points, bool closed);
/// interpolate()'s name for messages about `method`: "cagd::methods::interpolate(<name>)".
std::string interpolate_who(const Method& method);
/// Checks the points against the method's claims (method_applicability), then the points
/// themselves (finiteness, coincident neighbours), then builds the curve.
InterpolationResult interpolate(const Method& method, const PointList& points, bool closed,
                                const ParameterValues& values);
/// By method or preset name ("s-spline-m2"); `values` add to, or override, a preset's.
InterpolationResult interpolate(const std::string& name, const PointList& points, bool closed,
                                const ParameterText& values = {});

/// A method under named parameter values (a preset, or the method's defaults under its name).
struct Configuration {
    std::string name;                ///< the preset's name, or the method's
    const Method* method = nullptr;  ///< the method
    ParameterValues values;          ///< the parameter values
    MethodClaims claims;             ///< the method's claims under them
};
/// Every configuration, in registry order: a method's presets, or the method itself.
const std::vector<Configuration>& configurations();
/// A configuration by name; a method name without a configuration of that name gives the method
/// with its defaults. Throws InvalidInput listing the configurations.
Configuration find_configuration(const std::string& name);
/// The same with some parameter values changed: `overrides` replace or add to the configuration's
/// own (a preset's, or the defaults); the name stays. Throws InvalidInput as parse_parameter_values
/// for an unknown parameter or a bad value.
Configuration find_configuration(const std::string& name, const ParameterText& overrides);
/// interpolate() under the configuration's method and values.
InterpolationResult interpolate(const Configuration& configuration, const PointList& points, bool closed);
/// interpolate() on points near earlier ones: `start` is the solver_state of a result of the same
/// configuration on as many points, open or closed alike. A method with a rebuild starts its solve
/// from it (fewer Newton iterations when the points moved a little); any other method, or an empty
/// start, builds anew. The same checks.
InterpolationResult interpolate_from(const Configuration& configuration, const PointList& points, bool closed,
                                     const Eigen::VectorXd& start);
/// interpolate_from on points validated already, closed as they were validated (compare validates
/// them once for all its configurations): the claims checked, then the build; the same result as
/// from the PointList. An empty start builds anew.
InterpolationResult interpolate_from(const Configuration& configuration, const ValidPoints& points,
                                     const Eigen::VectorXd& start = Eigen::VectorXd());

/// The registry as a Markdown table (docs/methods.md) or as plain lines (`cagd interpolate --list-methods`).
std::string registry_markdown();
/// The registry as plain lines (`cagd interpolate --list-methods`).
std::string registry_listing();

}  // namespace cagd::methods
