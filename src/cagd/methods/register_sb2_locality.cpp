// The methods of sb2_locality (Kuroda, Furukawa, Kimura): S-splines and B2-splines with
// controllable locality m (eq 3, 7, 11-13), their end conditions and extra-point rules (section 3).
#include "cagd/methods/detail/registration.hpp"

#include "cagd/locality/locality_spline.hpp"

namespace cagd::methods::detail {

namespace {

std::vector<Parameter> locality_parameters() {
    std::vector<Parameter> p = {
        {.name = "m",
         .type = P::integer,
         .default_text = "2",
         .lower = 0,
         .upper = locality::kMaxLocality,
         .help = "locality m for every segment (eq 12; m = 4, 5 truncated by eq 13)"},
        {.name = "m-vector", .type = P::text, .help = "one m per segment instead of --m, pairs as l:r, e.g. 1,2,1:3"},
        {.name = "end",
         .type = P::choice,
         .default_text = "natural",
         .choices = {"natural", "tangent", "bessel"},
         .help = "end condition (section 3.3)"},
        {.name = "rule",
         .type = P::choice,
         .default_text = "locality",
         .choices = {"locality", "I", "IIa", "fmill"},
         .help = "extra control point: locality (eq 12) | I (eq 15) | IIa (eq 16) | fmill (eq 17)"},
    };
    for (Parameter& t : tangent_parameters()) p.push_back(std::move(t));
    return p;
}

MethodClaims locality_claims(const ParameterValues& v) {
    return {.parametric_continuity = 2,
            .geometric_continuity = 2,
            .parameter = "uniform",
            .invariance = v.text("end") == "tangent" ? Invariance::none : Invariance::affine,
            .max_dimension = 3};
}

InterpolationResult build_locality(const ValidPoints& valid, const ParameterValues& v, locality::SplineForm form) {
    const PointList& points = valid.points();
    const bool closed = valid.closed();
    const std::string who =
        std::string("cagd::methods(") + (form == locality::SplineForm::s_spline ? "s-spline" : "b2-spline") + ")";
    locality::Options o;
    o.form = form;
    if (v.given("m") && v.has("m-vector")) fail_input(who, "give --m or --m-vector, not both");
    if (v.has("m-vector"))
        o.m = locality::parse_m_vector(v.text("m-vector"));
    else
        o.m = {{v.integer("m"), v.integer("m")}};
    o.closed = closed;
    const std::string& rule = v.text("rule");
    o.rule = rule == "I"       ? locality::ExtraPointRule::method_I
             : rule == "IIa"   ? locality::ExtraPointRule::method_IIa
             : rule == "fmill" ? locality::ExtraPointRule::fmill
                               : locality::ExtraPointRule::locality;
    const std::string& end = v.text("end");
    o.start.kind = o.end.kind = end == "tangent"  ? locality::EndKind::tangent
                                : end == "bessel" ? locality::EndKind::bessel
                                                  : locality::EndKind::natural;
    require_tangent_pair(who, v);
    if (o.start.kind == locality::EndKind::tangent) {
        o.start.tangent = v.vector("start-tangent");
        o.end.tangent = v.vector("end-tangent");
    }
    auto c = std::make_shared<BSplineCurve>(locality::interpolate(valid, o).curve);
    return result_of(unit_span_interpolant(std::move(c), node_count(points, closed), unit_lengths(points, closed)));
}

}  // namespace

std::vector<Method> sb2_locality_methods() {
    std::vector<Method> r;
    r.push_back({
        .name = "s-spline",
        .paper = "sb2_locality",
        .source = "eq (3), (11)-(13), sec 3.3",
        .summary = "S-spline with controllable locality m",
        .parameters = locality_parameters(),
        .claims = locality_claims,
        .build = [](const ValidPoints& p,
                    const ParameterValues& v) { return build_locality(p, v, locality::SplineForm::s_spline); },
        .presets = {{"s-spline-m1", {{"m", "1"}}}, {"s-spline-m2", {{"m", "2"}}}, {"s-spline-m4", {{"m", "4"}}}},
    });
    r.push_back({
        .name = "b2-spline",
        .paper = "sb2_locality",
        .source = "eq (7), (11)-(13), sec 3.3",
        .summary = "B2-spline with controllable locality m",
        .parameters = locality_parameters(),
        .claims = locality_claims,
        .build = [](const ValidPoints& p,
                    const ParameterValues& v) { return build_locality(p, v, locality::SplineForm::b2_spline); },
        .presets = {{"b2-spline-m1", {{"m", "1"}}}, {"b2-spline-m2", {{"m", "2"}}}, {"b2-spline-m4", {{"m", "4"}}}},
    });
    return r;
}

}  // namespace cagd::methods::detail
