// The exact and approximate Bézier forms, the B-spline forms and the writers of export/, for every
// configuration of the registry, open and closed, planar and (where a method takes them) space
// points: the round trips the formats rely on.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "../support/messages.hpp"
#include "../support/point_lists.hpp"
#include "cagd/analysis/curve_measures.hpp"
#include "cagd/export/bspline_form.hpp"
#include "cagd/export/curve_formats.hpp"
#include "cagd/export/curve_json.hpp"
#include "cagd/export/curve_samples.hpp"
#include "cagd/export/step_writer.hpp"
#include "cagd/methods/curve_provenance.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"

using namespace cagd;
using namespace cagd::exports;

namespace {

// The round-trip tolerance of exact forms, relative to the curve's scale (bezier_form.hpp).
constexpr double kExactRelative = 1e-12;

// A closed star-shaped octagon and a space curve on a helix (distinct consecutive points).
PointList closed_octagon() {
    PointList p(8, 2);
    for (int i = 0; i < 8; ++i) {
        const double a = 2 * std::numbers::pi * i / 8, r = i % 2 ? 1.4 : 1.0;
        p.row(i) << r * std::cos(a), r * std::sin(a);
    }
    return p;
}
PointList helix_points() {
    PointList p(9, 3);
    for (int i = 0; i < 9; ++i) p.row(i) << std::cos(0.7 * i), std::sin(0.7 * i), 0.25 * i;
    return p;
}

struct Case {
    std::string name;
    std::shared_ptr<const Curve> curve;
    bool closed;
};

// Every configuration's curve (in its method's parameter) on the three point sets it takes.
std::vector<Case> registry_curves() {
    std::vector<Case> out;
    const PointList open = test::kNewberyGarrett, closed = closed_octagon(), space = helix_points();
    for (const methods::Configuration& c : methods::configurations()) {
        const std::vector<std::pair<const PointList*, bool>> sets{{&open, false}, {&closed, true}, {&space, false}};
        for (const auto& [points, is_closed] : sets) {
            if (points->cols() > c.claims.max_dimension || (is_closed && !c.claims.supports_closed)) continue;
            const methods::InterpolationResult r = methods::interpolate(c, *points, is_closed);
            if (!r.outcome.ok()) continue;
            out.push_back({c.name + (is_closed             ? " closed"
                                     : points->cols() == 3 ? " 3-D"
                                                           : " open"),
                           std::make_shared<methods::MethodParameterCurve>(*r.interpolant), is_closed});
        }
    }
    return out;
}

// max over samples of |a^(k) − b^(k)| / max |a^(k)|, k = 0, 1, 2 (position, 1st, 2nd derivative),
// 9 samples per piece of `pieces` with both one-sided jets at the joins.
double relative_jet_difference(const Curve& curve, const BezierPieces& pieces) {
    double worst = 0.0;
    std::array<double, 3> scale{0, 0, 0}, diff{0, 0, 0};
    for (int i = 0; i < pieces.pieces(); ++i) {
        const BezierCurve piece = piece_curve(pieces, i);
        for (int j = 0; j <= 8; ++j) {
            const double t = piece.t_min() + (piece.t_max() - piece.t_min()) * j / 8;
            const Eigen::MatrixXd a = j == 8 ? curve.jet_from_left(t, 2) : curve.jet(t, 2), b = piece.jet(t, 2);
            for (int k = 0; k < 3; ++k) {
                scale[static_cast<std::size_t>(k)] = std::max(scale[static_cast<std::size_t>(k)], a.row(k).norm());
                diff[static_cast<std::size_t>(k)] =
                    std::max(diff[static_cast<std::size_t>(k)], (a.row(k) - b.row(k)).norm());
            }
        }
    }
    for (int k = 0; k < 3; ++k)
        worst = std::max(worst, diff[static_cast<std::size_t>(k)] / scale[static_cast<std::size_t>(k)]);
    return worst;
}

}  // namespace

