// The method registry (methods/method_registry.hpp): typed parameters, names, configurations, and
// that every registered method is reachable from each place that lists methods. The command line
// (interpolate, analyze --in, compare) is walked over every method by tests/cli_test.sh.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/finite.hpp"
#include "cagd/core/random_walk.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"

#include "../support/messages.hpp"

using namespace cagd;
using namespace cagd::methods;
using cagd::test::invalid_input_message;

namespace {

PointList wave(int n) {
    PointList p(n, 2);
    for (int i = 0; i < n; ++i) p.row(i) << i, (i % 2 ? 1.0 : 0.0) + 0.1 * i;
    return p;
}

}  // namespace

TEST(Methods, NamesAreUniqueAndFound) {
    std::set<std::string> seen;
    for (const std::string& n : method_names()) {
        EXPECT_TRUE(seen.insert(n).second) << "name given twice: " << n;
        EXPECT_EQ(&find_method(n), &find_method(find_method(n).name)) << n;
    }
    for (const Configuration& c : configurations())
        EXPECT_TRUE(seen.insert(c.name).second || find_method(c.name).presets.empty()) << c.name;
    const std::string m = invalid_input_message([] { find_method("cubic"); });
    EXPECT_NE(m.find("unknown method 'cubic'"), std::string::npos) << m;
    EXPECT_NE(m.find("curvature-profile"), std::string::npos) << "the message lists the known names: " << m;
}

TEST(Methods, EveryRegisteredMethodReachesEveryFront) {
    // compare, the property tests (EveryMethod/*) and fuzz_interpolate iterate configurations():
    // a method without presets appears there under its own name. The command takes its --method
    // choices from method_names() and prints registry_listing() for --list-methods; docs/methods.md
    // is registry_markdown(). The Python module's cagd.methods() equals the command's list
    // (python/tests), and tests/cli_test.sh runs every listed method through interpolate,
    // analyze --in and compare.
    const std::vector<std::string> choices = method_names();
    const std::string listing = registry_listing(), table = registry_markdown();
    for (const Method& m : registry()) {
        EXPECT_NE(std::find(choices.begin(), choices.end(), m.name), choices.end())
            << m.name << " is not a --method choice";
        EXPECT_NE(("\n" + listing).find("\n" + m.name + " "), std::string::npos)
            << m.name << " is not in --list-methods";
        EXPECT_NE(table.find("| `" + m.name + "`"), std::string::npos)
            << m.name << " is not in docs/methods.md's table";
        int found = 0;
        for (const Configuration& c : configurations()) found += c.method == &m;
        EXPECT_GE(found, 1) << m.name << " is not compared";
        if (m.presets.empty()) {
            EXPECT_EQ(find_configuration(m.name).method, &m);
        }
        EXPECT_TRUE(m.claims && m.build) << m.name;
        EXPECT_FALSE(m.paper.empty() || m.source.empty() || m.summary.empty()) << m.name;
    }
    // The configurations are, in registry order, each method's presets or the method itself.
    std::vector<std::string> names, expected;
    for (const Configuration& c : configurations()) names.push_back(c.name);
    for (const Method& m : registry()) {
        if (m.presets.empty()) expected.push_back(m.name);
        for (const Preset& p : m.presets) expected.push_back(p.name);
    }
    EXPECT_EQ(names, expected);
    // The published comparison (results/, committed) has one row per configuration, in this order:
    // a method added to the registry reaches it by the next make reproduce.
    std::ifstream in(std::string(CAGD_SOURCE_DIR) + "/results/pseudo_energy/fig_compare_table1_measures.csv");
    ASSERT_TRUE(in) << "results/pseudo_energy/fig_compare_table1_measures.csv";
    std::string line;
    std::vector<std::string> published;
    std::getline(in, line);  // header
    while (std::getline(in, line)) published.push_back(line.substr(0, line.find(',')));
    EXPECT_EQ(published, names) << "the committed comparison differs from the registry: run make reproduce";
}

TEST(Methods, EveryMethodInterpolatesWithItsDefaults) {
    const PointList p = wave(6);
    for (const Method& m : registry()) {
        const InterpolationResult r = interpolate(m.name, p, false);
        ASSERT_TRUE(r.outcome.ok() && r.interpolant) << m.name << ": " << r.outcome.message;
        const Interpolant& a = *r.interpolant;
        ASSERT_EQ(a.node_parameters.size(), 6u) << m.name;
        for (Eigen::Index i = 0; i < p.rows(); ++i)
            EXPECT_LE((a.curve->point(a.node_parameters[static_cast<std::size_t>(i)]) - p.row(i).transpose()).norm(),
                      1e-9)
                << m.name << " point " << i;
    }
}

