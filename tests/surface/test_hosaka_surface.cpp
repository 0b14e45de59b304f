// hosaka sections 4–5: Taylor jets, the tensor patch (eq 27), the edge-curve form and Coons' surface
// (eq 28–29), the Cartesian patch (eq 30), boundary-conforming synthesis (eq 31–40) and joining
// across a section (eq 41–43).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "cagd/core/errors.hpp"
#include "cagd/numeric/taylor_jet.hpp"
#include "cagd/surface/boundary_surface.hpp"
#include "cagd/surface/hosaka_patch.hpp"

using namespace cagd;
using namespace cagd::surface;
using numeric::TaylorJet;

namespace {

CornerDerivatives random_corners(int m, int dim, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-1, 1);
    CornerDerivatives c(m, dim);
    for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l)
            for (int i = 0; i <= m; ++i)
                for (int j = 0; j <= m; ++j) {
                    Eigen::VectorXd v(dim);
                    for (int r = 0; r < dim; ++r)
                        v(r) = d(rng) + (i == 0 && j == 0 ? 2.0 * (r == 0 ? k : r == 1 ? l : 0) : 0.0);
                    c.at(k, l, i, j) = v;
                }
    return c;
}

// Boundaries of our test surfaces: lower y0 = 0.2 sin x, upper y1 = 1.5 + 0.1 x², with z and
// cross-boundary derivatives sinusoids.
BoundaryCurve boundary(int m, int k) {
    BoundaryCurve c;
    c.x_min = 0.0;
    c.x_max = 2.0;
    c.y = k == 0 ? sinusoid(0.2, 1.0, 0.0) : polynomial_function({1.5, 0.0, 0.1});
    for (int j = 0; j <= m; ++j)
        c.phi.push_back(sinusoid(0.5 / (j + 1), 1.0 + 0.3 * j + 0.2 * k, 0.4 * j - k, j == 0 ? 0.3 * k : 0.0));
    return c;
}

}  // namespace

TEST(HosakaPatch, InterpolatesEveryCornerDerivative) {
    for (int m = 0; m <= 3; ++m) {
        const HosakaPatch patch(random_corners(m, 3, 10u + static_cast<unsigned>(m)));
        for (int k = 0; k < 2; ++k)
            for (int l = 0; l < 2; ++l)
                for (int i = 0; i <= m; ++i)
                    for (int j = 0; j <= m; ++j)
                        EXPECT_LT((patch.derivative(k, l, i, j) - patch.corners().at(k, l, i, j)).norm(), 1e-11)
                            << m << k << l << i << j;
    }
    EXPECT_THROW(HosakaPatch(random_corners(1, 3, 1)).point(1.5, 0.5), InvalidInput);
}

TEST(EdgeFormPatch, WithTwistsEqualsTensorPatchAndWithoutIsCoons) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> d(0, 1);
    for (int m = 1; m <= 2; ++m) {
        const HosakaPatch patch(random_corners(m, 3, 20u + static_cast<unsigned>(m)));
        const PatchEdges edges = patch.edges();
        const EdgeFormPatch full(m, edges, patch.corners()), coons(m, edges);
        for (int s = 0; s < 50; ++s) {
            const double u = d(rng), v = d(rng);
            for (int a = 0; a <= 2; ++a)
                for (int b = 0; b <= 2; ++b)
                    EXPECT_LT((full.derivative(u, v, a, b) - patch.derivative(u, v, a, b)).norm(), 1e-11);
            EXPECT_LT((coons.point(u, v) - coons_boolean_sum(edges, m, u, v)).norm(), 1e-13);
            // Coons contains the edges.
            EXPECT_LT((coons.point(u, 0) - patch.point(u, 0)).norm(), 1e-13);
            EXPECT_LT((coons.point(1, v) - patch.point(1, v)).norm(), 1e-13);
        }
        for (int k = 0; k < 2; ++k)
            for (int l = 0; l < 2; ++l) {
                EXPECT_LT(coons.derivative(k, l, 1, 1).norm(), 1e-12);  // zero twist
                EXPECT_GT(patch.derivative(k, l, 1, 1).norm(), 1e-3);   // the data's is not
                EXPECT_LT((coons.derivative(k, l, 1, 0) - patch.derivative(k, l, 1, 0)).norm(),
                          1e-12);  // edge tangents kept
            }
    }
}

TEST(EdgeFormPatch, RejectsEdgesThatDoNotMeet) {
    const HosakaPatch patch(random_corners(1, 3, 3));
    PatchEdges e = patch.edges();
    Eigen::MatrixXd start = patch.edge(3).start_derivatives(0), end = patch.edge(3).end_derivatives(0);
    start(0, 2) += 0.1;
    e.r3 = std::make_shared<spline::HosakaCurve>(1, start, end);
    EXPECT_THROW(EdgeFormPatch(1, e), InvalidInput);
    e.r3 = nullptr;
    EXPECT_THROW(EdgeFormPatch(1, e), InvalidInput);
}