TEST(BezierForm, ExactPiecesOfEveryPolynomialMethodAgreeWithTheCurve) {
    int exact = 0;
    for (const Case& c : registry_curves()) {
        if (c.curve->polynomial_degree() < 0) continue;
        const BezierForm f = to_bezier(*c.curve);
        ASSERT_TRUE(f.exact) << c.name;
        EXPECT_EQ(f.pieces.degree, c.curve->polynomial_degree()) << c.name;
        EXPECT_EQ(f.pieces.breaks, c.curve->breakpoints()) << c.name;
        EXPECT_LE(relative_jet_difference(*c.curve, f.pieces), kExactRelative)
            << c.name << ": |r^(k) − b^(k)| / max |r^(k)|, k ≤ 2, ≤ 1e-12";
        ++exact;
    }
    EXPECT_GE(exact, 30);  // every configuration but the curvature profile, on two or three point sets
}

TEST(BezierForm, ApproximationOfTheCurvatureProfileIsWithinItsStatedDistance) {
    int approximated = 0;
    for (const Case& c : registry_curves()) {
        if (c.curve->polynomial_degree() >= 0) continue;
        for (const int degree : {3, 5}) {
            const BezierForm f = to_bezier(*c.curve, {.degree = degree, .relative_tolerance = 1e-6});
            ASSERT_TRUE(f.outcome.ok()) << c.name << ": " << f.outcome.message;
            EXPECT_FALSE(f.exact);
            EXPECT_LE(f.max_distance, f.tolerance) << c.name;
            EXPECT_NEAR(f.tolerance, 1e-6 * sampled_diagonal(*c.curve), 1e-20);
            // An independent check: 101 samples per piece, none of them the bound's 32.
            double worst = 0.0;
            for (int i = 0; i < f.pieces.pieces(); ++i) {
                const BezierCurve piece = piece_curve(f.pieces, i);
                for (int j = 1; j < 101; ++j) {
                    const double t = piece.t_min() + (piece.t_max() - piece.t_min()) * (j + 0.37) / 101.37;
                    worst = std::max(worst, (c.curve->point(t) - piece.point(t)).norm());
                }
                // Degree 5 matches the second derivative at both ends, so curvature is exact at the joins.
                if (degree == 5) {
                    const Eigen::MatrixXd a = c.curve->jet(piece.t_min(), 2), b = piece.jet(piece.t_min(), 2);
                    EXPECT_LE((a.row(2) - b.row(2)).norm(), 1e-9 * std::max(1.0, a.row(2).norm()))
                        << c.name << " piece " << i;
                }
            }
            EXPECT_LE(worst, f.tolerance) << c.name << " degree " << degree;
            ++approximated;
        }
    }
    EXPECT_GE(approximated, 2);
}

TEST(BezierForm, RaisedDegreeIsTheSameCurveAndLowerIsApproximated) {
    const methods::InterpolationResult r = methods::interpolate("cubic-b", test::kNewberyGarrett, false);
    const methods::MethodParameterCurve c(*r.interpolant);
    const BezierForm quintic = to_bezier_of_degree(c, 5);
    EXPECT_TRUE(quintic.exact);
    EXPECT_EQ(quintic.pieces.degree, 5);
    EXPECT_LE(relative_jet_difference(c, quintic.pieces), kExactRelative);
    const methods::InterpolationResult s = methods::interpolate("s-spline", test::kNewberyGarrett, false);
    const methods::MethodParameterCurve quartic(*s.interpolant);
    ASSERT_EQ(quartic.polynomial_degree(), 4);
    const BezierForm cubic = to_bezier_of_degree(quartic, 3);
    EXPECT_FALSE(cubic.exact);
    EXPECT_GT(cubic.max_distance, 0.0);
    EXPECT_LE(cubic.max_distance, cubic.tolerance);
    EXPECT_NE(test::invalid_input_message([&] { to_bezier(c, {.degree = 4}); }).find("got 4"), std::string::npos);
}

