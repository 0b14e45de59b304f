#include "cagd/spline/bspline.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "cagd/core/errors.hpp"

namespace cagd {

namespace {
const char* const kBSplineWho = "cagd::BSplineCurve";
constexpr int kIndexedSpans = 64;  // fewer spans: the binary search alone
}  // namespace

BSplineCurve::BSplineCurve(int degree, std::vector<double> knots, Eigen::MatrixXd control_points)
    : degree_(degree), knots_(std::move(knots)), control_(std::move(control_points)) {
    if (degree_ < 0) fail_input(kBSplineWho, "degree must be >= 0, got " + std::to_string(degree_));
    const auto n = static_cast<std::size_t>(control_.rows());
    if (control_.rows() < degree_ + 1)
        fail_input(kBSplineWho, "needs at least degree+1 = " + std::to_string(degree_ + 1) + " control points, got " +
                                    std::to_string(n));
    if (knots_.size() != n + static_cast<std::size_t>(degree_) + 1)
        fail_input(kBSplineWho, "knot count must be control points + degree + 1 = " + std::to_string(n + degree_ + 1) +
                                    ", got " + std::to_string(knots_.size()));
    for (std::size_t i = 0; i < knots_.size(); ++i) {
        if (!std::isfinite(knots_[i]))
            fail_input(kBSplineWho, "knot " + std::to_string(i) + " is " + full_precision(knots_[i]));
        if (i > 0 && knots_[i] < knots_[i - 1])
            fail_input(kBSplineWho, "knots must be non-decreasing; knot " + std::to_string(i) + " = " +
                                        full_precision(knots_[i]) + " < " + full_precision(knots_[i - 1]));
        const auto pp1 = static_cast<std::size_t>(degree_) + 1;
        if (i >= pp1 && knots_[i] == knots_[i - pp1])
            fail_input(kBSplineWho, "knot " + full_precision(knots_[i]) +
                                        " has multiplicity > degree+1 = " + std::to_string(degree_ + 1));
    }
    if (!(t_min() < t_max()))
        fail_input(kBSplineWho, "empty domain [" + full_precision(t_min()) + ", " + full_precision(t_max()) + "]");
    if (!control_.allFinite()) fail_input(kBSplineWho, "control points must be finite");
}

std::optional<double> BSplineCurve::span_offset_bound(const Curve& other, double t0, double t1, double u0,
                                                      double u1) const {
    const auto* o = dynamic_cast<const BSplineCurve*>(&other);
    if (o == nullptr || o->degree_ != degree_ || o->knots_.size() != knots_.size() ||
        o->control_.rows() != control_.rows() || o->control_.cols() != control_.cols() || !(t0 == u0 && t1 == u1) ||
        !(t_min() <= t0 && t0 <= t1 && t1 <= t_max()))
        return std::nullopt;
    // The knot spans s0..s1 of t ∈ [t0, t1], and what A2.3 and the basis read for them: knots
    // s0 − p .. s1 + p + 1, control points s0 − p .. s1.
    const int p = degree_, s0 = find_span(t0), s1 = find_span(t1);
    for (int i = s0 - p; i <= s1 + p + 1; ++i)
        if (!(knots_[static_cast<std::size_t>(i)] == o->knots_[static_cast<std::size_t>(i)])) return std::nullopt;
    const Eigen::Index first = s0 - p, count = s1 - s0 + p + 1;
    return control_.middleRows(first, count) == o->control_.middleRows(first, count) ? std::optional<double>(0.0)
                                                                                     : std::nullopt;
}

int BSplineCurve::find_span(double t) const {
    const int n = static_cast<int>(control_.rows());
    if (t >= t_max()) {
        int s = n - 1;
        while (s > degree_ && knots_[s] == knots_[s + 1]) --s;
        return s;
    }
    // The span s with U_s ≤ t < U_{s+1}, p ≤ s < n (unique: an empty span fails t < U_{s+1}).
    // First the last span found, or the one after it, if t is in it. On a curve of many spans (a sampled curve asks for
    // millions) then from the bucket of t: a start at or before the span, a short forward scan, and
    // the definition checked; the binary search otherwise. The same span either way.
    const auto found = [&](int s) {
        last_span_.span.store(s, std::memory_order_relaxed);
        return s;
    };
    const int hint = last_span_.span.load(std::memory_order_relaxed);
    if (hint >= degree_ && knots_[static_cast<std::size_t>(hint)] <= t) {  // (hint < n: t < t_max)
        if (t < knots_[static_cast<std::size_t>(hint) + 1]) return hint;
        if (hint + 1 < n && t < knots_[static_cast<std::size_t>(hint) + 2])
            return found(hint + 1);  // the next span (U_{hint+1} ≤ t): a sampling's next step
    }
    auto from = knots_.begin() + degree_;
    if (n - degree_ >= kIndexedSpans && t >= t_min()) {
        const SpanBuckets& b = span_buckets();
        const auto bucket =
            static_cast<std::size_t>(std::min(static_cast<double>(b.first.size() - 1), (t - t_min()) * b.per_unit));
        int s = b.first[bucket];
        if (knots_[static_cast<std::size_t>(s)] <= t) {
            for (int step = 0; step < 8; ++step, ++s)
                if (s + 1 == n || t < knots_[static_cast<std::size_t>(s) + 1])
                    return found(s);    // (s + 1 = n: t < t_max = U_n)
            from = knots_.begin() + s;  // U_s ≤ t still: search on from there
        }
    }
    const auto it = std::upper_bound(from, knots_.begin() + n, t);
    return found(static_cast<int>(it - knots_.begin()) - 1);
}

const BSplineCurve::SpanBuckets& BSplineCurve::span_buckets() const {
    std::call_once(*span_buckets_.once, [&] {
        const int n = static_cast<int>(control_.rows()), count = n - degree_;
        SpanBuckets b;
        b.per_unit = count / (t_max() - t_min());
        b.first.resize(static_cast<std::size_t>(count));
        int s = degree_;
        for (int k = 0; k < count; ++k) {
            const double left =
                t_min() +
                k / b.per_unit;  // (rounding here costs a longer scan or the binary search, never a wrong span)
            while (s + 1 < n && knots_[static_cast<std::size_t>(s) + 1] <= left) ++s;
            b.first[static_cast<std::size_t>(k)] = s;
        }
        span_buckets_.value = std::move(b);
    });
    return span_buckets_.value;
}

namespace {

// Piegl & Tiller, The NURBS Book (2nd ed.), algorithm A2.3. The work arrays have at most `Max`
// rows and columns (Eigen::Dynamic: unbounded): on the stack for the usual low degrees.
// With Fixed ≥ 0 the degree is that constant (p must equal it): the compiler then unrolls the loops;
// the operations and their order are the same, so are the values, bit for bit.
template <int Max, int Fixed = -1, class Ders>
void basis_function_derivatives_a23(int degree, const std::vector<double>& U, int span, double u, int order,
                                    Ders& ders) {
    const int p = Fixed >= 0 ? Fixed : degree;
    using Work = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, Max, Max>;
    using WorkVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, Max, 1>;
    const int nd = std::min(order, p);
    Work ndu(p + 1, p + 1), a(2, p + 1);
    WorkVector left(p + 1), right(p + 1);
    ndu(0, 0) = 1.0;
    for (int j = 1; j <= p; ++j) {
        left(j) = u - U[span + 1 - j];
        right(j) = U[span + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            ndu(j, r) = right(r + 1) + left(j - r);
            const double temp = ndu(r, j - 1) / ndu(j, r);
            ndu(r, j) = saved + right(r + 1) * temp;
            saved = left(j - r) * temp;
        }
        ndu(j, j) = saved;
    }
    ders.setZero(order + 1, p + 1);
    for (int j = 0; j <= p; ++j) ders(0, j) = ndu(j, p);
    for (int r = 0; r <= p; ++r) {
        int s1 = 0, s2 = 1;
        a(0, 0) = 1.0;
        for (int k = 1; k <= nd; ++k) {
            double d = 0.0;
            const int rk = r - k, pk = p - k;
            if (r >= k) {
                a(s2, 0) = a(s1, 0) / ndu(pk + 1, rk);
                d = a(s2, 0) * ndu(rk, pk);
            }
            const int j1 = (rk >= -1) ? 1 : -rk;
            const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
            for (int j = j1; j <= j2; ++j) {
                a(s2, j) = (a(s1, j) - a(s1, j - 1)) / ndu(pk + 1, rk + j);
                d += a(s2, j) * ndu(rk + j, pk);
            }
            if (r <= pk) {
                a(s2, k) = -a(s1, k - 1) / ndu(pk + 1, r);
                d += a(s2, k) * ndu(r, pk);
            }
            ders(k, r) = d;
            std::swap(s1, s2);
        }
    }
    double factor = p;
    for (int k = 1; k <= nd; ++k) {
        ders.row(k) *= factor;
        factor *= (p - k);
    }
}

constexpr int kStackOrder = 8;  // degrees 0..7 keep the work arrays on the stack

}  // namespace

Eigen::MatrixXd basis_function_derivatives(int p, const std::vector<double>& U, int span, double u, int order) {
    Eigen::MatrixXd ders;
    if (p + 1 <= kStackOrder)
        basis_function_derivatives_a23<kStackOrder>(p, U, span, u, order, ders);
    else
        basis_function_derivatives_a23<Eigen::Dynamic>(p, U, span, u, order, ders);
    return ders;
}

void basis_function_derivatives_into(int p, const std::vector<double>& U, int span, double u, int order,
                                     BasisDerivatives& ders) {
    if (p < 0 || p + 1 > kStackOrder || order < 0 || order + 1 > kStackOrder)
        fail_input("cagd::basis_function_derivatives_into",
                   "needs degree 0..7 and order 0..7, got " + std::to_string(p) + " and " + std::to_string(order));
    switch (p) {  // the usual degrees unrolled
        case 2: return basis_function_derivatives_a23<kStackOrder, 2>(p, U, span, u, order, ders);
        case 3: return basis_function_derivatives_a23<kStackOrder, 3>(p, U, span, u, order, ders);
        case 4: return basis_function_derivatives_a23<kStackOrder, 4>(p, U, span, u, order, ders);
        case 5: return basis_function_derivatives_a23<kStackOrder, 5>(p, U, span, u, order, ders);
        default: return basis_function_derivatives_a23<kStackOrder>(p, U, span, u, order, ders);
    }
}

namespace {

// D = ders · (the control points P_{first..first+p}), the basis derivatives of one span (rows
// 0..p) times its control points, into out[k·dim + e]: D(k, e) = Σ_{i=0..p} ders(k, i) P_{first+i,e}
// summed in the order i = 0, 1, …, p — the order of Eigen's coefficient-based product, which it
// uses for these small dynamic sizes (degree ≤ 7), so the same values as
// `ders * control.middleRows(first, p + 1)` bit for bit (tested: the Taylor table and the knot
// jets against that product), without its dispatch per span. The usual degrees and dimensions
// with both fixed at compile time (unrolled); P, Dim < 0: at run time.
template <int P, int Dim>
void basis_times_control_of(const BasisDerivatives& ders, const Eigen::MatrixXd& control, int first, int p_at_run_time,
                            int dim_at_run_time, double* out) {
    const int p = P >= 0 ? P : p_at_run_time, dim = Dim >= 0 ? Dim : dim_at_run_time;
    for (int e = 0; e < dim; ++e) {
        const double* x = control.col(e).data() + first;
        for (int k = 0; k <= p; ++k) {
            double sum = ders(k, 0) * x[0];
            for (int i = 1; i <= p; ++i) sum += ders(k, i) * x[i];
            out[k * dim + e] = sum;
        }
    }
}

// The unrolled product for degree p in Dim dimensions, when p is one of the unrolled degrees.
template <int Dim>
bool basis_times_control_unrolled(const BasisDerivatives& ders, const Eigen::MatrixXd& control, int first, int p,
                                  double* out) {
    switch (p) {
        case 2: basis_times_control_of<2, Dim>(ders, control, first, p, Dim, out); return true;
        case 3: basis_times_control_of<3, Dim>(ders, control, first, p, Dim, out); return true;
        case 4: basis_times_control_of<4, Dim>(ders, control, first, p, Dim, out); return true;
        case 5: basis_times_control_of<5, Dim>(ders, control, first, p, Dim, out); return true;
        default: return false;
    }
}

void basis_times_control(const BasisDerivatives& ders, const Eigen::MatrixXd& control, int first, int p, double* out) {
    const int dim = static_cast<int>(control.cols());
    if (dim == 2 && basis_times_control_unrolled<2>(ders, control, first, p, out)) return;
    if (dim == 3 && basis_times_control_unrolled<3>(ders, control, first, p, out)) return;
    basis_times_control_of<-1, -1>(ders, control, first, p, dim, out);
}

}  // namespace

double BSplineCurve::span_middle(int span) const {
    return 0.5 * (knots_[static_cast<std::size_t>(span)] + knots_[static_cast<std::size_t>(span) + 1]);
}

// Spans per block of the Taylor and knot-jet tables: a block is built on first use, its flag one
// atomic load per lookup.
constexpr int kSpansPerTableBlock = 1024;

template <class Fill>
const double* BSplineCurve::span_row(SpanTable& table, int span, std::size_t row_size, Fill fill) const {
    const int count = static_cast<int>(control_.rows()) - degree_, index = span - degree_;
    if (!table.allocated.load(std::memory_order_acquire)) {
        const std::lock_guard<std::mutex> lock(table.building);
        if (!table.allocated.load(std::memory_order_relaxed)) {
            table.row.resize(static_cast<std::size_t>(count));
            int rows = 0;  // an empty span shares the next one's row: it is never located
            for (int i = 0; i < count; ++i) {
                table.row[static_cast<std::size_t>(i)] = rows;
                if (knots_[static_cast<std::size_t>(i + degree_)] < knots_[static_cast<std::size_t>(i + degree_) + 1])
                    ++rows;
            }
            table.values.assign(static_cast<std::size_t>(rows) * row_size, 0.0);
            table.built = std::make_unique<std::atomic<std::uint8_t>[]>(
                static_cast<std::size_t>((count + kSpansPerTableBlock - 1) / kSpansPerTableBlock));
            table.allocated.store(true, std::memory_order_release);
        }
    }
    std::atomic<std::uint8_t>& built = table.built[static_cast<std::size_t>(index / kSpansPerTableBlock)];
    if (!built.load(std::memory_order_acquire)) {
        const std::lock_guard<std::mutex> lock(table.building);
        if (!built.load(std::memory_order_relaxed)) {
            const int first = degree_ + index / kSpansPerTableBlock * kSpansPerTableBlock;
            fill(first, std::min(first + kSpansPerTableBlock, degree_ + count), [&](int s) {
                return table.values.data() +
                       static_cast<std::size_t>(table.row[static_cast<std::size_t>(s - degree_)]) * row_size;
            });
            built.store(1, std::memory_order_release);
        }
    }
    return table.values.data() + static_cast<std::size_t>(table.row[static_cast<std::size_t>(index)]) * row_size;
}

const double* BSplineCurve::taylor(int span) const {
    const int p = degree_, dim = dimension();
    return span_row(taylor_, span, static_cast<std::size_t>((p + 1) * dim), [&](int first, int last, auto row_of) {
        // The basis derivatives on the stack (degree ≤ 7) and the product's array reused: no heap per
        // span. The same product, bit for bit, as from basis_function_derivatives' MatrixXd (both
        // sizes are dynamic, so Eigen sums each entry in the same order; tested).
        BasisDerivatives stack_ders;
        Eigen::MatrixXd heap_ders, d;
        for (int s = first; s < last; ++s) {
            if (!(knots_[static_cast<std::size_t>(s)] < knots_[static_cast<std::size_t>(s) + 1]))
                continue;             // empty span: never located
            double* row = row_of(s);  // D, then D(k, ·) / k!
            if (p + 1 <= kStackOrder) {
                basis_function_derivatives_into(p, knots_, s, span_middle(s), p, stack_ders);
                basis_times_control(stack_ders, control_, s - p, p, row);
            } else {
                heap_ders = basis_function_derivatives(p, knots_, s, span_middle(s), p);
                d.noalias() = heap_ders * control_.middleRows(s - p, p + 1);
                for (int k = 0; k <= p; ++k)
                    for (int e = 0; e < dim; ++e) row[k * dim + e] = d(k, e);
            }
            double factorial = 1.0;
            for (int k = 0; k <= p; ++k) {
                if (k > 0) factorial *= k;
                for (int e = 0; e < dim; ++e) row[k * dim + e] /= factorial;
            }
        }
    });
}

const double* BSplineCurve::knot_jet(int span, bool at_end) const {
    if (degree_ + 1 > kStackOrder)
        fail_input("cagd::BSplineCurve::knot_jet", "the table of knot jets holds degrees up to 7");
    const int p = degree_, dim = dimension();
    const double* both =
        span_row(knot_jets_, span, static_cast<std::size_t>(2 * (p + 1) * dim), [&](int first, int last, auto row_of) {
            BasisDerivatives ders;  // the very product the direct path forms (degree ≤ 7 only: see taylor_jet)
            for (int s = first; s < last; ++s) {
                if (!(knots_[static_cast<std::size_t>(s)] < knots_[static_cast<std::size_t>(s) + 1]))
                    continue;  // empty span: never located
                for (int end = 0; end < 2; ++end) {
                    basis_function_derivatives_into(p, knots_, s, knots_[static_cast<std::size_t>(s + end)], p, ders);
                    basis_times_control(ders, control_, s - p, p,
                                        row_of(s) + static_cast<std::size_t>(end * (p + 1) * dim));
                }
            }
        });
    return both + (at_end ? static_cast<std::size_t>((p + 1) * dim) : 0);
}

namespace {
// k!/(k−d)! = k (k−1) ⋯ (k−d+1), products of small integers: exact in double. From a table for
// the orders of the stack path (k < kStackOrder), computed otherwise — the same value.
constexpr double falling_product(int k, int d) {
    double f = 1.0;
    for (int i = 0; i < d; ++i) f *= k - i;
    return f;
}
struct FallingFactorials {
    double value[kStackOrder][kStackOrder]{};
    constexpr FallingFactorials() {
        for (int k = 0; k < kStackOrder; ++k)
            for (int d = 0; d <= k; ++d) value[k][d] = falling_product(k, d);
    }
};
constexpr FallingFactorials kFalling;
inline double falling_factorial(int k, int d) { return k < kStackOrder ? kFalling.value[k][d] : falling_product(k, d); }
}  // namespace

namespace {
// Rows first..last of the jet from one span's Taylor coefficients c (c_0 … c_p, row-major, `dim`
// per row) at h = t − (the span's middle): r^(d) = Σ_{k≥d} k!/(k−d)! c_k h^{k−d} by Horner, zero
// beyond the degree; into out's rows 0..last − first. The usual degrees and dimensions with both
// fixed at compile time (unrolled), the same operations in the same order.
template <int P, int Dim, class Out>
void taylor_rows_fixed(int p, int dim, const double* c, double h, int first, int last, Out& out) {
    const int pp = P > 0 ? P : p, dd = Dim > 0 ? Dim : dim;
    for (int d = first; d <= last; ++d)
        for (int e = 0; e < dd; ++e) {
            if (d > pp) {
                out(d - first, e) = 0.0;
                continue;
            }
            double v = falling_factorial(pp, d) * c[pp * dd + e];
            for (int k = pp - 1; k >= d; --k) v = v * h + falling_factorial(k, d) * c[k * dd + e];
            out(d - first, e) = v;
        }
}

template <class Out>
void taylor_rows(int p, int dim, const double* c, double h, int first, int last, Out& out) {
    switch ((dim == 2 || dim == 3) && p >= 2 && p <= 5 ? 8 * dim + p : -1) {  // (a key unique to each case)
        case 18: return taylor_rows_fixed<2, 2>(p, dim, c, h, first, last, out);
        case 19: return taylor_rows_fixed<3, 2>(p, dim, c, h, first, last, out);
        case 20: return taylor_rows_fixed<4, 2>(p, dim, c, h, first, last, out);
        case 21: return taylor_rows_fixed<5, 2>(p, dim, c, h, first, last, out);
        case 26: return taylor_rows_fixed<2, 3>(p, dim, c, h, first, last, out);
        case 27: return taylor_rows_fixed<3, 3>(p, dim, c, h, first, last, out);
        case 28: return taylor_rows_fixed<4, 3>(p, dim, c, h, first, last, out);
        case 29: return taylor_rows_fixed<5, 3>(p, dim, c, h, first, last, out);
        default: return taylor_rows_fixed<0, 0>(p, dim, c, h, first, last, out);
    }
}
}  // namespace

// Rows 0..order of the jet at t from the Taylor coefficients of `span`: r^(d)(t) = Σ_{k≥d}
// k!/(k−d)! c_k h^{k−d}, h = t − (the span's middle), by Horner; rows beyond the degree are zero.
void BSplineCurve::taylor_jet(int span, double t, int order, Eigen::Ref<Eigen::MatrixXd> out) const {
    const int p = degree_, dim = dimension();
    const bool at_start = t == knots_[static_cast<std::size_t>(span)];
    if (at_start || t == knots_[static_cast<std::size_t>(span) + 1]) {
        // At a knot (the curve's ends, the joins) the A2.3 values: there the basis functions whose
        // support ends are exactly zero, so a control point changes nothing beyond its support,
        // bit for bit (the Taylor form leaves ε there). Rows
        // 0..p come from the table of knot jets; higher orders run A2.3.
        if (order <= p &&
            p + 1 <= kStackOrder) {  // (above degree 7 Eigen's product may sum in another order: computed here)
            const double* c = knot_jet(span, !at_start);
            for (int k = 0; k <= order; ++k)
                for (int e = 0; e < dim; ++e) out(k, e) = c[k * dim + e];
            return;
        }
        if (p + 1 <= kStackOrder && order + 1 <= kStackOrder) {
            BasisDerivatives ders;
            basis_function_derivatives_into(p, knots_, span, t, order, ders);
            out.noalias() = ders * control_.middleRows(span - p, p + 1);
        } else {
            out.noalias() =
                basis_function_derivatives(p, knots_, span, t, order) * control_.middleRows(span - p, p + 1);
        }
        return;
    }
    const double* c = taylor(span);
    const double h = t - span_middle(span);
    taylor_rows(p, dim, c, h, 0, order, out);
}

void BSplineCurve::evaluate_jet(double t, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const {
    const int order = first + static_cast<int>(out.rows()) - 1;
    int span = 0;
    if (side == JetSide::left) {
        // The last non-empty span [U_i, U_{i+1}) with U_i < t: the polynomial piece that ends at or after t.
        const int n = static_cast<int>(control_.rows());
        const auto it = std::lower_bound(knots_.begin() + degree_, knots_.begin() + n + 1, t);
        span = static_cast<int>(it - knots_.begin()) - 1;
    } else {
        span = find_span(t);
    }
    if (first == 0) return taylor_jet(span, t, order, out);
    if (t != knots_[static_cast<std::size_t>(span)] && t != knots_[static_cast<std::size_t>(span) + 1])
        return taylor_rows(degree_, dimension(), taylor(span), t - span_middle(span), 1, order,
                           out);  // off the knots: rows 1..order alone
    Eigen::MatrixXd jet(order + 1, dimension());
    taylor_jet(span, t, order, jet);
    out = jet.bottomRows(order);
}

std::vector<double> BSplineCurve::breakpoints() const {
    std::vector<double> b;
    for (int i = degree_; i <= static_cast<int>(control_.rows()); ++i)
        if (b.empty() || knots_[i] > b.back()) b.push_back(knots_[i]);
    return b;
}

double bspline_basis(int p, const std::vector<double>& k, double t, int derivative) {
    if (p < 0 || k.size() != static_cast<std::size_t>(p) + 2)
        fail_input("cagd::bspline_basis",
                   "needs degree+2 = " + std::to_string(p + 2) + " local knots, got " + std::to_string(k.size()));
    if (derivative < 0) fail_input("cagd::bspline_basis", "derivative must be >= 0");
    if (derivative > p) return 0.0;
    if (t < k.front() || t > k.back()) return 0.0;
    if (p == 0) {
        if (k[0] == k[1]) return 0.0;
        return (t < k[1] || t == k.back()) ? 1.0 : 0.0;
    }
    // Evaluate through the curve machinery: the function is the single basis function of
    // a B-spline whose knot vector is padded with p knots beyond each end.
    const double w = std::max(1.0, k.back() - k.front());
    std::vector<double> U;
    for (int i = p; i >= 1; --i) U.push_back(k.front() - w * i);
    U.insert(U.end(), k.begin(), k.end());
    for (int i = 1; i <= p; ++i) U.push_back(k.back() + w * i);
    // U has 3p+2 knots -> 2p+1 basis functions; ours is index p.
    Eigen::MatrixXd control = Eigen::MatrixXd::Zero(2 * p + 1, 1);
    control(p, 0) = 1.0;
    const BSplineCurve curve(p, U, control);
    // A2.3 at t itself (not the curve's Taylor form): exact zeros at the ends of the support.
    const int span = curve.find_span(t);
    const Eigen::MatrixXd ders = basis_function_derivatives(p, U, span, t, derivative);
    return (ders * control.middleRows(span - p, p + 1))(derivative, 0);
}

BSplineCurve insert_knot(const BSplineCurve& c, double t) {
    // Boehm's algorithm.
    if (!(t >= c.t_min() && t <= c.t_max()))
        fail_input("cagd::insert_knot", "t = " + full_precision(t) + " outside the domain");
    const int p = c.degree();
    const auto& U = c.knots();
    const Eigen::MatrixXd& P = c.control_points();
    const int n = static_cast<int>(P.rows());
    int k = c.find_span(t);
    if (t == c.t_max()) k = n - 1;
    std::vector<double> V(U.begin(), U.begin() + k + 1);
    V.push_back(t);
    V.insert(V.end(), U.begin() + k + 1, U.end());
    Eigen::MatrixXd Q(n + 1, P.cols());
    for (int i = 0; i <= n; ++i) {
        if (i <= k - p)
            Q.row(i) = P.row(i);
        else if (i > k)
            Q.row(i) = P.row(i - 1);
        else {
            const double denom = U[i + p] - U[i];
            const double a = denom > 0 ? (t - U[i]) / denom : 0.0;
            Q.row(i) = a * P.row(i) + (1.0 - a) * P.row(i - 1);
        }
    }
    return BSplineCurve(p, V, Q);
}

BSplineCurve elevate_degree(const BSplineCurve& c) {
    const int p = c.degree(), q = p + 1;
    const auto& U = c.knots();
    // Every knot with multiplicity +1, then trimmed so that the domain is unchanged:
    // new knot q (0-based) is the last copy of t_p, new knot n' is the first copy of t_n.
    std::vector<double> L;
    for (std::size_t i = 0; i < U.size(); ++i) {
        L.push_back(U[i]);
        if (i + 1 == U.size() || U[i + 1] != U[i]) L.push_back(U[i]);
    }
    const double a = c.t_min(), b = c.t_max();
    const auto last_a = static_cast<int>(std::upper_bound(L.begin(), L.end(), a) - L.begin()) - 1;
    const auto first_b = static_cast<int>(std::lower_bound(L.begin(), L.end(), b) - L.begin());
    std::vector<double> V;
    for (int i = last_a - q; i < 0; ++i) V.push_back(L.front());  // pad (clamped input)
    V.insert(V.end(), L.begin() + std::max(0, last_a - q),
             L.begin() + std::min<int>(static_cast<int>(L.size()), first_b + q + 1));
    while (static_cast<int>(V.size()) < (first_b - (last_a - q)) + q + 1) V.push_back(L.back());
    const int n_new = static_cast<int>(V.size()) - q - 1;
    // Least squares on q+1 Chebyshev samples per span: exact since r ∈ new space.
    const std::vector<double> br = c.breakpoints();
    const int samples = q + 1;
    const int rows = static_cast<int>(br.size() - 1) * samples;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(rows, n_new), B(rows, c.dimension());
    int row = 0;
    for (std::size_t s = 0; s + 1 < br.size(); ++s) {
        for (int j = 0; j < samples; ++j) {
            const double x = std::cos(std::numbers::pi * (2.0 * j + 1.0) / (2.0 * samples));
            const double t = 0.5 * (br[s] + br[s + 1]) + 0.5 * (br[s + 1] - br[s]) * x;
            const auto it = std::upper_bound(V.begin() + q, V.begin() + n_new, t);
            const int span = static_cast<int>(it - V.begin()) - 1;
            const Eigen::MatrixXd N = basis_function_derivatives(q, V, span, t, 0);
            for (int k = 0; k <= q; ++k) A(row, span - q + k) = N(0, k);
            B.row(row) = c.jet(t, 0).row(0);
            ++row;
        }
    }
    const Eigen::MatrixXd control = A.colPivHouseholderQr().solve(B);
    return BSplineCurve(q, V, control);
}

std::vector<BezierCurve> bezier_segments(const BSplineCurve& c) {
    const int p = c.degree();
    const std::vector<double> br = c.breakpoints();
    std::vector<BezierCurve> segments;
    for (std::size_t s = 0; s + 1 < br.size(); ++s)  // one-sided derivatives at both span ends (bezier.hpp)
        segments.emplace_back(bezier_from_end_jets(p, br[s + 1] - br[s], c.jet(br[s], p / 2),
                                                   c.jet_from_left(br[s + 1], std::max(0, p - p / 2 - 1))),
                              br[s], br[s + 1]);
    return segments;
}

}  // namespace cagd