TEST(CartesianSurface, ReproducesPolynomialsOfDegreeTwoMPlusOneAndIsCmAcrossLines) {
    // ζ = x³y² − 2xy³ + y (bidegree ≤ 3): m = 1 with exact node derivatives reproduces it exactly.
    const auto zeta = [](double x, double y, int a, int b) {
        const auto px = [&](int p) {
            return a > p ? 0.0 : std::tgamma(p + 1) / std::tgamma(p - a + 1) * std::pow(x, p - a);
        };
        const auto py = [&](int p) {
            return b > p ? 0.0 : std::tgamma(p + 1) / std::tgamma(p - b + 1) * std::pow(y, p - b);
        };
        return px(3) * py(2) - 2 * px(1) * py(3) + px(0) * py(1);
    };
    const std::vector<double> x{0, 0.4, 1.5, 2}, y{-1, 0.3, 1};
    std::vector<Eigen::MatrixXd> nodes;
    for (double yb : y)
        for (double xa : x) {
            Eigen::MatrixXd n(2, 2);
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) n(i, j) = zeta(xa, yb, i, j);
            nodes.push_back(n);
        }
    const CartesianSurface s(1, x, y, nodes);
    for (double xs : {0.0, 0.3, 0.9, 1.7, 2.0})
        for (double ys : {-1.0, -0.2, 0.5, 1.0})
            for (int a = 0; a <= 2; ++a)
                for (int b = 0; b <= 2; ++b)
                    EXPECT_NEAR(s.derivative(xs, ys, a, b), zeta(xs, ys, a, b), 1e-11) << xs << ys << a << b;
    EXPECT_THROW(s.value(2.5, 0), InvalidInput);
    EXPECT_THROW(CartesianSurface(1, {0, 0}, y, nodes), InvalidInput);
}

TEST(CartesianSplineSurface, InterpolatesHeightsAndIsC2AlongGridLines) {
    const std::vector<double> x{0, 0.5, 1.6, 2.0, 3.0}, y{0, 0.7, 1.1, 2.0};
    Eigen::MatrixXd z(5, 4);
    for (int a = 0; a < 5; ++a)
        for (int b = 0; b < 4; ++b)
            z(a, b) = std::sin(x[static_cast<std::size_t>(a)]) * std::cos(y[static_cast<std::size_t>(b)]);
    const CartesianSurface s = cartesian_spline_surface(x, y, z);
    for (int a = 0; a < 5; ++a)
        for (int b = 0; b < 4; ++b)
            EXPECT_NEAR(s.value(x[static_cast<std::size_t>(a)], y[static_cast<std::size_t>(b)]), z(a, b), 1e-14);
    // ζ^{(2,0)} continuous across x = x_1 (the spline's C2) for v inside a cell.
    for (double v : {0.2, 0.6})
        EXPECT_NEAR(s.derivative_in(0, 1, 1.0, v, 2, 0), s.derivative_in(1, 1, 0.0, v, 2, 0), 1e-11);
    // ζ^{(1,1)} from the splines along y of ζ^{(1,0)} equals the one along x of ζ^{(0,1)} (tensor spline).
    const Eigen::MatrixXd zy = spline::hosaka_explicit_spline(y, z.transpose()).slopes;    // ny × nx
    const Eigen::MatrixXd zyx = spline::hosaka_explicit_spline(x, zy.transpose()).slopes;  // nx × ny
    for (int a = 0; a < 5; ++a)
        for (int b = 0; b < 4; ++b) EXPECT_NEAR(s.node(a, b)(1, 1), zyx(a, b), 1e-12);
    EXPECT_THROW(cartesian_spline_surface(x, y, z.transpose()), InvalidInput);
}

TEST(BoundaryConformingSurface, MeetsBothBoundariesWithTheirCrossDerivatives) {
    for (int m = 0; m <= 2; ++m) {
        const BoundaryCurve lo = boundary(m, 0), hi = boundary(m, 1);
        const BoundaryConformingSurface s(m, lo, hi);
        for (double x : {0.0, 0.37, 1.2, 2.0})
            for (int j = 0; j <= m; ++j) {
                EXPECT_NEAR(s.derivative(x, lo.y(x, 0), 0, j), lo.phi[static_cast<std::size_t>(j)](x, 0), 1e-12);
                EXPECT_NEAR(s.derivative(x, hi.y(x, 0), 0, j), hi.phi[static_cast<std::size_t>(j)](x, 0), 1e-12);
            }
    }
}