TEST(BSplineForm, EveryCurveAsOneBSplineWithTheFewestKnots) {
    for (const Case& c : registry_curves()) {
        const BezierForm f = to_bezier(*c.curve);
        const BSplineForm b = to_bspline(f.pieces);
        const BSplineCurve full = bezier_pieces_curve(f.pieces);
        double worst = 0.0, scale = 0.0;
        for (const double t : f.pieces.breaks) scale = std::max(scale, full.point(t).norm());
        for (int i = 0; i < f.pieces.pieces(); ++i)
            for (int j = 0; j < 7; ++j) {
                const double t =
                    f.pieces.breaks[static_cast<std::size_t>(i)] +
                    (f.pieces.breaks[static_cast<std::size_t>(i) + 1] - f.pieces.breaks[static_cast<std::size_t>(i)]) *
                        (j + 0.5) / 7;
                worst = std::max(
                    {worst, (b.curve.point(t) - c.curve->point(t)).norm(), (full.point(t) - c.curve->point(t)).norm()});
            }
        EXPECT_LE(worst, f.exact ? kExactRelative * std::max(1.0, scale) : f.tolerance * 1.0000001) << c.name;
    }
    // The C2 cubic spline keeps simple knots, pchip (C1) double ones, Hermite A (G1 only: C0 in t) triple ones.
    const auto multiplicities = [](const std::string& method) {
        const methods::InterpolationResult r = methods::interpolate(method, test::kNewberyGarrett, false);
        return to_bspline(to_bezier(methods::MethodParameterCurve(*r.interpolant)).pieces).interior_multiplicities;
    };
    EXPECT_EQ(multiplicities("cubic-b"), std::vector<int>(11, 1));
    EXPECT_EQ(multiplicities("boost-pchip"), std::vector<int>(11, 2));
    EXPECT_EQ(multiplicities("hermite-a"), std::vector<int>(11, 3));
}

TEST(BSplineForm, ClosedC2SplineHasAPeriodicForm) {
    const methods::InterpolationResult r = methods::interpolate("cubic-b", closed_octagon(), true);
    const methods::MethodParameterCurve c(*r.interpolant);
    const PeriodicBSpline p = periodic_bspline(to_bezier(c).pieces);
    ASSERT_FALSE(p.knots.empty());
    const Eigen::Index n = p.control.rows();
    EXPECT_EQ(n, 8);  // simple knots at the 8 points, across the closing point too
    ASSERT_EQ(static_cast<Eigen::Index>(p.knots.size()), n + 2 * p.degree + 1);
    Eigen::MatrixXd wrapped(n + p.degree, 2);
    wrapped << p.control, p.control.topRows(p.degree);
    const BSplineCurve periodic(p.degree, p.knots, wrapped);
    EXPECT_DOUBLE_EQ(periodic.t_min(), c.t_min());
    EXPECT_NEAR(periodic.t_max(), c.t_max(), 1e-12 * c.t_max());
    for (int j = 0; j <= 200; ++j) {
        const double t = c.t_min() + (c.t_max() - c.t_min()) * j / 200;
        EXPECT_LE((periodic.point(std::min(t, periodic.t_max())) - c.point(t)).norm(), 1e-12) << "t = " << t;
    }
    // Hermite A is G1, C1 in t only where neighbouring chords are equal, as all of the octagon's
    // are: a periodic form with double knots.
    const methods::InterpolationResult h = methods::interpolate("hermite-a", closed_octagon(), true);
    EXPECT_EQ(periodic_bspline(to_bezier(methods::MethodParameterCurve(*h.interpolant)).pieces).control.rows(), 16);
}

TEST(CurveJson, ADocumentReadsBackBitForBit) {
    const methods::InterpolationResult r = methods::interpolate("hosaka", test::kNewberyGarrett, false, {{"m", "2"}});
    const methods::MethodParameterCurve c(*r.interpolant);
    const BezierForm f = to_bezier(c);
    std::stringstream s;
    const methods::Method& hosaka = methods::find_method("hosaka");
    write_curve_json(
        s, f,
        methods::method_provenance(hosaka, methods::parse_parameter_values("hosaka", hosaka.parameters, {{"m", "2"}}),
                                   test::kNewberyGarrett, false));
    const CurveDocument d = read_curve_json(s, "memory");
    EXPECT_EQ(d.form.pieces.breaks, f.pieces.breaks);
    EXPECT_EQ(d.form.pieces.control, f.pieces.control);  // exact equality: shortest round-trip numbers
    EXPECT_EQ(d.form.pieces.degree, 5);
    EXPECT_EQ(d.provenance.points, test::kNewberyGarrett);
    EXPECT_EQ(d.provenance.parameters.at("m"), "2");
    EXPECT_EQ(d.provenance.parameter, "chord length");
    EXPECT_EQ(d.provenance.registry, methods::registry_fingerprint());
    EXPECT_EQ(d.provenance.registry.size(), 16u);
}

