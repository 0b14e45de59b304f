// The space pseudo-energy (pseudo_energy section 6, extended to space): the 3-D unit-chord segment, its energies and
// the minimum of J = L²E over r0, r1; checked against the planar segment at φ = 0 and π, its symmetries, finite
// differences, the generic analysis module and the reference path.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"
#include "cagd/fairness/space_pseudo_energy.hpp"
#include "cagd/spline/bezier.hpp"

using namespace cagd;
using namespace cagd::fairness;

namespace {
const double kAngles[][2] = {
    {0.3, 0.7}, {1.2, 2.5}, {2.9, 0.4}, {0.8, 0.8}, {std::numbers::pi / 2, std::numbers::pi / 3}};
}  // namespace

TEST(SpacePseudoEnergy, PlanarAtPhiZeroAndPi) {
    for (const auto& a : kAngles) {
        // φ = 0 is the planar (θ0, θ1), φ = π the planar (θ0, −θ1).
        for (const auto& [phi, sign] : {std::pair{0.0, 1.0}, {std::numbers::pi, -1.0}}) {
            const SpacePseudoEnergyMinimum s = minimize_space_pseudo_energy(a[0], a[1], phi);
            const PseudoEnergyMinimum p = minimize_pseudo_energy(a[0], sign * a[1]);
            ASSERT_TRUE(s.outcome.ok()) << s.outcome.message;
            ASSERT_TRUE(p.outcome.ok()) << p.outcome.message;
            EXPECT_NEAR(s.pseudo_energy, p.pseudo_energy, 1e-12 * (1 + p.pseudo_energy))
                << a[0] << " " << a[1] << " " << phi;
            EXPECT_NEAR(s.r0, p.r0, 1e-12 * p.r0);
            EXPECT_NEAR(s.r1, p.r1, 1e-12 * p.r1);
            EXPECT_NEAR(s.length, p.length, 1e-12);
            EXPECT_EQ(s.type, p.type);
        }
    }
}

TEST(SpacePseudoEnergy, SegmentEnergiesEqualThePlanarOnesAndTheGenericQuadrature) {
    const double r0 = 0.9, r1 = 1.3;
    for (const auto& a : kAngles) {
        const SegmentEnergy s = space_segment_energy_fast(SpaceUnitChordHermite(a[0], a[1], 0.0, r0, r1));
        const SegmentEnergy p = segment_energy_fast(UnitChordHermite(a[0], a[1], r0, r1));
        EXPECT_NEAR(s.pseudo_energy, p.pseudo_energy, 1e-14 * p.pseudo_energy);
        EXPECT_NEAR(s.dj_dlog_r0, p.dj_dlog_r0, 1e-13 * (1 + std::abs(p.dj_dlog_r0)));
        // A true space segment against analysis/ on the same cubic as a Bézier curve (independent
        // curvature formula and adaptive quadrature).
        const SpaceUnitChordHermite seg(a[0], a[1], 1.1, r0, r1);
        Eigen::MatrixXd cp(4, 3);
        cp.row(0).setZero();
        cp.row(1) = (r0 * seg.u0() / 3.0).transpose();
        cp.row(2) = (Eigen::Vector3d(1, 0, 0) - r1 * seg.u1() / 3.0).transpose();
        cp.row(3) << 1, 0, 0;
        const BezierCurve bez(cp);
        EXPECT_NEAR((bez.point(0.37) - seg.position(0.37)).norm(), 0.0, 1e-15);
        const SegmentEnergy e = space_segment_energy_fast(seg);
        EXPECT_NEAR(e.length, analysis::arc_length(bez, 64), 1e-12);
        EXPECT_NEAR(e.strain_energy, analysis::bending_energy(bez, 64), 1e-10 * e.strain_energy);
        // The reference path (Romberg) agrees with the fast one.
        const SegmentEnergy ref = space_segment_energy_reference(seg);
        EXPECT_NEAR(ref.pseudo_energy, e.pseudo_energy, 1e-12 * e.pseudo_energy);
    }
}

