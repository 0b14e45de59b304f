#pragma once
/// @file
/// The one curve interface (docs/design.md): position and derivatives at a parameter.
/// Everything in analysis/ (curvature, length, area, distances) works on a Curve, so it is
/// written once for all curve types. Modelled on GTE's ParametricCurve::Evaluate(t, order).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace cagd {

/// Fixed-capacity storage for a jet: up to kJetCapacity rows (derivative orders 0..kJetCapacity−1)
/// and 3 columns, held inline, so filling one never allocates.
inline constexpr int kJetCapacity = 4;
/// The storage of a jet (derivative orders in rows, coordinates in columns), at most kJetCapacity × 3.
using JetMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kJetCapacity, 3>;

/// Which piece evaluates a parameter that is a breakpoint: the one that starts there (right, the
/// default) or the one that ends there (left: the left limit t' → t⁻).
enum class JetSide { right, left };

/// A parametric curve r(t), t ∈ [t_min, t_max], in 2 or 3 dimensions: position and derivatives at
/// any parameter, the one interface analysis/ measures every curve through.
///
/// One virtual evaluation primitive, evaluate_jet, as Geometric Tools' ParametricCurve::Evaluate;
/// jet, jet_from_left, derivatives, point and their allocation-free forms are non-virtual
/// conveniences on top of it, and check their arguments once for every curve.
class Curve {
public:
    virtual ~Curve() = default;
    /// Number of coordinates of a point: 2 (planar) or 3 (space).
    virtual int dimension() const = 0;
    /// First parameter of the curve's domain.
    virtual double t_min() const = 0;
    /// Last parameter of the curve's domain.
    virtual double t_max() const = 0;
    /// Parameters in [t_min, t_max] between which the curve is polynomial (ascending,
    /// including both ends). Quadrature in analysis/ integrates piece by piece.
    virtual std::vector<double> breakpoints() const = 0;
    /// p ≥ 0 when every piece between consecutive breakpoints is a polynomial of degree at most p in
    /// t (Hermite and Bézier curves, B-splines, Hosaka's curves); −1 for a curve that is not
    /// polynomial (the intrinsic and log-aesthetic curves). export/ gives a polynomial curve's exact
    /// Bézier and B-spline forms from its jets, and approximates the others with a stated error.
    virtual int polynomial_degree() const { return -1; }