TEST(CurveJson, BadDocumentsAreRefusedNamingTheMember) {
    const auto message = [](const std::string& text) {
        return test::invalid_input_message([&] {
            std::stringstream s(text);
            read_curve_json(s, "doc.json");
        });
    };
    EXPECT_NE(message("{").find("doc.json: not JSON"), std::string::npos);
    EXPECT_NE(message(R"({"format": "other"})").find("\"format\" must be"), std::string::npos);
    const std::string head = R"({"format": "cagd-curve", "format_version": 1, "library_version": "0.1", "registry": "x",
        "method": {"name": "", "parameters": {}, "parameter": "", "closed": false}, "points": [], "dimension": 2, "exact": true,
        "max_distance": 0, "tolerance": 0, )";
    EXPECT_NE(message(head + R"("degree": 1, "breaks": [0, 0], "pieces": [[[0, 0], [1, 1]]]})")
                  .find("breaks must increase (breaks[1])"),
              std::string::npos);
    EXPECT_NE(message(head + R"("degree": 1, "breaks": [0, 1], "pieces": [[[0, 0], [1]]]})")
                  .find("pieces[0][1] must have 2 coordinates"),
              std::string::npos);
    EXPECT_NE(message(head + R"("degree": 99, "breaks": [0, 1], "pieces": []})").find("degree = 99 outside [1, 31]"),
              std::string::npos);
    // Attacks: degree-0 pieces, an overflowing number, a span that overflows, a jump, a string among
    // the coordinates, nesting without end, and more small values than the reader keeps.
    EXPECT_NE(message(head + R"("degree": 0, "breaks": [0, 1, 2], "pieces": [[[0, 0]], [[1, 1]]]})")
                  .find("degree = 0 outside [1, 31]"),
              std::string::npos);
    EXPECT_NE(message(head + R"("degree": 1, "breaks": [0, 1], "pieces": [[[0, 0], [1e400, 1]]]})")
                  .find("doc.json: not JSON (in pieces[0][1][0]): number overflow parsing '1e400'"),
              std::string::npos);
    EXPECT_NE(message(head + R"("degree": 1, "breaks": [-1e308, 1e308], "pieces": [[[0, 0], [1, 1]]]})")
                  .find("breaks spans -1e+308 to 1e+308: the span overflows"),
              std::string::npos);
    EXPECT_NE(message(head + R"("degree": 1, "breaks": [0, 1, 2], "pieces": [[[0, 0], [1, 1]], [[1, 2], [3, 3]]]})")
                  .find("pieces[1] starts at (1, 2), pieces[0] ends at (1, 1): the pieces of a curve must join"),
              std::string::npos);
    EXPECT_NE(message(head + R"("degree": 1, "breaks": [0, 1], "pieces": [[[0, 0], [1, "1"]]]})")
                  .find("pieces[0][1][1] must be a number"),
              std::string::npos);
    EXPECT_NE(message(head + R"("degree": 1, "breaks": [0, 1], "pieces": [[[[0], 0], [1, 1]]]})")
                  .find("pieces[0][0][0] must be a number"),
              std::string::npos);
    EXPECT_NE(message(std::string(100, '[')).find("nested deeper than 64"), std::string::npos);
    std::string many = R"({"format": "cagd-curve", "other": [)";
    for (int i = 0; i < 100'001; ++i) many += "true,";
    EXPECT_NE(message(many).find("more than 100000 values outside the numeric arrays"), std::string::npos);
    EXPECT_NE(message("[1, 2]").find("doc.json: must be a JSON object"), std::string::npos);
}