TEST(SpacePseudoEnergy, GradientMatchesCentralDifferences) {
    const double h = 1e-6;
    for (const auto& a : kAngles)
        for (double phi : {0.4, 2.0, 4.5}) {
            const double r0 = 0.8, r1 = 1.1;
            const SegmentEnergy e = space_segment_energy_fast(SpaceUnitChordHermite(a[0], a[1], phi, r0, r1));
            const auto J = [&](double x0, double x1) {
                return space_segment_energy_fast(SpaceUnitChordHermite(a[0], a[1], phi, std::exp(x0), std::exp(x1)),
                                                 false)
                    .pseudo_energy;
            };
            const double g0 = (J(std::log(r0) + h, std::log(r1)) - J(std::log(r0) - h, std::log(r1))) / (2 * h);
            const double g1 = (J(std::log(r0), std::log(r1) + h) - J(std::log(r0), std::log(r1) - h)) / (2 * h);
            EXPECT_NEAR(e.dj_dlog_r0, g0, 1e-7 * (1 + std::abs(g0)));
            EXPECT_NEAR(e.dj_dlog_r1, g1, 1e-7 * (1 + std::abs(g1)));
        }
}

TEST(SpacePseudoEnergy, SymmetriesReflectionAndReversal) {
    for (const auto& a : kAngles)
        for (double phi : {0.5, 1.7, 2.6}) {
            const SpacePseudoEnergyMinimum m = minimize_space_pseudo_energy(a[0], a[1], phi);
            // Reflection in the x–y plane: φ → 2π − φ.
            const SpacePseudoEnergyMinimum refl = minimize_space_pseudo_energy(a[0], a[1], 2 * std::numbers::pi - phi);
            EXPECT_NEAR(refl.pseudo_energy, m.pseudo_energy, 1e-12 * m.pseudo_energy);
            EXPECT_NEAR(refl.r0, m.r0, 1e-9 * m.r0);
            // Reversal: (θ0, θ1, φ) → (θ1, θ0, φ), r0 ↔ r1.
            const SpacePseudoEnergyMinimum rev = minimize_space_pseudo_energy(a[1], a[0], phi);
            EXPECT_NEAR(rev.pseudo_energy, m.pseudo_energy, 1e-12 * m.pseudo_energy);
            EXPECT_NEAR(rev.r0, m.r1, 1e-9 * m.r1);
            EXPECT_NEAR(rev.r1, m.r0, 1e-9 * m.r0);
            EXPECT_NEAR(rev.length, m.length, 1e-12);
        }
}

TEST(SpacePseudoEnergy, FastAgreesWithReferenceOnRandomDirections) {
    std::mt19937 rng(26);
    std::uniform_real_distribution<double> theta(0.05, std::numbers::pi - 0.05), phi(0.0, 2 * std::numbers::pi);
    for (int k = 0; k < 3; ++k) {
        const double t0 = theta(rng), t1 = theta(rng), p = phi(rng);
        const SpacePseudoEnergyMinimum f = minimize_space_pseudo_energy(t0, t1, p);
        const SpacePseudoEnergyMinimum r = minimize_space_pseudo_energy_reference(t0, t1, p);
        ASSERT_TRUE(f.outcome.ok() && r.outcome.ok());
        EXPECT_NEAR(f.pseudo_energy, r.pseudo_energy, 1e-10 * (1 + r.pseudo_energy)) << t0 << " " << t1 << " " << p;
        EXPECT_NEAR(f.r0, r.r0, 1e-6 * r.r0);
        EXPECT_NEAR(f.r1, r.r1, 1e-6 * r.r1);
        EXPECT_NEAR(f.length, r.length, 1e-10);
    }
}

TEST(SpacePseudoEnergy, TypesAndUndefinedDirectionsAndBadInput) {
    // The type is the planar eq (14) in the plane and the binormal rule in space.
    EXPECT_EQ(SpaceUnitChordHermite(0.5, 0.5, std::numbers::pi, 1, 1).type(),
              SegmentType::c);                                                     // planar (0.5, −0.5): an arc
    EXPECT_EQ(SpaceUnitChordHermite(0.5, 0.5, 0.0, 1, 1).type(), SegmentType::s);  // planar (0.5, 0.5): an S
    const SpacePseudoEnergyMinimum straight = minimize_space_pseudo_energy(0.0, 0.0, 1.0);
    EXPECT_EQ(straight.outcome.status, Status::no_solution);
    EXPECT_EQ(straight.pseudo_energy, 0.0);
    EXPECT_EQ(minimize_space_pseudo_energy(std::numbers::pi, 0.0, 2.0).outcome.status, Status::no_solution);
    EXPECT_THROW(SpaceUnitChordHermite(-0.1, 1, 1, 1, 1), InvalidInput);
    EXPECT_THROW(SpaceUnitChordHermite(0.1, 3.5, 1, 1, 1), InvalidInput);
    EXPECT_THROW(SpaceUnitChordHermite(0.1, 1, 7, 1, 1), InvalidInput);
    EXPECT_THROW(SpaceUnitChordHermite(0.1, 1, NAN, 1, 1), InvalidInput);
    EXPECT_THROW(SpaceUnitChordHermite(0.1, 1, 1, 0, 1), InvalidInput);
    EXPECT_THROW(minimize_space_pseudo_energy(0.1, 1.0, -1.0), InvalidInput);
}