// body(which, curve) for each method's curve through wave(6) in u and the same curve in its own
// parameter (MethodParameterCurve, what Python evaluates).
template <class Body>
void for_each_method_curve(Body body) {
    const PointList p = wave(6);
    for (const Method& m : registry()) {
        const InterpolationResult r = interpolate(m.name, p, false);
        ASSERT_TRUE(r.interpolant) << m.name;
        const MethodParameterCurve in_method_parameter(*r.interpolant);
        body(m.name + " (u)", *r.interpolant->curve);
        body(m.name + " (method parameter)", static_cast<const Curve&>(in_method_parameter));
    }
}

TEST(Methods, AllocationFreeJetsEqualTheAllocatingOnes) {
    // Curve::jet_into / derivatives_into (overridden by the piecewise Hermite curves and the
    // method-parameter wrapper, the default elsewhere) give jet() / derivatives() bit for bit, at
    // breakpoints and between them; and derivatives_into is jet_into without its first row, bit
    // for bit (fairness_measures takes one for the other where it needs no position). Each
    // method's curve in u and the same curve in its own parameter (MethodParameterCurve, what
    // Python evaluates).
    for_each_method_curve([](const std::string& which, const Curve& c) {
        JetMatrix J;
        for (int k = 0; k <= 40; ++k) {
            const double t = std::min(c.t_max(), c.t_min() + (c.t_max() - c.t_min()) * k / 40.0);
            for (int order = 0; order < kJetCapacity; ++order) {
                c.jet_into(t, order, J);
                const Eigen::MatrixXd expected = c.jet(t, order);
                ASSERT_EQ(J.rows(), expected.rows()) << which;
                ASSERT_EQ(J.cols(), expected.cols()) << which;
                EXPECT_TRUE((J.array() == expected.array()).all()) << which << " jet, t = " << t << ", order " << order;
            }
            for (int order = 1; order <= kJetCapacity; ++order) {
                c.derivatives_into(t, order, J);
                EXPECT_TRUE((J.array() == c.derivatives(t, order).array()).all())
                    << which << " derivatives, t = " << t << ", order " << order;
                if (order < kJetCapacity) {
                    JetMatrix full;
                    c.jet_into(t, order, full);
                    EXPECT_TRUE((J.array() == full.bottomRows(order).array()).all())
                        << which << " derivatives against the jet, t = " << t << ", order " << order;
                }
            }
        }
        EXPECT_THROW(c.jet_into(c.t_min(), kJetCapacity, J), InvalidInput) << which;
        EXPECT_THROW(c.derivatives_into(c.t_min(), 0, J), InvalidInput) << which;
        EXPECT_THROW(c.jet_into(c.t_max() + 1.0, 1, J), InvalidInput) << which;
    });
}

TEST(Methods, BatchJetsEqualTheJetsOneByOne) {
    // Curve::jets_into (overridden by the piecewise Hermite curves and the method-parameter
    // wrapper, the default elsewhere) writes jet_into's values bit for bit, at every node (the
    // breakpoints of the curve in u, and of the curve in its own parameter), between them and at
    // both ends; blocks longer than the wrapper's own (256) included.
    for_each_method_curve([](const std::string& which, const Curve& c) {
        std::vector<double> t;
        for (int k = 0; k <= 600; ++k)
            t.push_back(std::min(c.t_max(), c.t_min() + (c.t_max() - c.t_min()) * k / 600.0));
        for (const double b : c.breakpoints()) t.push_back(b);
        const int dim = c.dimension();
        for (int order = 0; order < kJetCapacity; ++order) {
            const std::size_t stride = static_cast<std::size_t>((order + 1) * dim);
            std::vector<double> batch(t.size() * stride, std::numeric_limits<double>::quiet_NaN());
            c.jets_into(t.data(), t.size(), order, batch.data());
            JetMatrix J;
            for (std::size_t k = 0; k < t.size(); ++k) {
                c.jet_into(t[k], order, J);
                for (int row = 0; row <= order; ++row)
                    for (int col = 0; col < dim; ++col)
                        ASSERT_EQ(bits_of(batch[k * stride + static_cast<std::size_t>(row * dim + col)]),
                                  bits_of(J(row, col)))
                            << which << ", t = " << t[k] << ", order " << order << ", row " << row << ", column "
                            << col;
            }
        }
        std::vector<double> out(64);
        const double outside[] = {c.t_min(), c.t_max() + 1.0};
        EXPECT_THROW(c.jets_into(outside, 2, 1, out.data()), InvalidInput) << which;
        EXPECT_THROW(c.jets_into(outside, 1, kJetCapacity, out.data()), InvalidInput) << which;
    });
}

