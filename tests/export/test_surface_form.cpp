// Surfaces in CAD form (export/surface_form.hpp): the Bézier patches of Hosaka's tensor, Cartesian
// and edge-form patches and of the typical surface agree with the surfaces, derivatives included;
// the B-spline surface holds the same patches; the JSON document reads back bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "../support/messages.hpp"
#include "cagd/aesthetic/typical_surface.hpp"
#include "cagd/export/curve_formats.hpp"
#include "cagd/export/curve_json.hpp"
#include "cagd/export/surface_form.hpp"
#include "cagd/spline/bspline.hpp"

using namespace cagd;
using namespace cagd::exports;
using cagd::test::invalid_input_message;

namespace {

constexpr double kSurfaceExactRelative = 1e-12;

surface::CornerDerivatives corners_of(int m, int dim, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    surface::CornerDerivatives c(m, dim);
    for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l)
            for (int i = 0; i <= m; ++i)
                for (int j = 0; j <= m; ++j)
                    for (int x = 0; x < dim; ++x)
                        c.at(k, l, i, j)(x) = (i == 0 && j == 0 ? 3.0 * (x == 0   ? k
                                                                         : x == 1 ? l
                                                                                  : k * l)
                                                                : 0.0) +
                                              d(rng);
    return c;
}

// S at (u, v) of a B-spline surface: the curves along v of every row, then the curve along u.
Eigen::Vector3d bspline_surface_point(const BSplineSurface& s, double u, double v) {
    const Eigen::Index nu = s.control[0].rows(), nv = s.control[0].cols();
    Eigen::MatrixXd rows(nu, 3);
    for (Eigen::Index i = 0; i < nu; ++i) {
        Eigen::MatrixXd row(nv, 3);
        for (int c = 0; c < 3; ++c) row.col(c) = s.control[static_cast<std::size_t>(c)].row(i).transpose();
        rows.row(i) = BSplineCurve(s.degree_v, s.knots_v, row).point(v).transpose();
    }
    return BSplineCurve(s.degree_u, s.knots_u, rows).point(u);
}

// The pieces as one BezierPatch per cell, for derivatives.
surface::BezierPatch cell_patch(const BezierSurfacePieces& p, int a, int b) {
    return surface::BezierPatch(p.net(a, b));
}

}  // namespace

TEST(SurfaceForm, HosakaTensorPatchIsItsNetWithEveryDerivative) {
    for (int m = 0; m <= 3; ++m)
        for (int dim : {2, 3}) {
            const surface::HosakaPatch patch(corners_of(m, dim, 11u + static_cast<unsigned>(m)));
            const SurfaceForm f = to_bezier(patch);
            SCOPED_TRACE("m = " + std::to_string(m) + ", dim " + std::to_string(dim));
            ASSERT_EQ(f.pieces.degree_u, 2 * m + 1);
            ASSERT_TRUE(f.exact) << f.conversion_error;
            const double scale = net_diagonal(f.pieces);
            const surface::BezierPatch net = cell_patch(f.pieces, 0, 0);
            for (double u : {0.0, 0.13, 0.5, 0.91, 1.0})
                for (double v : {0.0, 0.29, 0.77, 1.0}) {
                    const analysis::SurfaceJet2 jet = net.jet(u, v);
                    const auto three = [&](const Eigen::VectorXd& x) {
                        return Eigen::Vector3d(x(0), x(1), dim == 3 ? x(2) : 0.0);
                    };
                    EXPECT_LE((jet.s - three(patch.point(u, v))).norm(), kSurfaceExactRelative * scale);
                    EXPECT_LE((jet.su - three(patch.derivative(u, v, 1, 0))).norm(), 1e-11 * scale);
                    EXPECT_LE((jet.svv - three(patch.derivative(u, v, 0, 2))).norm(), 1e-10 * scale);
                    EXPECT_LE((jet.suv - three(patch.derivative(u, v, 1, 1))).norm(), 1e-10 * scale);
                }
        }
}