// ---- the 3-D table (part 2) -------------------------------------------------------------------

#include <sstream>

#include "cagd/fairness/space_pseudo_energy_table.hpp"

TEST(SpacePseudoEnergyTable, SameBytesForAnyThreadCountAndRoundTrip) {
    const SpaceAngleGrid g{6, 8};
    std::ostringstream one, three;
    SpacePseudoEnergyTable::build(g, TableMethod::fast, 1).save(one);
    const SpacePseudoEnergyTable t = SpacePseudoEnergyTable::build(g, TableMethod::fast, 3);
    t.save(three);
    EXPECT_EQ(one.str(), three.str());
    const std::string path = (std::filesystem::temp_directory_path() / "cagd_space_table_test.txt").string();
    t.save(path);
    std::ostringstream again;
    SpacePseudoEnergyTable::load(path).save(again);
    EXPECT_EQ(again.str(), three.str());
    std::ofstream(path) << "# something else\n";
    EXPECT_THROW(SpacePseudoEnergyTable::load(path), InvalidInput);
    std::filesystem::remove(path);
}

TEST(SpacePseudoEnergyTable, NodesSymmetriesAndThePlane) {
    const SpaceAngleGrid g{6, 8};
    const SpacePseudoEnergyTable t = SpacePseudoEnergyTable::build(g, TableMethod::fast, 2);
    const std::vector<double> th = g.theta_nodes(), ph = g.phi_nodes();
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            for (int k = 0; k < 8; ++k) {
                const SpaceTableValue& v = t.node(i, j, k);
                // Lookup at a node returns the node; the filled symmetric nodes equal direct minima.
                const SpaceTableValue l = t.lookup(th[i], th[j], ph[k]);
                EXPECT_NEAR(l.pseudo_energy, v.pseudo_energy, 1e-12 * v.pseudo_energy);
                if ((i + j + k) % 7 == 0) {
                    const SpacePseudoEnergyMinimum m = minimize_space_pseudo_energy(th[i], th[j], ph[k]);
                    EXPECT_NEAR(m.pseudo_energy, v.pseudo_energy, 1e-10 * v.pseudo_energy) << i << j << k;
                    EXPECT_NEAR(m.r0, v.r0, 1e-6 * v.r0);
                }
            }
    // φ = 0 is the planar table's direction pair (θ0, θ1).
    const PseudoEnergyMinimum p = minimize_pseudo_energy(th[1], th[4]);
    EXPECT_NEAR(t.node(1, 4, 0).pseudo_energy, p.pseudo_energy, 1e-12 * p.pseudo_energy);
    // φ is periodic; θ outside [0, π] is refused.
    EXPECT_NEAR(t.lookup(1.0, 2.0, 0.3).pseudo_energy, t.lookup(1.0, 2.0, 0.3 + 2 * std::numbers::pi).pseudo_energy,
                1e-12);
    EXPECT_THROW(t.lookup(-0.1, 1.0, 0.0), InvalidInput);
    EXPECT_THROW(t.lookup(1.0, 1.0, NAN), InvalidInput);
    EXPECT_THROW(SpacePseudoEnergyTable::build({6, 7}, TableMethod::fast, 1), InvalidInput);
}

TEST(SpacePseudoEnergyTable, InterpolationErrorFallsWithTheGrid) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> theta(0.4, std::numbers::pi - 0.4), phi(0.0, 2 * std::numbers::pi);
    std::vector<std::array<double, 4>> probes;  // θ0, θ1, φ, exact J
    while (probes.size() < 30) {
        const double a = theta(rng), b = theta(rng), c = phi(rng);
        const SpacePseudoEnergyMinimum m = minimize_space_pseudo_energy(a, b, c);
        if (m.outcome.ok()) probes.push_back({a, b, c, m.pseudo_energy});
    }
    double err[2] = {0, 0};
    int level = 0;
    for (const SpaceAngleGrid g : {SpaceAngleGrid{8, 16}, SpaceAngleGrid{16, 32}}) {
        const SpacePseudoEnergyTable t = SpacePseudoEnergyTable::build(g, TableMethod::fast, 2);
        for (const auto& p : probes)
            err[level] = std::max(err[level], std::abs(t.lookup(p[0], p[1], p[2]).pseudo_energy - p[3]) / p[3]);
        ++level;
    }
    EXPECT_LT(err[1], 0.5 * err[0]) << err[0] << " " << err[1];
    RecordProperty("relative_error_8_16", std::to_string(err[0]) + " " + std::to_string(err[1]));
    EXPECT_LT(err[1], 0.1);
}

