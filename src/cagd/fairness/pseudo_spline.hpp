#pragma once
/// @file
/// The pseudo-spline: the cubic Hermite curve through points whose spans are minimum
/// pseudo-energy segments (pseudo_energy section 3, eq 9–13), with its length and area from the
/// L and S tables (section 5, eq 16–21).
///
/// Symbols ↔ names. Points P_0..P_n (closed: P_0..P_{n−1}, span n−1 returns to P_0).
///   l_i = |P_i P_{i+1}|, φ_i = angle of P_i P_{i+1}             chord_length[i], chord_angle[i]
///   α_i = tangent direction at P_i relative to the chord φ_i     alpha[i]
///   span i, in its unit-chord frame: θ0 = α_i, θ1 = α_{i+1} + φ_{i+1} − φ_i     (eq 9)
///   (r0, r1) = table minimiser at (θ0, θ1); span i = P_i + l_i R(φ_i) H(t)     (eq 10, 4)
/// Angle convention: every difference of chord angles is wrapped to (−π, π], so the turn at P_i,
/// τ_i = φ_i − φ_{i−1}, is the smaller of the two rotations; θ0, θ1 are wrapped likewise. A turn of
/// exactly ±π (a hairpin: P_{i+1} on the ray back through P_{i−1}) has no such convention and every
/// segment through it has a cusp (the table is undefined there): InvalidInput. The knot data of
/// Table 3 turn by 180° − 2.86° in the same (clockwise) sense at both interior points, which this
/// convention makes a loop crossing the first span (tested).
///
/// Tangent directions (eq 11–13), interior points i = 1..n−1 (closed: every point):
///   w(α) = l_{i−1} J(α + φ_i − φ_{i−1}) + l_i J(α)   on the search interval between 0 and φ_{i−1} − φ_i
/// (between the two chords; l_{i−1} = |P_{i−1}P_i|, l_i = |P_iP_{i+1}|), J(θ) = min_{θ1} J(θ, θ1) (eq 11).
/// The J(θ, θ1) symmetry J(θ0, θ1) = J(θ1, θ0) (reverse the segment and turn it by π about the chord
/// midpoint) makes J(·) the best rod energy for a fixed tangent at either end, which is why the
/// first term uses it for the end of span i−1. Open ends (eq 13): α_0 = θ1(α_1 + φ_1 − φ_0) and the
/// end direction at P_n is φ_{n−1} + θ1(α_{n−1}); we store alpha[n] = θ1(α_{n−1}), relative to the
/// incoming chord φ_{n−1} (the paper's α_n = φ_{n−1} + θ1(α_{n−1}) is the absolute angle).
///   exact        the least value of w over the search interval. With the paper's tables, J(θ) is
///                read linearly between the angle table's nodes, so w is linear between its
///                breakpoints (the ends of the interval and the α at which α or α + τ_i meets a node,
///                at most 2|τ_i|/h + 2 of them for node spacing h) and its least value is at one of
///                them: every breakpoint is evaluated. The result is therefore the exact minimiser
///                up to rounding (the same curve from another compiler or maths library, to ~1e-15),
///                not an iterate stopped at a tolerance. (Earlier versions used Brent's method, which
///                stops within 2^−26 relative of the breakpoint, so rounding moved the curve by up
///                to ~1e-9 of the diagonal.) Where w is flat over a stretch (relative differences
///                below 1e-10: both angles in one cell and their slopes cancelling, as equal chords
///                make them at the bisector) every point of it is a minimum; we take the middle of
///                the stretch (TangentTie), which keeps equal-chord data symmetric. Where the least
///                values of two separate stretches agree to 1e-10, the one of lower α is taken. An
///                oracle whose J(θ) is smooth (ExactOracle: no angle_energy_nodes) is minimised by
///                Brent's method (Boost.Math) at 2^−26 relative tolerance, flat stretches likewise.
///   approximate  the paper's "three interior points and quadratic interpolation": w at ¼, ½, ¾
///                of the interval, the vertex of the parabola through them, clamped to the interval.
///                The paper does not say what to do when the parabola is not convex; we take its
///                least value over the interval, an end point (lo when w(¼) < w(¾), else hi), and
///                judge convexity and slope against rounding (64 ε max w): a parabola within
///                rounding of a line is a line, within rounding of a constant gives the middle.
///                This keeps α continuous in the data, so the mode is invariant under rotation,
///                scaling and translation up to rounding — deciding by the sign of a rounding-noise
///                curvature (w is linear within a table cell) moved α by ¼ of the interval in a
///                rotated copy of the points.
///   none         w is not minimised: α_i is the direction of P_{i+1} − P_{i−1} (Hermite curve A's
///                direction, the tangent of the quadratic through the three points at uniform
///                parameter, Iri–Fujino [7] in section 3). Everything else is as in the method:
///                magnitudes from the table (eq 9) and ends by eq (13). So "none" differs from the
///                other modes only by the minimisation, which is what Table 4 times.
///
/// Length and area (section 5): L = Σ l_i L(θ0_i, θ1_i) (eq 16, 17) and the signed area
/// A = S_0 − Σ l_i² S(θ0_i, θ1_i) (eq 19, 20; the paper prints |A|), S_0 the shoelace area of the
/// polygon closed by P_n P_0 (eq 21); for an open curve the region is closed by the line P_n P_0.
///
/// Straight spans: when both |θ0|, |θ1| ≤ 1e-12 the span is the straight segment with r0 = r1 = 1
/// (J = 0, L = 1, S = 0); the table's (0, 0) node is undefined because r0, r1 are not determined there.
///
/// Sources of J, θ1(θ), r0, r1, L, S: `TableOracle` (the lookup tables of pseudo_energy_table.hpp,
/// the paper's method) or `ExactOracle` (the fast minimiser at the exact angles, no table: slower,
/// for checking the tables).
///
/// Preconditions (InvalidInput): planar points, finite, no coincident consecutive points, at least
/// 2 points open (2 points: the chord itself has no turn, both tangents along it) and 3 closed, no
/// hairpin. Failure modes: a table or minimiser with no value at the needed angles throws
/// InvalidInput naming the span.
#include <Eigen/Dense>
#include <utility>
#include <vector>