TEST(SurfaceForm, CartesianSurfaceIsAGraphOfPatchesOneACell) {
    const std::vector<double> x{0.0, 0.7, 1.5, 3.0}, y{-1.0, 0.0, 2.5};
    Eigen::MatrixXd z(4, 3);
    z << 0.1, 0.5, -0.2, 1.0, 0.3, 0.8, -0.4, 0.9, 0.0, 0.6, 1.2, -0.7;
    const surface::CartesianSurface s = surface::cartesian_spline_surface(x, y, z);
    const SurfaceForm f = to_bezier(s);
    ASSERT_TRUE(f.exact) << f.conversion_error;
    ASSERT_EQ(f.pieces.cells_u(), 3);
    ASSERT_EQ(f.pieces.cells_v(), 2);
    const double scale = net_diagonal(f.pieces);
    for (double xv : {0.0, 0.35, 0.7, 1.1, 2.9, 3.0})
        for (double yv : {-1.0, -0.4, 0.0, 1.7, 2.5}) {
            const Eigen::Vector3d p = f.pieces.point(xv, yv);
            EXPECT_NEAR(p(0), xv, kSurfaceExactRelative * scale);
            EXPECT_NEAR(p(1), yv, kSurfaceExactRelative * scale);
            EXPECT_NEAR(p(2), s.value(xv, yv), kSurfaceExactRelative * scale);
        }
    // ζ_x inside a cell: the patch's S_u divided by the cell's width.
    const analysis::SurfaceJet2 jet = cell_patch(f.pieces, 1, 1).jet(0.25, 0.6);
    EXPECT_NEAR(jet.su(2) / 0.8, s.derivative(0.7 + 0.25 * 0.8, 0.6 * 2.5, 1, 0), 1e-11);
    // One B-spline surface: the same points, and neighbouring nets share their rows (C0 at least).
    double mismatch = 1.0;
    const BSplineSurface b = bspline_surface(f.pieces, &mismatch);
    EXPECT_LE(mismatch, kSurfaceExactRelative * scale);
    EXPECT_EQ(b.knots_u.size(), static_cast<std::size_t>(b.control[0].rows() + 4));
    for (double xv : {0.0, 0.5, 0.7, 2.2, 3.0})
        for (double yv : {-1.0, 0.0, 1.3, 2.5})
            EXPECT_LE((bspline_surface_point(b, xv, yv) - f.pieces.point(xv, yv)).norm(),
                      kSurfaceExactRelative * scale);
}

TEST(SurfaceForm, CoonsPatchHasACellPerSpanOfItsEdges) {
    PointList bottom(4, 3), left(3, 3), top(4, 3), right(3, 3);
    bottom << 0, 0, 0, 1, 0, 0.2, 2, 0, -0.1, 3, 0, 0;
    top << 0, 2, 0.5, 1, 2.2, 0.4, 2, 2.1, 0.6, 3, 2, 0.3;
    left << 0, 0, 0, 0, 1, 0.4, 0, 2, 0.5;
    right << 3, 0, 0, 3.1, 1, 0.1, 3, 2, 0.3;
    const surface::EdgeFormPatch patch(1, surface::edges_through_points(bottom, left, top, right));
    const SurfaceForm f = to_bezier(patch);
    ASSERT_TRUE(f.exact) << f.conversion_error;
    EXPECT_EQ(f.pieces.degree_u, 3);
    EXPECT_GE(f.pieces.cells_u(), 3);  // the breaks of bottom and top, merged
    EXPECT_GE(f.pieces.cells_v(), 2);
    const double scale = net_diagonal(f.pieces);
    for (double u : {0.0, 0.2, 0.5, 0.999, 1.0})
        for (double v : {0.0, 0.45, 1.0})
            EXPECT_LE((f.pieces.point(u, v) - patch.point(u, v)).norm(), kSurfaceExactRelative * scale);
}

namespace {
// A quarter circle: not polynomial.
class QuarterArc : public Curve {
public:
    int dimension() const override { return 3; }
    double t_min() const override { return 0.0; }
    double t_max() const override { return 1.0; }
    void evaluate_jet(double t, int first, cagd::JetSide, Eigen::Ref<Eigen::MatrixXd> out) const override {
        const int order = first + static_cast<int>(out.rows()) - 1;
        Eigen::MatrixXd j = Eigen::MatrixXd::Zero(order + 1, 3);
        const double w = 0.5 * std::numbers::pi, a = w * t;
        for (int k = 0; k <= order; ++k) {
            const double f = std::pow(w, k);
            j(k, 0) = f * std::cos(a + w * k);
            j(k, 1) = f * std::sin(a + w * k);
        }
        j(0, 0) -= 1.0;
        take_rows(j, first, out);
    }
    std::vector<double> breakpoints() const override { return {0.0, 1.0}; }
};
}  // namespace

TEST(SurfaceForm, EdgesThatAreNotPolynomialHaveNoExactForm) {
    // Corners (0,0,0), (−1,1,0) (the arc's ends), (0,0,1), (−1,1,1); the bottom edge is the arc.
    PointList bottom(3, 3), left(3, 3), top(3, 3), right(3, 3);
    bottom << 0, 0, 0, -0.5, 0.5, 0, -1, 1, 0;
    left << 0, 0, 0, 0, 0, 0.5, 0, 0, 1;
    top << 0, 0, 1, -0.5, 0.5, 1, -1, 1, 1;
    right << -1, 1, 0, -1, 1, 0.5, -1, 1, 1;
    surface::PatchEdges e = surface::edges_through_points(bottom, left, top, right);
    e.r1 = std::make_shared<QuarterArc>();
    const surface::EdgeFormPatch patch(1, e);
    const std::string message = invalid_input_message([&] { to_bezier(patch); });
    EXPECT_NE(message.find("R1"), std::string::npos) << message;
    EXPECT_NE(message.find("not a polynomial"), std::string::npos) << message;
}