TEST(Methods, MethodsPageIsTheRegistry) {
    const auto names = method_names();
    if (std::find(names.begin(), names.end(), "occt-interpolate") == names.end())
        GTEST_SKIP() << "a library without OpenCASCADE: docs/methods.md lists its peer too";
    std::ifstream in(std::string(CAGD_SOURCE_DIR) + "/docs/methods.md");
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string page = ss.str(), table = registry_markdown();
    EXPECT_NE(page.find("<!-- methods:begin -->\n" + table + "<!-- methods:end -->"), std::string::npos)
        << "docs/methods.md's method table differs from the registry: run scripts/update-docs-methods.sh (make "
           "reproduce does)";
    for (const Method& m : registry()) EXPECT_NE(table.find("`" + m.name + "`"), std::string::npos) << m.name;
}

TEST(Methods, ParametersAreCheckedAgainstTheirDeclarations) {
    const Method& s = find_method("s-spline");
    // Defaults are filled in; given() tells them apart from given values.
    const ParameterValues d = parse_parameter_values(s.name, s.parameters, {});
    EXPECT_EQ(d.integer("m"), 2);
    EXPECT_FALSE(d.given("m"));
    EXPECT_EQ(d.text("end"), "natural");
    EXPECT_FALSE(d.has("m-vector"));
    const ParameterValues g = parse_parameter_values(s.name, s.parameters, {{"m", "10"}, {"start-tangent", "1,-2.5"}});
    EXPECT_EQ(g.integer("m"), 10) << "m = 10 (the old name parser read one digit)";
    EXPECT_TRUE(g.given("m"));
    EXPECT_EQ(g.vector("start-tangent"), Eigen::Vector2d(1, -2.5));
    // Each bad value is named with its option and what is allowed.
    const auto bad = [&](const ParameterText& t, const std::string& expected) {
        const std::string m = invalid_input_message([&] { parse_parameter_values(s.name, s.parameters, t); });
        EXPECT_NE(m.find(expected), std::string::npos) << m;
    };
    bad({{"m", "-1"}}, "--m '-1': out of range; allowed: integer in [0, 1000]");
    bad({{"m", "2.5"}}, "--m '2.5': not a whole number");
    bad({{"m", "two"}}, "--m 'two': not a number");
    bad({{"m", "inf"}}, "--m 'inf': not finite");
    bad({{"end", "clamped"}}, "--end 'clamped': not a choice; allowed: one of natural | tangent | bessel");
    bad({{"start-tangent", "1,x"}}, "'x' is not a number");
    bad({{"scale", "unit"}}, "--scale is not a parameter of s-spline");
    const Method& boost = find_method("boost-pchip");
    const std::string none = invalid_input_message([&] {
        parse_parameter_values(boost.name, boost.parameters, {{"m", "1"}});
    });
    EXPECT_NE(none.find("it has none"), std::string::npos) << none;
}

TEST(Methods, BuildersCheckCombinationsOfParameters) {
    const PointList p = wave(5);
    std::string m = invalid_input_message([&] { interpolate("s-spline", p, false, {{"end", "tangent"}}); });
    EXPECT_NE(m.find("--end tangent needs --start-tangent and --end-tangent"), std::string::npos) << m;
    m = invalid_input_message([&] {
        interpolate("hosaka", p, false, {{"start-tangent", "1,0"}, {"end-tangent", "1,0"}});
    });
    EXPECT_NE(m.find("--start-tangent applies with --end tangent only"), std::string::npos) << m;
    m = invalid_input_message([&] { interpolate("s-spline", p, false, {{"m", "1"}, {"m-vector", "1,1,1,1"}}); });
    EXPECT_NE(m.find("give --m or --m-vector, not both"), std::string::npos) << m;
    m = invalid_input_message([&] { interpolate("curvature-profile", p, false, {{"degree", "3"}}); });
    EXPECT_NE(m.find("--degree applies to a --knots list"), std::string::npos) << m;
    m = invalid_input_message([&] { interpolate("hosaka", p, false, {{"m", "31"}}); });
    EXPECT_NE(m.find("--m '31': out of range; allowed: integer in [1, 30]"), std::string::npos) << m;
    // A preset's values can be overridden by name.
    const InterpolationResult r1 = interpolate("s-spline-m1", p, false),
                              r4 = interpolate("s-spline-m1", p, false, {{"m", "4"}});
    const InterpolationResult s4 = interpolate("s-spline", p, false, {{"m", "4"}});
    EXPECT_GT(analysis::max_distance_same_parameter(*r1.interpolant->curve, *r4.interpolant->curve), 1e-6);
    EXPECT_EQ(analysis::max_distance_same_parameter(*s4.interpolant->curve, *r4.interpolant->curve), 0.0);
}

