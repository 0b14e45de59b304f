// analysis/arc_length_parameter: t(s) inverts the arc length on every registered method's curve.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cagd/analysis/arc_length_parameter.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"

#include "../support/point_lists.hpp"

namespace {

TEST(ArcLengthParameter, InvertsTheArcLengthOfEveryMethodsCurve) {
    for (const cagd::methods::Configuration& c : cagd::methods::configurations()) {
        const cagd::methods::InterpolationResult r = cagd::methods::interpolate(c, cagd::test::kNewberyGarrett, false);
        ASSERT_TRUE(r.outcome.ok()) << c.name;
        const auto curve = std::make_shared<const cagd::methods::MethodParameterCurve>(*r.interpolant);
        const cagd::analysis::ArcLengthParameter inverse(curve);
        const double length = cagd::analysis::accurate_arc_length(*curve).value;
        EXPECT_NEAR(inverse.length(), length, 1e-11 * length) << c.name;
        for (double f : {0.0, 0.013, 0.25, 0.5, 0.777, 1.0}) {
            const double s = f * inverse.length(), t = inverse.parameter_at(s);
            EXPECT_NEAR(cagd::analysis::arc_length(*curve, curve->t_min(), t, 64), s, 1e-11 * length)
                << c.name << ": ∫|r'| up to t(s) is s, s = " << s;
        }
        // Where the parameter is arc length already (curvature-profile), t(s) = s.
        if (c.claims.parameter == "arc length") {
            EXPECT_NEAR(inverse.parameter_at(0.4 * length), 0.4 * length, 1e-10 * length) << c.name;
        }
    }
}

TEST(ArcLengthParameter, RefusesAnArcLengthOutsideTheCurve) {
    const cagd::methods::InterpolationResult r =
        cagd::methods::interpolate("cubic-b", cagd::test::kNewberyGarrett, false);
    const cagd::analysis::ArcLengthParameter inverse(r.interpolant->curve);
    try {
        inverse.parameter_at(inverse.length() * 1.5);
        ADD_FAILURE() << "an arc length beyond the curve was accepted";
    } catch (const cagd::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("the curve's length"), std::string::npos) << e.what();
    }
    EXPECT_THROW(inverse.parameter_at(-1e-3), cagd::InvalidInput);
    EXPECT_THROW(inverse.parameter_at(std::nan("")), cagd::InvalidInput);
}

}  // namespace