// The reader keeps the numeric arrays flat and the rest in a small DOM: a document of 10^5 pieces
// reads back bit for bit, and a stream that ends inside the arrays names where.
TEST(CurveJson, LargeDocumentsStreamAndTruncatedOnesNameThePlace) {
    BezierForm f;
    f.exact = true;
    f.pieces.degree = 3;
    const int K = 100'000;
    for (int i = 0; i <= K; ++i) f.pieces.breaks.push_back(i);
    f.pieces.control.resize(4 * K, 2);
    for (int i = 0; i < K; ++i)
        for (int k = 0; k < 4; ++k)
            f.pieces.control.row(4 * i + k) << i + k / 3.0, std::sin(i + k / 3.0) + 1e-7 * (k == 3 ? 0 : k);
    std::stringstream s;
    write_curve_json(s, f, {});
    const std::string text = s.str();
    const CurveDocument d = read_curve_json(s, "big.json");
    EXPECT_EQ(d.form.pieces.control, f.pieces.control);
    EXPECT_EQ(d.form.pieces.breaks, f.pieces.breaks);
    std::stringstream cut(text.substr(0, text.size() / 2));
    const std::string m = test::invalid_input_message([&] { read_curve_json(cut, "cut.json"); });
    EXPECT_NE(m.find("cut.json: not JSON (in pieces["), std::string::npos) << m;
    EXPECT_NE(m.find("unexpected end of input"), std::string::npos) << m;
}

// A writer refuses what a reader would refuse: a non-finite number, named by its member.
TEST(CurveJson, NonFiniteValuesAreNeverWritten) {
    BezierForm f;
    f.pieces.degree = 1;
    f.pieces.breaks = {0, 1};
    f.pieces.control = Eigen::MatrixXd{{0, 0}, {1, std::numeric_limits<double>::infinity()}};
    std::stringstream s;
    EXPECT_NE(test::invalid_input_message([&] { write_curve_json(s, f, {}); }).find("pieces holds inf"),
              std::string::npos);
}

TEST(CurveFormats, ChosenByExtensionAndUnknownOnesAreBadInput) {
    EXPECT_EQ(curve_format_of_path("a/b.SVG"), CurveFormat::svg);
    EXPECT_EQ(curve_format_of_path("c.stp"), CurveFormat::step);
    EXPECT_EQ(curve_format_of_path("-"), CurveFormat::csv);
    EXPECT_EQ(curve_format_of_path("/dev/stdout"), CurveFormat::csv);
    EXPECT_NE(test::invalid_input_message([] { curve_format_of_path("curve.txt"); }).find("unknown extension '.txt'"),
              std::string::npos);
    EXPECT_NE(test::invalid_input_message([] { curve_format_named("pdf"); }).find("unknown format 'pdf'"),
              std::string::npos);
}

TEST(CurveFormats, ACurveThatStandsForAnotherSaysSoWithItsBound) {
    // A peer's pieces that approximate the peer's curve: the document is not exact, and its bound
    // is the pieces' distance from that curve (here the form's own is 0: cubic-b is polynomial).
    const methods::InterpolationResult r = methods::interpolate("cubic-b", test::kNewberyGarrett, false);
    const methods::MethodParameterCurve c(*r.interpolant);
    std::stringstream exact, standing;
    ASSERT_TRUE(write_curve(exact, CurveFormat::json, c, {}, {}).ok());
    ASSERT_TRUE(write_curve(standing, CurveFormat::json, c, {}, {.stands_within = 0.125}).ok());
    const CurveDocument e = read_curve_json(exact, "exact"), s = read_curve_json(standing, "standing");
    EXPECT_TRUE(e.form.exact);
    EXPECT_EQ(e.form.max_distance, 0.0);
    EXPECT_FALSE(s.form.exact);
    EXPECT_EQ(s.form.max_distance, 0.125);
    EXPECT_EQ(s.form.pieces.control, e.form.pieces.control);
    std::stringstream bad;
    EXPECT_NE(test::invalid_input_message([&] {
                  (void)write_curve(bad, CurveFormat::json, c, {}, {.stands_within = -0.5});
              }).find("stands_within must be finite and >= 0, got -0.5"),
              std::string::npos);
}