TEST(Methods, ClaimsFollowTheParameters) {
    const Method& h = find_method("hosaka");
    EXPECT_EQ(h.claims(parse_parameter_values(h.name, h.parameters, {{"scale", "unit"}})).invariance,
              Invariance::affine);
    EXPECT_EQ(h.claims(parse_parameter_values(h.name, h.parameters, {})).parameter, "chord length");
    // Open-only methods refuse closed curves, naming the method.
    const std::string m = invalid_input_message([] { interpolate("boost-pchip", wave(6), true); });
    EXPECT_NE(m.find("(boost-pchip): open curves only; got "), std::string::npos) << m;
}

// `cubic-bspline` (sb2_locality eq 10) is an alias of cubic-a (pseudo_energy sec 4.2): the same
// natural uniform C2 cubic, here in B-spline and there in Hermite form.
TEST(Methods, CubicBsplineAliasIsCubicA) {
    for (bool closed : {false, true}) {
        const PointList p = wave(7);
        const InterpolationResult a = interpolate("cubic-bspline", p, closed);
        const BSplineCurve b = locality::cubic_bspline_interpolant(p, closed);
        EXPECT_LE(analysis::max_distance_same_parameter(*a.interpolant->curve, b), 1e-13)
            << (closed ? "closed" : "open");
    }
}

TEST(Methods, PseudoSplineReportsTableQuantities) {
    const InterpolationResult r = interpolate("pseudo-spline", wave(5), false);
    ASSERT_EQ(r.quantities.size(), 3u);
    EXPECT_EQ(r.quantities[0].first, "length_from_tables");
    // eq (16)-(17) from the 36-node table vs the integrated curve differ by the table's interpolation
    // error: measured 1.4e-3 relative on these points, bounded by 3e-3.
    EXPECT_NEAR(r.quantities[0].second, analysis::arc_length(*r.interpolant->curve, 16), 3e-3 * r.quantities[0].second);
}

TEST(Methods, CurvatureProfileLogsNewton) {
    const InterpolationResult r = interpolate("curvature-profile", wave(5), false);
    ASSERT_TRUE(r.outcome.ok()) << r.outcome.message;
    ASSERT_GE(r.report.size(), 5u);
    EXPECT_EQ(r.report.front().first, "newton_0_residual");
    EXPECT_EQ(r.report.back().first, "knot_difference_list");
    EXPECT_EQ(r.report.back().second.rfind("{0, ", 0), 0u) << r.report.back().second;
}

namespace {
// The largest distance between two curves at the same fractions k/64 of their parameter domains
// (a warm and a cold solve of one method: their arc-length domains differ by the solver's tolerance).
double largest_gap_at_same_fractions(const InterpolationResult& a, const InterpolationResult& b) {
    double largest = 0.0;
    for (int k = 0; k <= 64; ++k) {
        const double t = static_cast<double>(k) / 64.0;
        const Curve &ca = *a.interpolant->curve, &cb = *b.interpolant->curve;
        const double ua = ca.t_min() + t * (ca.t_max() - ca.t_min()), ub = cb.t_min() + t * (cb.t_max() - cb.t_min());
        largest = std::max(largest, (ca.jet(ua, 0).row(0) - cb.jet(ub, 0).row(0)).norm());
    }
    return largest;
}
}  // namespace