#include "cagd/core/points.hpp"
#include "cagd/fairness/angle_minimum_table.hpp"
#include "cagd/fairness/pseudo_energy_table.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace cagd::fairness {

/// The tangent choice of eq (12): none (Hermite A's directions), exact (the least value; see above) or approximate (a
/// parabola through three values, Table 4).
enum class TangentOptimization { none, exact, approximate };
/// Exact mode, where w is flat over a stretch (J(θ) read linearly from a table: both angles of w in one
/// cell): every point of the stretch is a minimum, and `position` says which one, from 0 (its lower
/// α end) through 0.5 (the middle: the default, for equal chords the bisector) to 1 (its upper end).
/// Other positions are readings of the paper's procedure for erratum pseudo_energy-E4 (where a
/// minimiser might stop), not a method; InvalidInput outside [0, 1].
struct TangentTie {
    double position = 0.5;  ///< the fraction of a flat stretch of w taken as its minimiser (0.5: its middle)
};
/// "none", "exact" or "approx".
const char* to_string(TangentOptimization m);
TangentOptimization parse_tangent_optimization(const std::string& text);  ///< none | exact | approx

/// Where a pseudo-spline reads its segment values and J(θ).
class SegmentOracle {
public:
    virtual ~SegmentOracle() = default;
    /// r0, r1, J, L, S and type at (θ0, θ1) ∈ [−π, π]², (θ0, θ1) not an undefined node.
    virtual TableValue segment(double theta0, double theta1) const = 0;
    /// {J(θ), θ1(θ)} of eq (11).
    virtual std::pair<double, double> angle_minimum(double theta) const = 0;
    /// J(θ) alone (what eq 12 evaluates).
    virtual double angle_energy(double theta) const { return angle_minimum(theta).first; }
    /// The angles between which angle_energy is linear (a table's nodes over one period, ascending),
    /// or null where it is not piecewise linear (ExactOracle). The exact mode minimises a piecewise
    /// linear w at its breakpoints (see above) and a smooth one by Brent's method.
    virtual const std::vector<double>* angle_energy_nodes() const { return nullptr; }
};