TEST(CurveFormats, SvgIsACubicPathAndRefusesSpaceCurves) {
    const methods::InterpolationResult r = methods::interpolate("cubic-b", test::kNewberyGarrett, false);
    const methods::MethodParameterCurve c(*r.interpolant);
    std::stringstream s;
    ASSERT_TRUE(
        write_curve(s, CurveFormat::svg, c, {.points = test::kNewberyGarrett}, {.points = true, .comb = true}).ok());
    const std::string svg = s.str();
    std::size_t segments = 0;
    for (std::size_t at = svg.find("\nC"); at != std::string::npos; at = svg.find("\nC", at + 1)) ++segments;
    EXPECT_EQ(segments, 12u);
    EXPECT_NE(svg.find("the curve's exact cubic pieces"), std::string::npos);
    EXPECT_NE(svg.find("id=\"comb\" data-comb-scale=\""), std::string::npos);
    EXPECT_NE(svg.find("<circle"), std::string::npos);
    const methods::InterpolationResult h = methods::interpolate("cubic-b", helix_points(), false);
    const methods::MethodParameterCurve space(*h.interpolant);
    std::stringstream t;
    EXPECT_NE(test::invalid_input_message([&] {
                  (void)write_curve(t, CurveFormat::svg, space, {}, {});
              }).find("svg is planar"),
              std::string::npos);
}

// The comb at the ends of the representable scales: points scaled by 1e-120 wrote 3,988 nan (the
// speed's cube underflowed), by 1e140 teeth of length 0 (it overflowed). A tooth scales with the
// points, the comb's c (tooth = −c κ n) with their square.
TEST(CurveFormats, SvgCombScalesWithThePointsAtAnyRepresentableScale) {
    const auto comb = [](double s, double& c, Eigen::Vector4d& first_tooth) {
        const PointList p = s * test::kNewberyGarrett;
        const methods::InterpolationResult r = methods::interpolate("cubic-b", p, false);
        const methods::MethodParameterCurve curve(*r.interpolant);
        std::stringstream out;
        ASSERT_TRUE(write_curve(out, CurveFormat::svg, curve, {.points = p}, {.comb = true}).ok());
        const std::string svg = out.str();
        EXPECT_EQ(svg.find("nan"), std::string::npos) << "scale " << s;
        EXPECT_EQ(svg.find("inf"), std::string::npos) << "scale " << s;
        const std::size_t at = svg.find("data-comb-scale=\"");
        ASSERT_NE(at, std::string::npos);
        c = std::stod(svg.substr(at + 17));
        std::stringstream teeth(svg.substr(svg.find("d=\"M", at) + 4));
        char l = 0;
        teeth >> first_tooth(0) >> first_tooth(1) >> l >> first_tooth(2) >> first_tooth(3);
        ASSERT_EQ(l, 'L');
    };
    double c1 = 0.0;
    Eigen::Vector4d t1;
    comb(1.0, c1, t1);
    ASSERT_GT((t1.tail<2>() - t1.head<2>()).norm(), 0.0);
    for (const double s : {1e-120, 1e140}) {
        double c = 0.0;
        Eigen::Vector4d t;
        comb(s, c, t);
        EXPECT_NEAR(c / (c1 * s * s), 1.0, 1e-9) << "scale " << s;
        EXPECT_NEAR((t / s - t1).norm(), 0.0, 1e-9 * t1.norm()) << "scale " << s << ": the first tooth";
    }
}

namespace {
// The SPLINE entity's group codes: flags, degree, stated and counted knots and control points,
// and the smallest knot.
struct DxfSplineCounts {
    int knots = 0, controls = 0, flags = -1, degree = -1, nk = -1, nc = -1;
    double first_knot = INFINITY;
};
DxfSplineCounts dxf_spline_counts(const std::string& dxf) {
    std::stringstream entity(dxf.substr(dxf.find("AcDbSpline")));
    std::string line, previous;
    DxfSplineCounts c;
    while (std::getline(entity, line) && line != "ENDSEC") {
        if (previous == " 40") {
            ++c.knots;
            c.first_knot = std::min(c.first_knot, std::stod(line));
        }
        if (previous == " 10") ++c.controls;
        if (previous == " 70") c.flags = std::stoi(line);
        if (previous == " 71") c.degree = std::stoi(line);
        if (previous == " 72") c.nk = std::stoi(line);
        if (previous == " 73") c.nc = std::stoi(line);
        previous = line;
    }
    return c;
}
}  // namespace