// On points validated once (compare's path), every configuration builds the curve the PointList
// path builds, bit for bit, open and closed, and refuses what its claims exclude.
TEST(Methods, EveryConfigurationOnValidPointsIsThePointListBuild) {
    for (const bool closed : {false, true}) {
        PointList p(9, 2);
        for (Eigen::Index i = 0; i < p.rows(); ++i) {
            const double a = 2.0 * 3.141592653589793 * static_cast<double>(i) / static_cast<double>(p.rows());
            p.row(i) << (2.0 + 0.3 * std::sin(3.0 * a)) * std::cos(a), (1.5 + 0.2 * std::cos(2.0 * a)) * std::sin(a);
        }
        const ValidPoints valid = validate_points(p, 2, closed, "test");
        int built = 0;
        for (const Configuration& c : configurations()) {
            const std::string what = c.name + (closed ? ", closed" : ", open");
            if (!method_applicability(c.claims, p, closed).empty()) {
                EXPECT_THROW((void)interpolate_from(c, valid), InvalidInput) << what;
                continue;
            }
            const InterpolationResult a = interpolate(c, p, closed), b = interpolate_from(c, valid);
            ASSERT_EQ(a.outcome.ok(), b.outcome.ok())
                << what << ": " << a.outcome.message << " / " << b.outcome.message;
            if (!a.outcome.ok()) continue;
            EXPECT_EQ(a.interpolant->node_parameters, b.interpolant->node_parameters) << what;
            EXPECT_EQ(largest_gap_at_same_fractions(a, b), 0.0) << what;
            ++built;
        }
        EXPECT_GE(built, 10) << (closed ? "closed" : "open");
    }
    // Fewer points than a method needs: refused as from a PointList, naming the count.
    PointList two(2, 2);
    two << 0, 0, 1, 1;
    const std::string m = invalid_input_message(
        [&] { (void)interpolate_from(find_configuration("cubic-b"), validate_points(two, 2, true, "test")); });
    EXPECT_NE(m.find("got 2 points of a closed curve"), std::string::npos) << m;
}

// A rebuild on moved points starts from the first solve's final iterate: it converges in fewer
// Newton iterations to the cold solve's curve (within the solver's tolerance), for 300 points
// (sparse-LU steps) and for 12 (Moore–Penrose), open and closed; methods without a rebuild build anew.
TEST(Methods, CurvatureProfileRebuildsFromAnEarlierSolution) {
    const auto iterations = [](const InterpolationResult& r) {
        return std::count_if(r.report.begin(), r.report.end(),
                             [](const auto& q) { return q.first.ends_with("_residual"); });
    };
    const Configuration cp = find_configuration("curvature-profile");
    for (const long n : {12L, 300L})
        for (const bool closed : {false, true}) {
            PointList p = random_walk(n, 3, 0.5, 1.5, 0.6);
            if (closed)  // a wavy loop
                for (Eigen::Index i = 0; i < n; ++i) {
                    const double a = 2.0 * 3.141592653589793 * static_cast<double>(i) / static_cast<double>(n);
                    const double r = static_cast<double>(n) * (1.0 + 0.3 * std::sin(5.0 * a));
                    p.row(i) << r * std::cos(a), r * std::sin(a);
                }
            const InterpolationResult first = interpolate(cp, p, closed);
            ASSERT_TRUE(first.outcome.ok()) << first.outcome.message;
            ASSERT_GT(first.solver_state.size(), 0) << "the final iterate is kept";
            PointList moved = p;
            moved(n / 2, 1) += 1e-3;
            const InterpolationResult cold = interpolate(cp, moved, closed),
                                      warm = interpolate_from(cp, moved, closed, first.solver_state);
            ASSERT_TRUE(cold.outcome.ok() && warm.outcome.ok()) << cold.outcome.message << warm.outcome.message;
            EXPECT_LT(iterations(warm), iterations(cold)) << n << (closed ? " closed" : " open");
            EXPECT_LT(largest_gap_at_same_fractions(cold, warm), 1e-9)
                << "the warm solution is the cold one: " << n << (closed ? " closed" : " open");
            // Without a rebuild (cubic-b) the state is empty and interpolate_from builds anew.
            const InterpolationResult direct = interpolate(find_configuration("cubic-b"), p, closed);
            EXPECT_EQ(direct.solver_state.size(), 0);
        }
}

