// The C++ side of the Python module's test (python/tests/test_cagd.py): the library's
// values for the computations the test repeats through `cagd`, one "key value" line each, with
// 17 significant digits. Usage: python_reference_values SOURCE_DIR
//
// Data: the pseudo_energy paper's Table 1 points (open and closed), and the same points lifted to
// 3-D by z = (x − y)/4 (exact in binary floating point, so Python forms the same numbers).
// GCC 12 warns falsely on `"literal" + std::string&&` once inlined (-Wrestrict, GCC bug 105329);
// this program builds its keys that way throughout.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#endif
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cagd/aesthetic/log_aesthetic_curve.hpp"
#include "cagd/aesthetic/typical_bezier.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"
#include "cagd/smoothing/boundary_plate_smoothing.hpp"
#include "cagd/smoothing/elastic_line.hpp"
#include "cagd/smoothing/elastic_net.hpp"
#include "cagd/smoothing/plate_smoothing.hpp"
#include "cagd/smoothing/window_smoothing.hpp"
#include "cagd/spline/bezier.hpp"
#include "cagd/surface/boundary_surface.hpp"
#include "cagd/surface/hosaka_patch.hpp"

namespace {

void put(const std::string& key, double value) { std::printf("%s %.17g\n", key.c_str(), value); }

// The fractions of the parameter range the test evaluates at.
const double kFractions[] = {0.0, 0.1, 0.37, 0.5, 0.93, 1.0};

void curve_values(const std::string& key, const cagd::Curve& c) {
    put(key + ".length", cagd::analysis::accurate_arc_length(c).value);
    if (c.dimension() == 2) put(key + ".area", cagd::analysis::area_closed_by_chord(c));
    put(key + ".bending_energy", cagd::analysis::bending_energy(c));
    for (int f = 0; f < 6; ++f) {
        const double t = c.t_min() + kFractions[f] * (c.t_max() - c.t_min());
        const Eigen::MatrixXd jet = c.jet(t, 2);
        for (int r = 0; r < 3; ++r)
            for (int d = 0; d < c.dimension(); ++d)
                put(key + ".jet" + std::to_string(f) + "." + std::to_string(r) + "." + std::to_string(d), jet(r, d));
        put(key + ".curvature" + std::to_string(f),
            c.dimension() == 2 ? cagd::analysis::signed_curvature(c, t) : cagd::analysis::curvature(c, t));
        if (c.dimension() == 3) put(key + ".torsion" + std::to_string(f), cagd::analysis::torsion(c, t));
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: python_reference_values SOURCE_DIR\n";
        return 2;
    }
    const cagd::PointList plane =
        cagd::read_points_csv(std::string(argv[1]) + "/reference/pseudo_energy/data/table1.csv");
    cagd::PointList space(plane.rows(), 3);
    space.leftCols(2) = plane;
    space.col(2) = (plane.col(0) - plane.col(1)) / 4.0;

    for (const cagd::methods::Method& m : cagd::methods::registry()) {
        const cagd::methods::ParameterValues defaults = cagd::methods::parse_parameter_values(m.name, m.parameters, {});
        const cagd::methods::MethodClaims claims = m.claims(defaults);
        for (const bool closed : {false, true}) {
            if (closed && !claims.supports_closed) continue;
            for (const int dim : {2, 3}) {
                if (dim > claims.max_dimension) continue;
                const cagd::methods::InterpolationResult r =
                    cagd::methods::interpolate(m, dim == 2 ? plane : space, closed, defaults);
                const std::string key = m.name + (closed ? ".closed" : ".open") + "." + std::to_string(dim) + "d";
                put(key + ".ok", r.outcome.ok() ? 1.0 : 0.0);
                if (r.outcome.ok())
                    curve_values(key, cagd::methods::MethodParameterCurve(
                                          *r.interpolant));  // in the method's parameter, as Python
            }
        }
    }

    const std::vector<std::pair<double, double>> angles = {{0.3, 0.7}, {-1.2, 2.5}, {2.9, -0.4}};
    for (std::size_t i = 0; i < angles.size(); ++i) {
        const cagd::fairness::PseudoEnergyMinimum e =
            cagd::fairness::minimize_pseudo_energy(angles[i].first, angles[i].second);
        const std::string key = "pseudo_energy." + std::to_string(i);
        put(key + ".J", e.pseudo_energy);
        put(key + ".r0", e.r0);
        put(key + ".r1", e.r1);
        put(key + ".length", e.length);
        put(key + ".area", e.area);
    }

    const cagd::aesthetic::LogAestheticCurve lac = cagd::aesthetic::normalized_log_aesthetic_curve(-1.0, 2.0);
    curve_values("lac", lac);
    const cagd::aesthetic::TypicalPolygon typical = cagd::aesthetic::constant_rotation_typical_polygon(-1.0, 2.0, 9);
    curve_values("typical", cagd::BezierCurve(typical.points));

    const std::vector<double> x(plane.col(0).data(), plane.col(0).data() + plane.rows());
    std::vector<double> xs = x;
    for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = static_cast<double>(i);  // strictly increasing abscissae
    const cagd::smoothing::ElasticLine line = cagd::smoothing::elastic_line(xs, plane.col(1), 0.1);
    for (Eigen::Index i = 0; i < line.values().rows(); ++i)
        put("elastic_line.y" + std::to_string(i), line.values()(i, 0));

    // Surfaces (python/bindings_surface.cpp): one grid of heights, its Cartesian surface, the elastic
    // net and the plate smoothing over it; Coons' patch through four edges; a tensor patch.
    {
        const std::vector<double> gx{0.0, 1.0, 2.5, 3.0, 4.2}, gy{0.0, 0.5, 1.5, 2.0};
        Eigen::MatrixXd z(5, 4);
        for (int a = 0; a < 5; ++a)
            for (int b = 0; b < 4; ++b)
                z(a, b) =
                    std::sin(gx[static_cast<std::size_t>(a)]) * std::cos(gy[static_cast<std::size_t>(b)]) + 0.1 * a * b;
        const Eigen::MatrixXd lam = Eigen::MatrixXd::Constant(1, 1, 0.05);
        const cagd::surface::CartesianSurface cart = cagd::surface::cartesian_spline_surface(gx, gy, z);
        const cagd::surface::CartesianSurface net = cagd::smoothing::net_spline_smoothing(gx, gy, z, lam);
        const cagd::surface::CartesianSurface plate =
            cagd::smoothing::plate_smoothing(gx, gy, z, lam, cagd::smoothing::PlateEnergy::poisson).surface;
        const cagd::smoothing::BoundaryPlateSurface boundary_plate =
            cagd::smoothing::boundary_plate_smoothing(gx, gy, z, lam, cagd::smoothing::PlateEnergy::no_twist, 2)
                .surface;
        // Approximation 1 needs equally spaced lines, at least five each way.
        const std::vector<double> ex{0.0, 0.5, 1.0, 1.5, 2.0, 2.5}, ey{0.0, 1.0, 2.0, 3.0, 4.0};
        Eigen::MatrixXd ez(6, 5);
        for (int a = 0; a < 6; ++a)
            for (int b = 0; b < 5; ++b) ez(a, b) = std::cos(ex[static_cast<std::size_t>(a)]) + 0.05 * a * b * b;
        const cagd::surface::CartesianSurface window =
            cagd::smoothing::local_orthogonal_smoothing(ex, ey, ez, 0.3, cagd::smoothing::PlateEnergy::poisson);
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a <= 1; ++a)
                for (int b = 0; b <= 1; ++b) {
                    const double wx = 0.3 + 0.8 * k, wy = 0.7 + 1.1 * k;
                    put("surface.window." + std::to_string(k) + "." + std::to_string(a) + std::to_string(b),
                        window.derivative(wx, wy, a, b));
                }
        const double at[][2] = {{0.0, 0.0}, {0.7, 1.1}, {2.5, 0.5}, {3.9, 1.95}, {4.2, 2.0}};
        for (int k = 0; k < 5; ++k)
            for (int a = 0; a <= 1; ++a)
                for (int b = 0; b <= 1; ++b) {
                    const std::string key = "." + std::to_string(k) + "." + std::to_string(a) + std::to_string(b);
                    put("surface.cartesian" + key, cart.derivative(at[k][0], at[k][1], a, b));
                    put("surface.net" + key, net.derivative(at[k][0], at[k][1], a, b));
                    put("surface.plate" + key, plate.derivative(at[k][0], at[k][1], a, b));
                    put("surface.boundary_plate" + key, boundary_plate.derivative(at[k][0], at[k][1], a, b));
                }
        cagd::PointList bottom(4, 3), left(3, 3), top(4, 3), right(3, 3);
        bottom << 0, 0, 0, 1, 0, 0.3, 2, 0, 0.1, 3, 0, 0;
        left << 0, 0, 0, 0, 1, 0.5, 0, 2, 0;
        top << 0, 2, 0, 1, 2.2, 0.4, 2, 2.1, 0.2, 3, 2, 0;
        right << 3, 0, 0, 3, 1, -0.5, 3, 2, 0;
        const cagd::surface::EdgeFormPatch coons(1, cagd::surface::edges_through_points(bottom, left, top, right));
        cagd::surface::CornerDerivatives corners(1, 3);
        for (int k = 0; k < 2; ++k)
            for (int l = 0; l < 2; ++l)
                for (int i = 0; i <= 1; ++i)
                    for (int j = 0; j <= 1; ++j)
                        for (int d = 0; d < 3; ++d)
                            corners.at(k, l, i, j)[d] = std::sin(1.0 + k + 2 * l + 3 * i + 5 * j + 7 * d);
        const cagd::surface::HosakaPatch tensor(corners);
        // Boundary-conforming synthesis (m = 2) and the surface joined beyond x0 = 2.
        cagd::PointList lower(5, 3), upper(5, 3), far(4, 3);
        for (int k = 0; k < 5; ++k) {
            const double xk = 0.5 * k;
            lower.row(k) << xk, 0.2 * std::sin(xk), 0.1 * xk * xk;
            upper.row(k) << xk, 1.5 + 0.3 * xk, 1.0 - 0.2 * xk;
        }
        const cagd::surface::BoundaryConformingSurface strip(
            2, cagd::surface::boundary_through_points(lower, {0.3, -0.1}),
            cagd::surface::boundary_through_points(upper, {-0.2, 0.05}));
        const double y0 = strip.y_lower(2.0), y1 = strip.y_upper(2.0);
        for (int k = 0; k < 4; ++k) far.row(k) << y0 + (y1 - y0) * k / 3.0, 3.0 + 0.1 * k, 0.5 - 0.1 * k;
        const cagd::surface::SectionJoinedSurface joined(strip, 2.0,
                                                         cagd::surface::boundary_through_points(far, {0.2, 0.0}));
        const double strip_at[][2] = {{0.3, 0.5}, {1.0, 1.2}, {1.7, 0.9}, {2.0, 1.4}};
        const double joined_at[][2] = {{2.0, 0.5}, {2.4, 1.0}, {2.9, 1.6}};
        for (int k = 0; k < 4; ++k)
            for (int a = 0; a <= 1; ++a)
                for (int b = 0; b <= 1; ++b)
                    put("surface.strip." + std::to_string(k) + "." + std::to_string(a) + std::to_string(b),
                        strip.derivative(strip_at[k][0], strip_at[k][1], a, b));
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a <= 1; ++a)
                for (int b = 0; b <= 1; ++b)
                    put("surface.joined." + std::to_string(k) + "." + std::to_string(a) + std::to_string(b),
                        joined.derivative(joined_at[k][0], joined_at[k][1], a, b));
        const double uv[][2] = {{0.0, 0.0}, {0.3, 0.8}, {0.5, 0.5}, {1.0, 0.25}};
        for (int k = 0; k < 4; ++k)
            for (int a = 0; a <= 1; ++a)
                for (int b = 0; b <= 1; ++b)
                    for (int d = 0; d < 3; ++d) {
                        const std::string key = "." + std::to_string(k) + "." + std::to_string(a) + std::to_string(b) +
                                                "." + std::to_string(d);
                        put("surface.coons" + key, coons.derivative(uv[k][0], uv[k][1], a, b)[d]);
                        put("surface.tensor" + key, tensor.derivative(uv[k][0], uv[k][1], a, b)[d]);
                    }
    }

    cagd::compare::ComparisonOptions options;
    options.threads = 1;
    for (const cagd::compare::MethodComparison& c : cagd::compare::compare_methods(plane, options)) {
        if (!c.interpolant) continue;
        put("compare." + c.method + ".length", c.length);
        put("compare." + c.method + ".pseudo_energy", c.pseudo_energy);
        if (c.fairness) put("compare." + c.method + ".bending_energy", c.fairness->bending_energy);
    }
    return 0;
}
