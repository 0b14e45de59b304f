// The method of hosaka (Hosaka): the generalised Hermite spline with scale factors, C2 (eq 15,
// 18-20) or of order m, continuous to order 2m (section 3).
#include "cagd/methods/detail/registration.hpp"

#include "cagd/spline/hosaka_spline.hpp"

namespace cagd::methods::detail {

namespace {

// 2m unknowns per point, and the cost grows fast with m: order 30 keeps a run within seconds.
constexpr int kMaxHosakaOrder = 30;

InterpolationResult build_hosaka(const ValidPoints& valid, const ParameterValues& v) {
    const PointList& points = valid.points();
    const bool closed = valid.closed();
    spline::HosakaSplineOptions o;
    o.scale = v.text("scale") == "unit" ? spline::HosakaScale::unit : spline::HosakaScale::chord;
    o.closed = closed;
    require_tangent_pair("cagd::methods(hosaka)", v);
    const bool chord = o.scale == spline::HosakaScale::chord;
    if (v.text("end") ==
        "tangent") {  // given in the method's parameter t; Hosaka's B_1, C_n are per span: d/du = L d/dt
        // The first and last spans' lengths only, as chord_lengths computes them.
        const auto span_length = [&](Eigen::Index span) {
            if (!chord) return 1.0;
            PointList ends(2, points.cols());
            ends << points.row(span), points.row((span + 1) % points.rows());
            return chord_lengths(ends, false).front();
        };
        o.end = spline::HosakaEnd::tangent;
        o.start_tangent = span_length(0) * v.vector("start-tangent");
        o.end_tangent = span_length(node_count(points, closed) - 2) * v.vector("end-tangent");
    }
    const int m = v.integer("m");
    if (m == 1) {  // the chords once: the construction's |A_i| are the spans' dτ/dt
        std::shared_ptr<const spline::HosakaCurve> curve;
        std::vector<double> lengths;
        {  // k, B and C of eq (20) freed before the node parameters are made (peak memory)
            spline::HosakaSpline s = spline::hosaka_c2_spline(valid, o);
            lengths = std::move(s.span_lengths);
            curve = std::make_shared<const spline::HosakaCurve>(std::move(s.curve));
        }
        return result_of(unit_span_interpolant(std::move(curve), node_count(points, closed), std::move(lengths)));
    }
    // Order m > 1 forms its lengths inside a solve of 2m unknowns per point (SparseLU): these
    // chords again are a small part of it.
    spline::HosakaSplineFit fit = spline::hosaka_spline(valid, m, o);
    if (!fit.outcome.ok()) {
        InterpolationResult none;
        none.outcome = std::move(fit.outcome);
        return none;
    }
    std::vector<double> lengths = chord ? chord_lengths(points, closed) : unit_lengths(points, closed);
    return result_of(unit_span_interpolant(std::make_shared<spline::HosakaCurve>(std::move(*fit.curve)),
                                           node_count(points, closed), std::move(lengths)));
}

}  // namespace

std::vector<Method> hosaka_methods() {
    std::vector<Method> r;
    std::vector<Parameter> hosaka_parameters = {
        {.name = "m",
         .type = P::integer,
         .default_text = "1",
         .lower = 1,
         .upper = kMaxHosakaOrder,
         .help = "segment order m: segments of degree 2m+1, continuous to order 2m (m = 1: eq 18-20)"},
        {.name = "scale",
         .type = P::choice,
         .default_text = "chord",
         .choices = {"chord", "unit"},
         .help = "scale factors: chord (k_i = |A_i|/|A_i+1|, eq 19) or unit (k_i = 1)"},
        {.name = "end",
         .type = P::choice,
         .default_text = "natural",
         .choices = {"natural", "tangent"},
         .help = "end condition"},
    };
    for (Parameter& t : tangent_parameters()) hosaka_parameters.push_back(std::move(t));
    r.push_back({
        .name = "hosaka",
        .paper = "hosaka",
        .source = "eq (15), (18)-(20), sec 3",
        .summary = "generalised Hermite spline with scale factors, C2 (order m: C^2m)",
        .parameters = std::move(hosaka_parameters),
        .claims =
            [](const ParameterValues& v) {
                const bool chord = v.text("scale") == "chord";
                return MethodClaims{.parametric_continuity = 2,
                                    .geometric_continuity = 2,
                                    .parameter = chord ? "chord length" : "uniform",
                                    .invariance = v.text("end") == "tangent" ? Invariance::none
                                                  : chord                    ? Invariance::similarity
                                                                             : Invariance::affine,
                                    .max_dimension = 3};
            },
        .build = build_hosaka,
        .presets = {{"hosaka-c2-chord", {{"scale", "chord"}}}, {"hosaka-c2-unit", {{"scale", "unit"}}}},
    });
    return r;
}

}  // namespace cagd::methods::detail
