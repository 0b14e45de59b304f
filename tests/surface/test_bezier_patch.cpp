// surface/bezier_patch: tensor-product Bézier patches, grid and de Casteljau evaluation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cagd/aesthetic/log_aesthetic_space_curve.hpp"
#include "cagd/aesthetic/space_typical_bezier.hpp"
#include "cagd/aesthetic/typical_surface.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/analysis/surface_curvature.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/numeric/alexa_product.hpp"
#include "cagd/spline/bezier.hpp"
#include "cagd/surface/bezier_patch.hpp"

using namespace cagd;
using namespace cagd::aesthetic;

namespace {

// z = x² + y² over [0, 1]² as a bi-quadratic Bézier patch (Bernstein coefficients of t²: 0, 0, 1).
surface::ControlNet paraboloid_net() {
    surface::ControlNet net;
    for (auto& c : net) c.resize(3, 3);
    const double sq[3] = {0.0, 0.0, 1.0};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            net[0](i, j) = i / 2.0;
            net[1](i, j) = j / 2.0;
            net[2](i, j) = sq[i] + sq[j];
        }
    return net;
}

}  // namespace

TEST(BezierPatch, ParaboloidCurvatureMatchesTheMongeFormulas) {
    const surface::BezierPatch patch(paraboloid_net());
    for (double x : {0.0, 0.3, 1.0})
        for (double y : {0.2, 0.9}) {
            const analysis::SurfaceJet2 j = patch.jet(x, y);
            EXPECT_NEAR(j.s(2), x * x + y * y, 1e-15);
            const double w = 1.0 + 4 * x * x + 4 * y * y;
            const analysis::SurfaceCurvatures c = analysis::surface_curvatures(j);
            EXPECT_NEAR(c.gaussian, 4.0 / (w * w), 1e-13);
            EXPECT_NEAR(c.mean, (2.0 * (1 + 4 * y * y) + 2.0 * (1 + 4 * x * x)) / (2.0 * std::pow(w, 1.5)), 1e-13);
        }
}

TEST(BezierPatch, GridAndDeCasteljauAgreeAtDegree24) {
    const surface::ControlNet net = log_aesthetic_typical_net(-0.5, -0.6, 1.0, 24, 0.3);
    const surface::BezierPatch patch(net);
    const std::vector<double> us{0.0, 0.31, 1.0}, vs{0.05, 0.5, 0.93};
    const surface::SurfaceGrid g = patch.evaluate_grid(us, vs);
    for (Eigen::Index a = 0; a < 3; ++a)
        for (Eigen::Index b = 0; b < 3; ++b) {
            const analysis::SurfaceJet2 x = g.jet(a, b), y = patch.jet_de_casteljau(us[static_cast<std::size_t>(a)],
                                                                                    vs[static_cast<std::size_t>(b)]);
            EXPECT_LT((x.s - y.s).norm(), 1e-13);
            EXPECT_LT((x.suv - y.suv).norm(), 1e-10);
            EXPECT_LT((x.svv - y.svv).norm(), 1e-10);
            EXPECT_LT((x.suu - y.suu).norm(), 1e-10);
        }
    EXPECT_THROW(patch.jet(1.2, 0.5), InvalidInput);
    surface::ControlNet bad = net;
    bad[1].resize(3, 3);
    EXPECT_THROW(surface::BezierPatch{bad}, InvalidInput);
}
