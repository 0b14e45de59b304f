// Boost.Math's interpolants as peers: pchip and makima per coordinate over chord length, and the
// centripetal Catmull-Rom spline, converted exactly into the piecewise Hermite form.
#include "cagd/methods/boost_peers.hpp"
#include "cagd/methods/detail/registration.hpp"

namespace cagd::methods::detail {

namespace {

MethodClaims boost_componentwise_claims(const ParameterValues&) {
    return {.parametric_continuity = 1,
            .parameter = "chord length",
            .invariance = Invariance::translation_scale,
            .supports_closed = false,
            .min_points = 4,
            .min_points_closed = 0,
            .max_dimension = 3};
}

}  // namespace

std::vector<Method> boost_math_methods() {
    std::vector<Method> r;
    r.push_back({
        .name = "boost-pchip",
        .paper = "Boost.Math",
        .source = "boost::math::interpolators::pchip on x(t), y(t)",
        .summary = "monotone piecewise cubic Hermite per coordinate over chord length (a peer)",
        .claims = boost_componentwise_claims,
        .build = [](const ValidPoints& p,
                    const ParameterValues&) { return result_of(boost_pchip_interpolant(p.points())); },
    });
    r.push_back({
        .name = "boost-makima",
        .paper = "Boost.Math",
        .source = "boost::math::interpolators::makima on x(t), y(t)",
        .summary = "modified Akima per coordinate over chord length (a peer)",
        .claims = boost_componentwise_claims,
        .build = [](const ValidPoints& p,
                    const ParameterValues&) { return result_of(boost_makima_interpolant(p.points())); },
    });
    r.push_back({
        .name = "boost-catmull-rom",
        .paper = "Boost.Math",
        .source = "boost::math::catmull_rom, centripetal (alpha = 1/2)",
        .summary = "centripetal Catmull-Rom spline (a peer)",
        .claims = fixed({.parametric_continuity = 1,
                         .parameter = "centripetal (sum of sqrt chord)",
                         .invariance = Invariance::similarity,
                         .min_points = 4,
                         .min_points_closed = 4,
                         .max_dimension = 3}),
        .build =
            [](const ValidPoints& p, const ParameterValues&) {
                return result_of(boost_catmull_rom_interpolant(p.points(), p.closed()));
            },
    });
    return r;
}

}  // namespace cagd::methods::detail