/// The paper's tables: the 2-D table for the segments, the angle table for J(θ).
class TableOracle : public SegmentOracle {
public:
    /// `reading`: how the energy table is read between nodes (pseudo_energy_table.hpp); the angle
    /// table should be derived under the same reading (AngleMinimumTable::from_energy_table).
    TableOracle(const PseudoEnergyTable& energy, const AngleMinimumTable& angle, const TableReading& reading = {})
        : energy_(energy), angle_(angle), reading_(reading), default_reading_(reading.is_default()) {}
    TableValue segment(double theta0, double theta1) const override {
        return default_reading_ ? energy_.lookup(theta0, theta1) : energy_.lookup(theta0, theta1, reading_);
    }
    std::pair<double, double> angle_minimum(double theta) const override { return angle_.lookup(theta); }
    double angle_energy(double theta) const override { return angle_.pseudo_energy(theta); }
    const std::vector<double>* angle_energy_nodes() const override { return &angle_.nodes(); }

private:
    const PseudoEnergyTable& energy_;
    const AngleMinimumTable& angle_;
    TableReading reading_;
    bool default_reading_ = true;
};

/// The two tables the paper's method reads: J, r0, r1, L, S over direction pairs, and J(θ), θ1(θ)
/// derived from it as section 4.1 describes. Keep the object alive while its oracle() is used.
struct PseudoSplineTables {
    PseudoEnergyTable energy;  ///< the 2-D table
    AngleMinimumTable angle;   ///< J(θ), θ1(θ) derived from it
    /// The tables of a 2-D table, the angle table derived as section 4.1 describes.
    static PseudoSplineTables from(PseudoEnergyTable energy) {
        AngleMinimumTable angle = AngleMinimumTable::from_energy_table(energy);
        return {std::move(energy), std::move(angle)};
    }
    /// The oracle reading these tables.
    TableOracle oracle() const { return TableOracle(energy, angle); }
};

/// The minimiser at the exact angles for the segments and J(θ) (no table error, slower).
class ExactOracle : public SegmentOracle {
public:
    TableValue segment(double theta0, double theta1) const override;
    std::pair<double, double> angle_minimum(double theta) const override;
};

/// Segments by the minimiser at the exact angles (as ExactOracle), J(θ) and θ1(θ) from another oracle
/// (its tables): the planar counterpart of ExactSpaceOracle(planar), for comparing the two.
class ExactSegmentOracle : public SegmentOracle {
public:
    /// Segments exact, angles from `angles` (which must outlive this oracle).
    explicit ExactSegmentOracle(const SegmentOracle& angles) : angles_(angles) {}
    TableValue segment(double theta0, double theta1) const override { return ExactOracle{}.segment(theta0, theta1); }
    std::pair<double, double> angle_minimum(double theta) const override { return angles_.angle_minimum(theta); }
    double angle_energy(double theta) const override { return angles_.angle_energy(theta); }
    const std::vector<double>* angle_energy_nodes() const override { return angles_.angle_energy_nodes(); }

private:
    const SegmentOracle& angles_;
};

/// One span of a pseudo-spline: its frame angles and the values it used.
struct PseudoSplineSpan {
    double theta0 = 0.0;  ///< θ0 in the span's unit-chord frame (eq 9)
    double theta1 = 0.0;  ///< θ1 in the span's unit-chord frame
    TableValue value;     ///< r0, r1, J, L, S used for the span
};

