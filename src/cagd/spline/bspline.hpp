#pragma once
/// @file
/// B-spline curves of any degree on any (uniform or non-uniform) knot vector.
///
///   r(t) = Σ_{i=0}^{n−1} N_{i,p}(t) d_i,   t ∈ [t_p, t_n],
/// with knots t_0 ≤ … ≤ t_{n+p} (n + p + 1 of them) and Cox–de Boor basis N_{i,p}.
/// Evaluation with derivatives: per non-empty span, the Taylor coefficients at its middle m_s,
/// c_k = r^(k)(m_s)/k! (basis-function derivatives by Piegl & Tiller, The NURBS Book, algorithm
/// A2.3, once per span, on the first evaluation of its block of spans: thread-safe), then Horner in h = t − m_s
/// (|h| ≤ half the span, which keeps the rounding at the ends small): O(p·order) per point. At a
/// knot itself the A2.3 values, as before: there the basis functions whose support ends are
/// exactly zero, so a control point changes nothing beyond its support, bit for bit (the locality
/// checks rely on it; tested). (A clamped end gives its control point to rounding, not exactly:
/// A2.3 forms the end basis value 1 as r·(1/r).) They are computed once per span end with the Taylor
/// coefficients (rows 0..p) and read from that table, so a jet at a knot costs what one off the
/// knots does; orders above p at a knot run A2.3 itself. (The table and A2.3 agree to rounding, a
/// few ε of the jet's terms.)
/// Knot insertion: Boehm's algorithm (exact, convex combinations). Degree elevation:
/// the elevated curve lies exactly in the spline space of degree p+1 whose knots are
/// the old ones with every multiplicity raised by one; its control points are found by
/// a least-squares fit to p+2 samples per span, which is exact up to rounding because the
/// old curve is in that space (QR; error ~ 10 ε·|d| for well-conditioned knots).
/// Bézier segments: per non-empty span, from the one-sided jets at its two ends (bezier_from_end_jets).
///
/// Preconditions (InvalidInput otherwise): p ≥ 0; knots non-decreasing and finite;
/// control point count n = knots − p − 1 ≥ p + 1; t_p < t_n; no knot of multiplicity > p+1.
#include <Eigen/Dense>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "cagd/core/curve.hpp"
#include "cagd/spline/bezier.hpp"

namespace cagd {

/// A B-spline curve of degree p on a knot vector (see above), evaluated through per-span Taylor coefficients.
class BSplineCurve : public Curve {
public:
    /// Degree p, knots t_0..t_{n+p} and control points d_0..d_{n−1} (one per row); InvalidInput unless the
    /// preconditions above hold.
    BSplineCurve(int degree, std::vector<double> knots, Eigen::MatrixXd control_points);

    /// p.
    int degree() const { return degree_; }
    /// t_0..t_{n+p}.
    const std::vector<double>& knots() const { return knots_; }
    /// d_0..d_{n−1}, one per row.
    const Eigen::MatrixXd& control_points() const { return control_; }