    /// THE evaluation primitive: row i of `out` is the derivative d^k r/dt^k at t of order
    /// k = first + i, i = 0..out.rows() − 1, from the piece that starts at t (JetSide::right) or
    /// ends there (JetSide::left). first is 0 (with the position) or 1 (without: a curve whose
    /// position is costly, IntrinsicCurve's quadrature, skips it). The conveniences below call it
    /// with out.rows() ≥ 1, out.cols() == dimension(), t inside the domain (left: t > t_min), so an
    /// implementation checks only what is its own (an order it does not provide: InvalidInput).
    virtual void evaluate_jet(double t, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const = 0;

    /// An upper bound B on the distance between this curve r and `other` q at equal fractions of the
    /// parameter intervals [t0, t1] and [u0, u1]: |r(t0 + f (t1 − t0)) − q(u0 + f (u1 − u0))| ≤ B for
    /// f ∈ [0, 1] (t1 and u1 themselves at f = 1), the positions as evaluate_jet computes them
    /// (JetSide::right); std::nullopt where the curve knows no bound cheaper than sampling — the
    /// default, and whenever `other` is not of its own kind. A comparison skips the spans that cannot
    /// have moved with it (compare's locality footprint). Never throws for intervals outside the domain:
    /// it knows no bound there.
    virtual std::optional<double> span_offset_bound(const Curve& /*other*/, double /*t0*/, double /*t1*/, double /*u0*/,
                                                    double /*u1*/) const {
        return std::nullopt;
    }

    /// Row k of the result is the k-th derivative d^k r/dt^k at t, k = 0..order.
    /// Precondition: t_min ≤ t ≤ t_max, order ≥ 0 (InvalidInput otherwise).
    Eigen::MatrixXd jet(double t, int order) const;
    /// The left limit lim_{t'→t⁻} jet(t', order), for t_min < t ≤ t_max: at a breakpoint, the jet of
    /// the piece that ends there (jet(t) is the piece that starts there). Continuity at a join is
    /// measured by comparing the two.
    Eigen::MatrixXd jet_from_left(double t, int order) const;
    /// The derivatives without the position: row k − 1 is d^k r/dt^k at t, k = 1..order (order ≥ 1).
    /// Speed, curvature and their integrals need only these.
    Eigen::MatrixXd derivatives(double t, int order) const;
    /// jet(t, order) written into `out` (resized to order + 1 rows × dimension()), for
    /// 0 ≤ order < kJetCapacity and dimension() ≤ 3 (InvalidInput otherwise): the allocation-free
    /// form for loops over many parameters.
    void jet_into(double t, int order, JetMatrix& out) const;
    /// derivatives(t, order) likewise, for 1 ≤ order ≤ kJetCapacity.
    void derivatives_into(double t, int order, JetMatrix& out) const;
    /// jet_into at the `count` parameters t[0 … count − 1], each jet row by row (order r, then
    /// coordinate c) into out[(k·(order + 1) + r)·dimension() + c] (Python's Curve.evaluate runs it).
    /// Preconditions and errors as jet_into's; after an error `out` is incomplete.
    void jets_into(const double* t, std::size_t count, int order, double* out) const;
    /// Position r(t) (row 0 of jet(t, 0)) as a column vector.
    Eigen::VectorXd point(double t) const { return jet(t, 0).row(0).transpose(); }

protected:
    /// For a curve whose formula gives a whole jet at once: rows first.. of `jet` into out.
    static void take_rows(const Eigen::MatrixXd& jet, int first, Eigen::Ref<Eigen::MatrixXd> out) {
        out = jet.middleRows(first, out.rows());
    }
};

/// Throws InvalidInput naming `who` unless `rows` × `dimension` fits a JetMatrix.
/// (Inline: it sits in every jet_into; the throwing path is out of line.)
[[noreturn]] void reject_jet_capacity(const char* who, int rows, int dimension);
/// Throws InvalidInput naming `who` unless 1 ≤ `rows` ≤ kJetCapacity and 1 ≤ `dimension` ≤ 3.
inline void require_jet_capacity(const char* who, int rows, int dimension) {
    if (rows < 1 || rows > kJetCapacity || dimension < 1 || dimension > JetMatrix::MaxColsAtCompileTime) [[unlikely]]
        reject_jet_capacity(who, rows, dimension);
}

/// Helpers for curves made of K pieces of unit parameter length, piece s on u ∈ [s, s+1]
/// (piecewise Hermite curves, Hosaka curves).
std::vector<double> unit_piece_breakpoints(int pieces);  ///< 0, 1, …, K
/// Where a parameter u of a curve of K unit pieces falls: its piece and the local parameter.
struct PieceLocation {
    int piece;  ///< s, the last piece for u = K
    double t;   ///< u − s ∈ [0, 1]
};
/// Throws InvalidInput naming `who` for u outside [0, K] (or NaN) or order < 0.
[[noreturn]] void reject_unit_piece(const char* who, double u, int pieces, int order);
/// The piece s = min(⌊u⌋, K − 1) holding u ∈ [0, K] and t = u − s; InvalidInput for u outside [0, K] or order < 0.
[[gnu::always_inline]] inline PieceLocation locate_unit_piece(const char* who, double u, int pieces, int order) {
    if (!(u >= 0.0 && u <= pieces) || order < 0) [[unlikely]]
        reject_unit_piece(who, u, pieces, order);
    // u ∈ [0, K] here, so truncation is the floor (and a single instruction, where std::floor is a
    // library call without SSE4.1).
    const int s = std::min(static_cast<int>(u), pieces - 1);
    return {s, u - s};
}
/// The piece that ends at u for u ∈ (0, K] (t = 1 at a breakpoint): for Curve::jet_from_left.
PieceLocation locate_unit_piece_from_left(const char* who, double u, int pieces, int order);

}  // namespace cagd