/// The pseudo-spline through points and how it was built.
struct PseudoSpline {
    spline::PiecewiseHermiteCurve curve;       ///< the curve, in Hermite form on unit spans
    std::vector<double> alpha;                 ///< one per point (see above for the last point of an open curve)
    std::vector<double> chord_angle;           ///< φ_i, one per span
    std::vector<double> chord_length;          ///< l_i, one per span
    std::vector<PseudoSplineSpan> spans;       ///< one per span
    long oracle_calls = 0;                     ///< J(θ) evaluations spent on the tangent directions
    double length_from_tables() const;         ///< eq (16), (17)
    double area_from_tables() const;           ///< eq (19)–(21), signed (counter-clockwise positive)
    double pseudo_energy_from_tables() const;  ///< Σ l_i J_i (J scales with the chord length)
    double polygon_area() const;               ///< S_0 of eq (21)
};

/// The pseudo-spline through the points (eq 9–13): tangents by `mode`, segments from `oracle`.
PseudoSpline pseudo_spline(const PointList& points, const SegmentOracle& oracle, TangentOptimization mode, bool closed,
                           TangentTie tie = {});

/// The curve and the three table sums alone: pseudo_spline(...).curve, .length_from_tables(),
/// .area_from_tables() and .pseudo_energy_from_tables(), bit for bit, without the per-span records
/// and per-point arrays. What the method registry builds.
struct PseudoSplineCurve {
    spline::PiecewiseHermiteCurve curve;     ///< the curve, in Hermite form on unit spans
    double length_from_tables = 0.0;         ///< eq (16)–(17)
    double area_from_tables = 0.0;           ///< eq (19)–(21)
    double pseudo_energy_from_tables = 0.0;  ///< Σ l_i J_i
};
/// The pseudo-spline's curve and table sums, without the per-span records (the same curve bit for bit; what the
/// registry builds).
PseudoSplineCurve pseudo_spline_curve(const PointList& points, const SegmentOracle& oracle, TangentOptimization mode,
                                      bool closed, TangentTie tie = {});
/// The same through points validated already (closed as they were validated): the same curve, the
/// points not checked again where their checks cover this construction's.
PseudoSplineCurve pseudo_spline_curve(const ValidPoints& points, const SegmentOracle& oracle, TangentOptimization mode,
                                      TangentTie tie = {});

/// "Equivalent points" of Tables 5 and 6 (section 5.1): the smallest N ≥ 3 for which the regular
/// N-gon inscribed in the unit circle is closer to the circle than the spline, i.e.
/// |true − spline| > |true − polygon_N|, with perimeter 2N sin(π/N) (true 2π) or area
/// (N/2) sin(2π/N) (true π). `spline_error` = |true − spline|; throws InvalidInput if it is not
/// positive and finite (no polygon is worse than a perfect value) or N would exceed 10^9.
enum class CircleMeasure { perimeter, area };
/// The smallest N ≥ 3 whose regular N-gon is closer to the circle than a spline with error `spline_error` (see above).
long equivalent_polygon_points(double spline_error, CircleMeasure measure);
/// The analogue for a circular helix of radius a rising p per turn (p/a = rise_over_radius ≥ 0): the
/// smallest N ≥ 3 for which the polygon through N equally spaced points per turn has a smaller
/// relative length error than `relative_error` (> 0), the polygon's being
/// 1 − N sqrt(4 sin²(π/N) + (p/(aN))²) / sqrt(4π² + (p/a)²). At p = 0 it is the circle's perimeter
/// rule relative to 2π.
long equivalent_helix_polygon_points(double relative_error, double rise_over_radius);

/// The turn φ_i − φ_{i−1} wrapped to (−π, π] between two chord directions given as vectors.
double turning_angle(const Eigen::Vector2d& incoming, const Eigen::Vector2d& outgoing);

}  // namespace cagd::fairness