// ---- the space pseudo-spline (part 3) ---------------------------------------------------------

#include "cagd/core/point_csv.hpp"
#include "cagd/fairness/space_pseudo_spline.hpp"

namespace {
// Exact segments, J(θ) from the 36-node fast tables (ExactOracle's J(θ) costs 0.15 s a value).
const SegmentOracle& hybrid() {
    static const PseudoSplineTables tables =
        PseudoSplineTables::from(PseudoEnergyTable::build({36, NodePlacement::periodic}, TableMethod::fast, 2));
    static const TableOracle angles = tables.oracle();
    static const ExactSegmentOracle h(angles);
    return h;
}
}  // namespace

TEST(SpacePseudoSpline, FarEndOptimumIsPlanarAndJOfThetaGrows) {
    // (a) of space_pseudo_spline.hpp: over φ the energy is least at φ = 0 or π.
    for (double t0 : {0.3, 1.0, 2.0})
        for (double t1 : {0.4, 1.3, 2.6}) {
            const double plane = std::min(minimize_space_pseudo_energy(t0, t1, 0.0).pseudo_energy,
                                          minimize_space_pseudo_energy(t0, t1, std::numbers::pi).pseudo_energy);
            for (int k = 1; k < 12; ++k)
                EXPECT_GE(minimize_space_pseudo_energy(t0, t1, std::numbers::pi * k / 6).pseudo_energy,
                          plane * (1 - 1e-12))
                    << t0 << " " << t1 << " " << k;
        }
    // (b): J(θ) grows on [0, π].
    double prev = -1.0;
    for (int k = 0; k <= 36; ++k) {
        const double j = hybrid().angle_energy(std::numbers::pi * k / 36 * 0.999);
        EXPECT_GT(j, prev) << k;
        prev = j;
    }
}

TEST(SpacePseudoSpline, PlanarPointsGiveThePlanarPseudoSpline) {
    const PointList p = read_points_csv(std::string(CAGD_SOURCE_DIR) + "/reference/pseudo_energy/data/table1.csv");
    const ExactSpaceOracle space(hybrid());
    for (bool closed : {false, true})
        for (TangentOptimization mode :
             {TangentOptimization::none, TangentOptimization::exact, TangentOptimization::approximate}) {
            const PseudoSpline plane = pseudo_spline(p, hybrid(), mode, closed);
            const SpacePseudoSpline s = space_pseudo_spline(p, space, mode, closed);
            const double scale = bounding_box_diagonal(p);
            for (int k = 0; k <= 400; ++k) {
                const double u = plane.curve.t_max() * k / 400;
                const Eigen::VectorXd a = plane.curve.point(u), b = s.curve.point(u);
                // Exact mode: Brent stops at a relative 2^-26 of the tangent angle (method_registry.hpp), and
                // the two constructions evaluate w at different angles (signed in the plane, turned in space).
                const double tol = mode == TangentOptimization::exact ? 1e-7 : 1e-12;
                EXPECT_NEAR((b.head<2>() - a).norm(), 0.0, tol * scale)
                    << to_string(mode) << " closed " << closed << " u " << u;
                EXPECT_EQ(b(2), 0.0);
            }
            EXPECT_NEAR(s.length_from_tables(), plane.length_from_tables(), 1e-9 * plane.length_from_tables());
        }
}