// Spiro's rebuild: on open points the arc-length Newton alone from the earlier solution (the
// chordwise Newton not run), reaching the cold solve's curve; a closed curve is solved anew.
TEST(Methods, SpiroRebuildsOpenCurvesFromAnEarlierSolution) {
    const Configuration spiro = find_configuration("spiro");
    const auto chordwise = [](const InterpolationResult& r) {
        for (const auto& [name, value] : r.report)
            if (name == "chordwise_newton_iterations") return std::stoi(value);
        return -1;
    };
    for (const bool closed : {false, true}) {
        PointList p(40, 2);
        for (Eigen::Index i = 0; i < p.rows(); ++i) {
            const double a = 2.0 * 3.141592653589793 * static_cast<double>(i) / static_cast<double>(p.rows());
            if (closed)
                p.row(i) << 10 * std::cos(a) * (1 + 0.2 * std::sin(3 * a)),
                    10 * std::sin(a) * (1 + 0.2 * std::sin(3 * a));
            else
                p.row(i) << static_cast<double>(i), std::sin(0.7 * static_cast<double>(i));
        }
        const InterpolationResult first = interpolate(spiro, p, closed);
        ASSERT_TRUE(first.outcome.ok()) << first.outcome.message;
        ASSERT_GT(first.solver_state.size(), 0);
        PointList moved = p;
        moved(20, 1) += 1e-3;
        const InterpolationResult cold = interpolate(spiro, moved, closed),
                                  warm = interpolate_from(spiro, moved, closed, first.solver_state);
        ASSERT_TRUE(cold.outcome.ok() && warm.outcome.ok()) << cold.outcome.message << warm.outcome.message;
        EXPECT_GT(chordwise(cold), 0);
        if (closed)
            EXPECT_EQ(chordwise(warm), chordwise(cold)) << "closed: solved anew";
        else
            EXPECT_EQ(chordwise(warm), 0) << "open: the arc-length Newton alone";
        EXPECT_LT(largest_gap_at_same_fractions(cold, warm), 1e-9) << (closed ? "closed" : "open");
    }
}

// A start from which Newton does not contract (the points moved too far: here one point by five
// chords) is abandoned for the design's own start: the outcome and the curve are the cold solve's.
TEST(Methods, InterpolateFromAFarStartSolvesFromTheDesignsOwn) {
    const Configuration cp = find_configuration("curvature-profile");
    const PointList p = random_walk(60, 3, 0.5, 1.5, 1.0);
    const InterpolationResult first = interpolate(cp, p, false);
    ASSERT_TRUE(first.outcome.ok()) << first.outcome.message;
    PointList moved = p;
    moved(30, 1) += 5.0;
    const InterpolationResult cold = interpolate(cp, moved, false),
                              warm = interpolate_from(cp, moved, false, first.solver_state);
    ASSERT_TRUE(cold.outcome.ok()) << cold.outcome.message;
    ASSERT_TRUE(warm.outcome.ok()) << warm.outcome.message;
    double largest = 0.0;
    for (int k = 0; k <= 64; ++k) {
        const double uc = cold.interpolant->curve->t_min() +
                          k / 64.0 * (cold.interpolant->curve->t_max() - cold.interpolant->curve->t_min());
        const double uw = warm.interpolant->curve->t_min() +
                          k / 64.0 * (warm.interpolant->curve->t_max() - warm.interpolant->curve->t_min());
        largest = std::max(
            largest, (cold.interpolant->curve->jet(uc, 0).row(0) - warm.interpolant->curve->jet(uw, 0).row(0)).norm());
    }
    EXPECT_LT(largest, 1e-9);
}

// Valid points whose arithmetic leaves double precision are an outcome, not bad input, and not
// said to "coincide".
TEST(Methods, OverflowAndUnderflowAreOutcomes) {
    PointList huge(4, 2), tiny(4, 2);
    huge << 0, 0, 1e308, 1e308, -1e308, 1e308, 1e308, -1e308;
    tiny << 0, 0, 1e-300, 0, 2e-300, 1e-300, 3e-300, 0;
    for (const Method& m : registry()) {
        const InterpolationResult h = interpolate(m.name, huge, false), t = interpolate(m.name, tiny, false);
        EXPECT_EQ(h.outcome.status, Status::not_representable) << m.name;
        EXPECT_NE(h.outcome.message.find("overflow"), std::string::npos) << h.outcome.message;
        EXPECT_EQ(t.outcome.status, Status::not_representable) << m.name;
        EXPECT_NE(t.outcome.message.find("differ by 1e-300 at most"), std::string::npos) << t.outcome.message;
    }
    // fuzz_interpolate: Boost's centripetal Catmull-Rom read past its knots when a chord overflowed.
    PointList found(4, 2);
    found << -2.5637160159163056e-69, -2.563716015893285e-69, -2.463211248477931e-69, -4.634680644701329e+158,
        -4.556343627664677e+100, -4.634630171264599e+158, -4.0672354653460985e+289, 8.145974672594263e-260;
    EXPECT_EQ(interpolate("boost-catmull-rom", found, false).outcome.status, Status::not_representable);
}