TEST(SurfaceForm, TypicalSurfaceIsItsOwnNet) {
    const surface::ControlNet net = aesthetic::log_aesthetic_typical_net(-0.5, 2.0, 1.0, 8, 0.3);
    const SurfaceForm f = to_bezier(surface::BezierPatch(net));
    ASSERT_TRUE(f.exact) << f.conversion_error;
    EXPECT_EQ(f.pieces.degree_u, 8);
    EXPECT_EQ(f.pieces.net(0, 0)[2], net[2]);
}

TEST(SurfaceJson, ADocumentReadsBackBitForBit) {
    const SurfaceForm f = to_bezier(surface::HosakaPatch(corners_of(2, 3, 5u)));
    std::stringstream s;
    write_surface_json(s, f, {"hosaka-tensor", {{"m", "2"}}});
    const SurfaceDocument d = read_surface_json(s, "doc");
    EXPECT_EQ(d.provenance.kind, "hosaka-tensor");
    EXPECT_EQ(d.provenance.parameters.at("m"), "2");
    EXPECT_EQ(d.form.exact, f.exact);
    EXPECT_EQ(d.form.conversion_error, f.conversion_error);
    ASSERT_EQ(d.form.pieces.nets.size(), 1u);
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(d.form.pieces.nets[0][static_cast<std::size_t>(c)], f.pieces.nets[0][static_cast<std::size_t>(c)]);
}

TEST(SurfaceJson, BadDocumentsAreRefusedNamingTheMember) {
    const SurfaceForm f = to_bezier(surface::HosakaPatch(corners_of(1, 3, 6u)));
    std::stringstream s;
    write_surface_json(s, f, {"hosaka-tensor", {}});
    const std::string good = s.str();
    const auto refused = [](std::string text) {
        std::istringstream in(text);
        return invalid_input_message([&] { read_surface_json(in, "bad.json"); });
    };
    std::string wrong_degree = good;
    wrong_degree.replace(wrong_degree.find("\"degree_u\": 3"), 13, "\"degree_u\": 2");
    EXPECT_NE(refused(wrong_degree).find("patches[0]"), std::string::npos);
    std::string decreasing = good;
    decreasing.replace(decreasing.find("\"u_breaks\""), 10, "\"u_breaks\": [1.0, 0.0], \"ignored\"");
    EXPECT_NE(refused(decreasing).find("u_breaks"), std::string::npos);
    EXPECT_NE(refused("{\"format\": \"cagd-curve\", \"format_version\": 1}").find("cagd-surface"), std::string::npos);
}

// A form that is not exact to rounding is never written, in either format: an outcome, not input.
TEST(SurfaceFormats, AFormThatIsNotExactIsNotWritten) {
    SurfaceForm f = to_bezier(surface::HosakaPatch(corners_of(1, 3, 7u)));
    ASSERT_TRUE(f.exact);
    f.exact = false;
    f.conversion_error = 2.5e-3;
    for (const CurveFormat format : {CurveFormat::json, CurveFormat::step}) {
        std::ostringstream out;
        const Outcome written = write_surface(out, format, f, {});
        EXPECT_EQ(written.status, Status::not_representable);
        EXPECT_NE(written.message.find("0.0025"), std::string::npos) << written.message;
        EXPECT_TRUE(out.str().empty()) << "nothing written";
    }
}

TEST(SurfaceFormats, JsonAndStepOnlyWithTheirLimits) {
    const SurfaceForm f = to_bezier(surface::HosakaPatch(corners_of(1, 3, 7u)));
    std::ostringstream out;
    EXPECT_NE(invalid_input_message([&] { (void)write_surface(out, CurveFormat::svg, f, {}); }).find("svg"),
              std::string::npos);
    EXPECT_NE(invalid_input_message([&] { (void)write_surface(out, CurveFormat::dxf, f, {}); }).find("dxf"),
              std::string::npos);
    if (!step_available()) GTEST_SKIP() << "no OpenCASCADE in this build";
    std::ostringstream step;
    ASSERT_TRUE(write_surface(step, CurveFormat::step, f, {}).ok());
    EXPECT_NE(step.str().find("B_SPLINE_SURFACE_WITH_KNOTS"), std::string::npos);
    const SurfaceForm high =
        to_bezier(surface::BezierPatch(aesthetic::log_aesthetic_typical_net(-0.5, 2.0, 1.0, 30, 0.3)));
    std::ostringstream too_high;
    EXPECT_NE(invalid_input_message([&] { (void)write_surface(too_high, CurveFormat::step, high, {}); }).find("25"),
              std::string::npos);
}