TEST(CurveFormats, DxfHoldsOneSplineWithConsistentCounts) {
    // Closed: periodic, the 8 distinct control points and the first 3 again; knots from 0.
    const methods::InterpolationResult r = methods::interpolate("cubic-b", closed_octagon(), true);
    const methods::MethodParameterCurve c(*r.interpolant);
    std::stringstream s;
    ASSERT_TRUE(write_curve(s, CurveFormat::dxf, c, {.closed = true}, {}).ok());
    const DxfSplineCounts closed = dxf_spline_counts(s.str());
    EXPECT_EQ(closed.flags, 1 | 2 | 8);  // closed, periodic, planar
    EXPECT_EQ(closed.degree, 3);
    EXPECT_EQ(closed.knots, closed.nk);
    EXPECT_EQ(closed.controls, closed.nc);
    EXPECT_EQ(closed.nk, closed.nc + closed.degree + 1);
    EXPECT_EQ(closed.nc, 8 + 3);
    EXPECT_EQ(closed.first_knot, 0.0);
    // Open: clamped, p + 1 and one per simple interior knot.
    const methods::InterpolationResult o = methods::interpolate("cubic-b", helix_points(), false);
    std::stringstream so;
    ASSERT_TRUE(write_curve(so, CurveFormat::dxf, methods::MethodParameterCurve(*o.interpolant), {}, {}).ok());
    const DxfSplineCounts open = dxf_spline_counts(so.str());
    EXPECT_EQ(open.flags, 0);  // a space curve: not planar
    EXPECT_EQ(open.nk, open.nc + 4);
    EXPECT_EQ(open.nc, 4 + 7);  // C2 at the 7 inner points of 9
}

TEST(CurveSamples, ArcLengthSamplesAreEquallySpacedInArcLength) {
    const methods::InterpolationResult r = methods::interpolate("hosaka", test::kNewberyGarrett, false);
    const methods::MethodParameterCurve c(*r.interpolant);
    std::stringstream s;
    ASSERT_TRUE(write_curve_samples(s, c, {.arc_length_samples = 11}).ok());
    std::string line;
    std::getline(s, line);
    EXPECT_EQ(line, "t,x,y,dx,dy,ddx,ddy");
    std::vector<double> ts;
    while (std::getline(s, line)) ts.push_back(std::stod(line.substr(0, line.find(','))));
    ASSERT_EQ(ts.size(), 11u);
    const double L = analysis::adaptive_arc_length(c, 1e-12);
    // The t column has 15 digits; |r'| ≤ a few times L / t_max, so each arc is exact to ~1e-13 L.
    for (std::size_t k = 0; k + 1 < ts.size(); ++k)
        EXPECT_NEAR(analysis::arc_length(c, ts[k], ts[k + 1], 8), L / 10, 1e-10 * L)
            << "between samples " << k << " and " << k + 1;
}

TEST(StepExport, ACurveBeyondTheLimitIsRefusedBeforeOpenCascadeSeesIt) {
    // One control point over kMaxStepControlPoints: refused by count, whether or not the library
    // has OpenCASCADE (the check comes first), naming the count and the formats that take it.
    const long n = exports::kMaxStepControlPoints + 1;
    std::vector<double> knots(static_cast<std::size_t>(n + 2));
    for (std::size_t i = 0; i < knots.size(); ++i)
        knots[i] = static_cast<double>(std::min<long>(std::max<long>(static_cast<long>(i), 1), n));
    Eigen::MatrixXd poles(n, 2);
    for (long i = 0; i < n; ++i) poles.row(i) << static_cast<double>(i), 0.0;
    const BSplineCurve line(1, knots, poles);
    std::ostringstream out;
    const std::string message = test::invalid_input_message([&] { exports::write_step(out, line); });
    EXPECT_NE(message.find("the curve has " + std::to_string(n) + " control points; STEP takes at most 2500000"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("JSON, SVG or DXF"), std::string::npos);
    EXPECT_TRUE(out.str().empty());
}