TEST(SpacePseudoSpline, InterpolatesIsInvariantAndInPlaneOptimal) {
    // A space polygon (a sampled helix with a kink), open.
    PointList p(9, 3);
    for (int i = 0; i < 9; ++i) p.row(i) << std::cos(0.7 * i), std::sin(0.7 * i), 0.25 * i + (i == 4 ? 0.3 : 0.0);
    const ExactSpaceOracle space(hybrid());
    const SpacePseudoSpline s = space_pseudo_spline(p, space, TangentOptimization::exact, false);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR((s.curve.point(i) - p.row(i).transpose()).norm(), 0.0, 1e-12);
    // The tangent minimises w over the sphere: random directions never do better.
    std::mt19937 rng(5);
    std::normal_distribution<double> N;
    for (int i = 1; i < 8; ++i) {
        const Eigen::Vector3d in = (p.row(i) - p.row(i - 1)).transpose(), out = (p.row(i + 1) - p.row(i)).transpose();
        const auto w = [&](const Eigen::Vector3d& t) {
            const auto ang = [&](const Eigen::Vector3d& c) { return std::atan2(c.cross(t).norm(), c.dot(t)); };
            return in.norm() * hybrid().angle_energy(ang(in)) + out.norm() * hybrid().angle_energy(ang(out));
        };
        const double best = w(s.tangent[static_cast<std::size_t>(i)]);
        for (int k = 0; k < 2000; ++k) {
            const Eigen::Vector3d t = Eigen::Vector3d(N(rng), N(rng), N(rng)).normalized();
            EXPECT_GE(w(t), best * (1 - 1e-9)) << "point " << i;
        }
    }
    // Similarity: rotate, scale and translate the points; the curve follows. With the tables' J(θ)
    // (linear between nodes) w can be flat over an interval, where Brent's answer is decided by
    // rounding; a smooth J(θ) isolates the construction: J(θ) = θ²(1 + θ²/10), θ1(θ) = −θ/2.
    struct SmoothJ final : SegmentOracle {
        TableValue segment(double t0, double t1) const override { return ExactOracle{}.segment(t0, t1); }
        std::pair<double, double> angle_minimum(double t) const override { return {angle_energy(t), -t / 2}; }
        double angle_energy(double t) const override { return t * t * (1 + t * t / 10); }
    } smooth;
    const ExactSpaceOracle smooth_space(smooth);
    const SpacePseudoSpline sm = space_pseudo_spline(p, smooth_space, TangentOptimization::exact, false);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const Eigen::Vector3d shift(3, -1, 2);
    PointList q(9, 3);
    for (int i = 0; i < 9; ++i) q.row(i) = (2.5 * R * p.row(i).transpose() + shift).transpose();
    const SpacePseudoSpline sq = space_pseudo_spline(q, smooth_space, TangentOptimization::exact, false);
    for (int k = 0; k <= 80; ++k) {
        const double u = 8.0 * k / 80;
        EXPECT_NEAR((sq.curve.point(u) - (2.5 * R * sm.curve.point(u) + shift)).norm(), 0.0,
                    1e-7 * 2.5 * bounding_box_diagonal(p))
            << u;
    }
    EXPECT_THROW(space_pseudo_spline(PointList::Zero(3, 4), space, TangentOptimization::exact, false), InvalidInput);
}

#include "cagd/methods/method_registry.hpp"

TEST(SpacePseudoSpline, ThroughTheRegistryWithAndWithoutASpaceTable) {
    PointList p(7, 3);
    for (int i = 0; i < 7; ++i) p.row(i) << std::cos(0.8 * i), std::sin(0.8 * i), 0.2 * i;
    const methods::InterpolationResult exact = methods::interpolate("pseudo-spline", p, false);
    ASSERT_TRUE(exact.outcome.ok());
    const std::string path = (std::filesystem::temp_directory_path() / "cagd_space_table_registry.txt").string();
    SpacePseudoEnergyTable::build({12, 24}, TableMethod::fast, 2).save(path);
    const methods::InterpolationResult table = methods::interpolate("pseudo-spline", p, false, {{"space-table", path}});
    ASSERT_TRUE(table.outcome.ok());
    for (int i = 0; i < 7; ++i) {
        EXPECT_NEAR((exact.interpolant->curve->point(i) - p.row(i).transpose()).norm(), 0.0, 1e-12);
        EXPECT_NEAR((table.interpolant->curve->point(i) - p.row(i).transpose()).norm(), 0.0, 1e-12);
    }
    // The same tangents; the spans' magnitudes from a 15° table differ a little from the exact ones.
    const double le = exact.quantities.front().second, lt = table.quantities.front().second;
    EXPECT_NEAR(lt, le, 1e-2 * le);
    EXPECT_NE(lt, le);
    EXPECT_THROW(methods::interpolate("pseudo-spline", p.leftCols(2), false, {{"space-table", path}}), InvalidInput);
    std::filesystem::remove(path);
}