TEST(BoundaryConformingSurface, RecurrenceAgreesWithDirectDifferentiationAndFiniteDifferences) {
    for (int m = 1; m <= 2; ++m) {
        const BoundaryConformingSurface s(m, boundary(m, 0), boundary(m, 1));
        for (double x : {0.3, 1.1, 1.8})
            for (double v : {0.0, 0.25, 0.8, 1.0}) {
                const double y = s.y_lower(x) + v * (s.y_upper(x) - s.y_lower(x));
                for (int i = 0; i <= 4; ++i)
                    for (int n = 0; n <= 3; ++n) {
                        const double direct = s.derivative_direct(x, y, i, n);
                        EXPECT_NEAR(s.derivative(x, y, i, n), direct, 1e-10 * (1 + std::abs(direct)))
                            << m << " " << x << " " << v << " " << i << " " << n;
                    }
                if (v > 0.0 && v < 1.0) {  // the jets against a central difference in x (inside the section)
                    const double h = 1e-5, fd = (s.value(x + h, y) - s.value(x - h, y)) / (2 * h);
                    EXPECT_NEAR(s.derivative_direct(x, y, 1, 0), fd, 1e-8);
                }
            }
    }
}

TEST(BoundaryConformingSurface, RejectsCrossingCurvesAndDifferentRanges) {
    BoundaryCurve lo = boundary(1, 0), hi = boundary(1, 1);
    BoundaryCurve crossing = hi;
    crossing.y = polynomial_function({0.5, -0.5});  // drops below 0.2 sin x near x = 0.7
    EXPECT_THROW(BoundaryConformingSurface(1, lo, crossing), InvalidInput);
    BoundaryCurve shorter = hi;
    shorter.x_max = 1.5;
    EXPECT_THROW(BoundaryConformingSurface(1, lo, shorter), InvalidInput);
    EXPECT_THROW(BoundaryConformingSurface(2, lo, hi), InvalidInput);  // m+1 functions needed
    const BoundaryConformingSurface s(1, lo, hi);
    EXPECT_THROW(s.value(2.5, 1.0), InvalidInput);
    EXPECT_THROW(s.value(1.0, 5.0), InvalidInput);
}

TEST(Identity40, EveryBracketVanishesForMUpToFive) {
    for (int m = 0; m <= 5; ++m)
        for (int j = 0; j <= m; ++j)
            for (int k = 0; k < 2; ++k)
                for (int s = 0; s < 2; ++s) EXPECT_TRUE(identity40_bracket(m, j, k, s).is_zero()) << m << j << k << s;
    EXPECT_THROW(identity40_bracket(1, 2, 0, 0), InvalidInput);
}

TEST(SectionJoinedSurface, AgreesWithTheFirstSurfaceToOrderMAcrossTheSeam) {
    for (int m = 1; m <= 2; ++m) {
        const BoundaryConformingSurface a(m, boundary(m, 0), boundary(m, 1));
        const double x0 = 2.0, y0 = a.y_lower(x0), y1 = a.y_upper(x0);
        BoundaryCurve far;
        far.x_min = y0;
        far.x_max = y1;
        far.y = sinusoid(0.2, 2.0, 0.0, 3.0);  // x3(y) = 3 + 0.2 sin 2y
        for (int i = 0; i <= m; ++i) far.phi.push_back(sinusoid(0.3 / (i + 1), 1.5, i, i == 0 ? 0.5 : 0.0));
        const SectionJoinedSurface b(a, x0, far);
        double worst = 0.0, next = 0.0;
        for (double v : {0.1, 0.5, 0.9}) {
            const double y = y0 + v * (y1 - y0);
            for (int n = 0; n <= 2; ++n) {
                for (int i = 0; i <= m; ++i)
                    worst = std::max(worst, std::abs(a.derivative(x0, y, i, n) - b.derivative(x0, y, i, n)));
                next = std::max(next, std::abs(a.derivative(x0, y, m + 1, n) - b.derivative(x0, y, m + 1, n)));
            }
        }
        EXPECT_LT(worst, 1e-10) << m;
        EXPECT_GT(next, 1e-3) << m;  // order m+1 is not matched
        EXPECT_NEAR(b.value(b.x_far(0.5 * (y0 + y1)), 0.5 * (y0 + y1)), far.phi[0](0.5 * (y0 + y1), 0), 1e-12);
        BoundaryCurve wrong = far;
        wrong.x_max = y1 + 0.1;
        EXPECT_THROW(SectionJoinedSurface(a, x0, wrong), InvalidInput);
        wrong = far;
        wrong.y = constant_function(1.0);  // x3 < x0
        EXPECT_THROW(SectionJoinedSurface(a, x0, wrong), InvalidInput);
        EXPECT_THROW(SectionJoinedSurface(a, 5.0, far), InvalidInput);
    }
}