    int dimension() const override { return static_cast<int>(control_.cols()); }
    double t_min() const override { return knots_[degree_]; }
    double t_max() const override { return knots_[control_.rows()]; }
    /// Allocation-free (after the first evaluation builds the Taylor coefficients).
    void evaluate_jet(double t, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const override;
    std::vector<double> breakpoints() const override;
    int polynomial_degree() const override { return degree_; }
    /// 0 where both curves evaluate [t0, t1] = [u0, u1] from equal data: another B-spline curve of the
    /// same degree, knot count and control-point shape whose knots and control points agree, entry by
    /// entry, wherever Algorithm A2.3 reads them for the knot spans of [t0, t1]; std::nullopt otherwise.
    std::optional<double> span_offset_bound(const Curve& other, double t0, double t1, double u0,
                                            double u1) const override;

    /// Index s with t_s ≤ t < t_{s+1}, p ≤ s ≤ n−1 (t = t_max: the last non-empty span).
    int find_span(double t) const;

private:
    /// A value built once on first use, from a const member (a copy builds its own).
    template <class T>
    struct OnceCache {
        std::unique_ptr<std::once_flag> once = std::make_unique<std::once_flag>();
        T value{};
        OnceCache() = default;
        OnceCache(const OnceCache&) : once(std::make_unique<std::once_flag>()) {}
        OnceCache& operator=(const OnceCache&) {
            once = std::make_unique<std::once_flag>();
            value = T{};
            return *this;
        }
        OnceCache(OnceCache&&) noexcept = default;
        OnceCache& operator=(OnceCache&&) noexcept = default;
    };
    /// Rows of doubles per non-empty span s (row[s − p]; an empty span takes no row: a curve of
    /// Bézier pieces, every knot p-fold, has one non-empty span in p), built on first use block by block of
    /// kSpansPerTableBlock spans (thread-safe), each row exactly as a whole-table build forms it: a
    /// curve evaluated on a few spans only (the locality footprint's moved curve: a few dozen of 10^5)
    /// builds their blocks, not the whole table. A built block is found by one acquire load (the
    /// lookup of every jet). A copy, or a moved curve, builds its own.
    struct SpanTable {
        std::mutex building;                                 ///< held while a block (or the array) is built
        std::atomic<bool> allocated{false};                  ///< values and built exist (release/acquire)
        std::unique_ptr<std::atomic<std::uint8_t>[]> built;  ///< per block: 1 once its rows are filled
        std::vector<int> row;                                ///< per span s − p: its row in values
        std::vector<double> values;
        SpanTable() = default;
        SpanTable(const SpanTable&) : SpanTable() {}
        SpanTable(SpanTable&&) noexcept : SpanTable() {}
        SpanTable& operator=(const SpanTable&) { return reset(); }
        SpanTable& operator=(SpanTable&&) noexcept { return reset(); }
        SpanTable& reset() {
            allocated.store(false, std::memory_order_relaxed);
            built.reset();
            row.clear();
            values.clear();
            return *this;
        }
    };
    /// The row of `span` in `table` (row_size doubles per span), its block filled first if need be by
    /// fill(first, last, row_of): the non-empty spans first ≤ s < last into row_of(s) (row_size doubles).
    template <class Fill>
    const double* span_row(SpanTable& table, int span, std::size_t row_size, Fill fill) const;
    /// The span find_span found last (a hint, checked against the definition before use: successive
    /// evaluations, a quadrature's nodes or a sampling, mostly fall in the same span). Relaxed
    /// atomic: threads evaluating one curve may overwrite each other's hint, never a result. A copy
    /// starts without one.
    struct SpanHint {
        mutable std::atomic<int> span{-1};
        SpanHint() = default;
        SpanHint(const SpanHint&) {}
        SpanHint& operator=(const SpanHint&) {
            span.store(-1, std::memory_order_relaxed);
            return *this;
        }
    };
    /// Equal buckets over [t_min, t_max), one per span: first[b] is the span holding the bucket's
    /// left end, where find_span starts its forward scan.
    struct SpanBuckets {
        std::vector<int> first;
        double per_unit = 0.0;  ///< buckets per unit of t
    };
    const SpanBuckets& span_buckets() const;
    const double* taylor(int span) const;  ///< c_0 … c_p of `span`
    double span_middle(int span) const;
    void taylor_jet(int span, double t, int order, Eigen::Ref<Eigen::MatrixXd> out) const;  ///< rows 0..order
    const double* knot_jet(int span, bool at_end) const;  ///< rows 0..p of the A2.3 jet at the span's start or end knot

    int degree_;
    std::vector<double> knots_;
    Eigen::MatrixXd control_;
    mutable SpanTable taylor_;  ///< span s − p: (p + 1) × dimension, c_0 … c_p, row-major
    mutable OnceCache<SpanBuckets> span_buckets_;
    SpanHint last_span_;
    mutable SpanTable knot_jets_;  ///< span s − p: start then end, each (p + 1) × dimension, row-major
};

/// Derivatives 0..order of the p+1 basis functions non-zero on span s at t:
/// result(k, j) = d^k N_{s−p+j, p}(t) / dt^k. (Piegl & Tiller A2.3.)
Eigen::MatrixXd basis_function_derivatives(int degree, const std::vector<double>& knots, int span, double t, int order);
/// The same into a matrix on the stack (degree ≤ 7, order ≤ 7; InvalidInput otherwise), bit for bit.
using BasisDerivatives = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 8, 8>;
/// basis_function_derivatives written into `ders` (order + 1 rows, p + 1 columns; p ≤ 7), without allocating.
void basis_function_derivatives_into(int degree, const std::vector<double>& knots, int span, double t, int order,
                                     BasisDerivatives& ders);

/// One B-spline basis function of degree p given by its p+2 local knots
/// [κ_0, …, κ_{p+1}], or its derivative, at t; zero outside [κ_0, κ_{p+1}). Right-continuous,
/// except that t = κ_{p+1} is taken from the left (so closed supports evaluate symmetrically).
double bspline_basis(int degree, const std::vector<double>& local_knots, double t, int derivative = 0);

/// The same curve with the knot t inserted once (Boehm); t in [t_min, t_max].
BSplineCurve insert_knot(const BSplineCurve& curve, double t);
/// The same curve as a B-spline of degree p + 1 (every knot's multiplicity raised by one).
BSplineCurve elevate_degree(const BSplineCurve& curve);
/// The curve's polynomial pieces as Bézier curves, one per non-empty span, each on its span's interval.
std::vector<BezierCurve> bezier_segments(const BSplineCurve& curve);

}  // namespace cagd
