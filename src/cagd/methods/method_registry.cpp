#include "cagd/methods/method_registry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cagd/methods/detail/registration.hpp"

namespace cagd::methods {

namespace detail {

std::vector<Parameter> tangent_parameters() {
    return {
        {.name = "start-tangent",
         .type = P::vector,
         .help =
             "derivative at the first point with respect to the method's parameter t, e.g. 1,0 (with --end tangent)"},
        {.name = "end-tangent",
         .type = P::vector,
         .help = "derivative at the last point with respect to t (with --end tangent)"}};
}

void require_tangent_pair(const std::string& who, const ParameterValues& v) {
    const bool tangent_end = v.text("end") == "tangent";
    for (const char* name : {"start-tangent", "end-tangent"}) {
        if (tangent_end && !v.has(name)) fail_input(who, "--end tangent needs --start-tangent and --end-tangent");
        if (!tangent_end && v.has(name))
            fail_input(who, std::string("--") + name + " applies with --end tangent only, the end is " + v.text("end"));
    }
}

}  // namespace detail

const std::vector<Method>& registry() {
    // The families in the order of the tables: one registration file each (detail/registration.hpp).
    static const std::vector<Method> methods = [] {
        std::vector<Method> all;
        for (std::vector<Method> (*family)() :
             {detail::pseudo_energy_methods, detail::sb2_locality_methods, detail::hosaka_methods,
              detail::curvature_profile_methods, detail::boost_math_methods, detail::eigen_methods,
              detail::opencascade_methods})
            for (Method& m : family()) all.push_back(std::move(m));
        return all;
    }();
    return methods;
}

std::vector<std::string> method_names() {
    std::vector<std::string> names;
    for (const Method& m : registry()) {
        names.push_back(m.name);
        for (const std::string& a : m.aliases) names.push_back(a);
    }
    return names;
}

const Method& find_method(const std::string& name) {
    for (const Method& m : registry()) {
        if (m.name == name) return m;
        for (const std::string& a : m.aliases)
            if (a == name) return m;
    }
    std::string known;
    for (const std::string& n : method_names()) known += (known.empty() ? "" : ", ") + n;
    fail_input("cagd::methods::find_method", "unknown method '" + name + "'; known: " + known);
}

namespace {

// Squared distances must stay finite and nonzero: coordinates beyond 1e150 overflow them (and the
// methods' products of differences; Boost's centripetal parameter read past its knots at 4e289,
// found by fuzz_interpolate), chords below 1e-150 (relative to the coordinates' size when that
// exceeds 1) underflow them.
constexpr double kLargestCoordinate = 1e150;
constexpr double kShortestChord = 1e-150;

}  // namespace

std::string method_applicability(const MethodClaims& m, const PointList& points, bool closed) {
    if (closed && !m.supports_closed) return "open curves only";
    const int need = closed ? m.min_points_closed : m.min_points;
    if (points.rows() < need) return "needs at least " + std::to_string(need) + " points";
    if (m.max_points > 0 && points.rows() > m.max_points)
        return "takes at most " + std::to_string(m.max_points) + " points";
    if (points.cols() < 2) return "needs points of dimension 2 or 3";
    if (points.cols() > m.max_dimension)
        return m.max_dimension == 2 ? "planar points only"
                                    : "at most " + std::to_string(m.max_dimension) + " dimensions";
    return "";
}

std::string interpolate_who(const Method& method) { return "cagd::methods::interpolate(" + method.name + ")"; }

namespace {

// InvalidInput naming `who` unless the method's claims take the points (method_applicability).
void require_applicable(const MethodClaims& claims, const PointList& points, bool closed, const std::string& who) {
    if (const std::string why = method_applicability(claims, points, closed); !why.empty())
        fail_input(who, why + "; got " + std::to_string(points.rows()) +
                            (closed ? " points of a closed curve" : " points") + " in dimension " +
                            std::to_string(points.cols()));
}

// interpolate()'s build on points checked against the claims and validated, with the solve started
// from `start` when the method has a rebuild and `start` is not empty.
InterpolationResult build_valid(const Method& method, const ValidPoints& valid, const ParameterValues& values,
                                const Eigen::VectorXd& start, const std::string& who) {
    const PointList& points = valid.points();
    const bool closed = valid.closed();
    const PointExtent& extent = valid.extent();
    // Valid points whose arithmetic leaves double precision: differences of coordinates near 1e308
    // overflow, and chords below 1e-150 square to 0 (their norm underflows). The result is not
    // representable: an outcome, not bad input.
    const double largest = extent.largest_abs_coordinate;
    if (largest > kLargestCoordinate) {
        InterpolationResult r;
        r.outcome = {
            Status::not_representable,
            method.name + ": coordinates up to " + full_precision(largest) +
                " overflow its arithmetic (at most 1e150: squared distances must stay finite); scale the points down"};
        return r;
    }
    const double shortest = kShortestChord * std::max(1.0, largest);
    if (const Eigen::Index i = extent.shortest_squared_chord >= shortest * shortest
                                   ? -1
                                   : first_chord_shorter_than(points, closed, shortest);
        i >= 0) {
        const Eigen::Index next = i + 1 == points.rows() ? 0 : i + 1;
        InterpolationResult r;
        r.outcome = {Status::not_representable,
                     method.name + ": " + point_label(i) + " and " + point_label(next) + " differ by " +
                         full_precision((points.row(next) - points.row(i)).cwiseAbs().maxCoeff()) +
                         " at most per coordinate: below 1e-150 (times the coordinates' size) the chord's square "
                         "underflows; scale the points up"};
        return r;
    }
    try {
        return method.rebuild && start.size() > 0 ? method.rebuild(valid, values, start) : method.build(valid, values);
    } catch (const std::domain_error& e) {  // Boost.Math's own precondition checks
        fail_input(who, std::string("Boost.Math refused the points: ") + e.what());
    }
}

// interpolate()'s checks (the claims, then the points) and build.
InterpolationResult checked_build(const Method& method, const PointList& points, bool closed,
                                  const ParameterValues& values, const Eigen::VectorXd& start) {
    const MethodClaims claims = method.claims(values);
    const std::string who = interpolate_who(method);
    require_applicable(claims, points, closed, who);
    const ValidPoints valid =
        validate_points(points, closed ? claims.min_points_closed : claims.min_points, closed, who);
    return build_valid(method, valid, values, start, who);
}

}  // namespace

InterpolationResult interpolate(const Method& method, const PointList& points, bool closed,
                                const ParameterValues& values) {
    return checked_build(method, points, closed, values, Eigen::VectorXd());
}

InterpolationResult interpolate(const std::string& name, const PointList& points, bool closed,
                                const ParameterText& values) {
    for (const Method& m : registry())
        for (const Preset& p : m.presets)
            if (p.name == name) {
                ParameterText merged = values;
                merged.insert(p.values.begin(), p.values.end());  // keeps what `values` gives
                return interpolate(m, points, closed, parse_parameter_values(m.name, m.parameters, merged));
            }
    const Method& m = find_method(name);
    return interpolate(m, points, closed, parse_parameter_values(m.name, m.parameters, values));
}

namespace {

Configuration configure(const Method& m, const std::string& name, const ParameterText& text) {
    Configuration c{name, &m, parse_parameter_values(m.name, m.parameters, text), {}};
    c.claims = m.claims(c.values);
    return c;
}

}  // namespace

const std::vector<Configuration>& configurations() {
    static const std::vector<Configuration> all = [] {
        std::vector<Configuration> out;
        for (const Method& m : registry()) {
            if (m.presets.empty()) out.push_back(configure(m, m.name, {}));
            for (const Preset& p : m.presets) out.push_back(configure(m, p.name, p.values));
        }
        return out;
    }();
    return all;
}

Configuration find_configuration(const std::string& name) {
    for (const Configuration& c : configurations())
        if (c.name == name) return c;
    for (const Method& m : registry()) {
        bool match = m.name == name;
        for (const std::string& a : m.aliases) match = match || a == name;
        if (match) return configure(m, m.name, {});
    }
    std::string known;
    for (const Configuration& c : configurations()) known += (known.empty() ? "" : ", ") + c.name;
    fail_input("cagd::methods::find_configuration",
               "unknown method '" + name + "'; known: " + known + " (or any method name, with its defaults)");
}

Configuration find_configuration(const std::string& name, const ParameterText& overrides) {
    const Configuration base = find_configuration(name);
    if (overrides.empty()) return base;
    ParameterText text;
    for (const Preset& p : base.method->presets)
        if (p.name == base.name) text = p.values;
    for (const auto& [parameter, value] : overrides) text[parameter] = value;
    return configure(*base.method, base.name, text);
}

InterpolationResult interpolate(const Configuration& configuration, const PointList& points, bool closed) {
    return interpolate(*configuration.method, points, closed, configuration.values);
}

InterpolationResult interpolate_from(const Configuration& configuration, const PointList& points, bool closed,
                                     const Eigen::VectorXd& start) {
    return checked_build(*configuration.method, points, closed, configuration.values, start);
}

InterpolationResult interpolate_from(const Configuration& configuration, const ValidPoints& points,
                                     const Eigen::VectorXd& start) {
    const Method& method = *configuration.method;
    const MethodClaims claims = method.claims(configuration.values);
    const std::string who = interpolate_who(method);
    require_applicable(claims, points.points(), points.closed(), who);
    const bool closed = points.closed();
    return build_valid(method, points.at_least(closed ? claims.min_points_closed : claims.min_points, who),
                       configuration.values, start, who);
}

}  // namespace cagd::methods
