#include "cagd/intrinsic/tangent_angle_spline.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "cagd/core/bernstein_polynomial.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/intrinsic/detail/bezier_extraction.hpp"
#include "cagd/numeric/gauss_legendre.hpp"
#include "cagd/spline/bspline.hpp"

namespace cagd::intrinsic {

namespace {
// The turning (radians) one 16-point Gauss–Legendre piece integrates to rounding (the header's bound).
constexpr double kRadiansPerPiece = 3.0;

const numeric::GaussLegendreRule& rule16() {
    static const numeric::GaussLegendreRule rule(16);
    return rule;
}

// The whole segment (τ = 1, what the Newton's rows integrate) split into at most this many pieces
// has its Bernstein basis values at the quadrature nodes tabulated once per degree: the same
// numbers, computed by the same expressions at the same t, as the loop below would compute (an
// eighth of a degree-4 design's time went to recomputing them).
constexpr int kTabulatedPieces = 4;
constexpr int kNodes = 16;

// Row (m·16 + q)·5 + r: B_{r,p} at node q of piece m of `pieces`, for degree p; null beyond the table.
const double* tabulated_basis(int p, int pieces) {
    using Table = std::vector<double>;
    static const std::array<std::array<Table, kTabulatedPieces + 1>, 5> tables = [] {
        std::array<std::array<Table, kTabulatedPieces + 1>, 5> t;
        const auto& rule = rule16();
        for (int degree = 0; degree <= 4; ++degree)
            for (int count = 1; count <= kTabulatedPieces; ++count) {
                Table& v = t[static_cast<std::size_t>(degree)][static_cast<std::size_t>(count)];
                v.assign(static_cast<std::size_t>(count * kNodes * 5), 0.0);
                const double h = 1.0 / count;
                for (int m = 0; m < count; ++m) {
                    const double a = m * h;
                    for (int q = 0; q < kNodes; ++q) {
                        const double x = a + 0.5 * h * (rule.nodes()[static_cast<std::size_t>(q)] + 1.0);
                        bernstein_basis_values(degree, x,
                                               std::span<double>(&v[static_cast<std::size_t>((m * kNodes + q) * 5)],
                                                                 static_cast<std::size_t>(degree) + 1));
                    }
                }
            }
        return t;
    }();
    return pieces <= kTabulatedPieces ? tables[static_cast<std::size_t>(p)][static_cast<std::size_t>(pieces)].data()
                                      : nullptr;
}
}  // namespace

TangentAngleSpline::TangentAngleSpline(KnotLayout layout, std::vector<double> segment_lengths, Eigen::VectorXd de_boor)
    : layout_(std::move(layout)), lengths_(std::move(segment_lengths)), de_boor_(std::move(de_boor)) {
    const std::string who = "intrinsic::TangentAngleSpline";
    const int k = layout_.segments(), p = layout_.degree();
    if (static_cast<int>(lengths_.size()) != k)
        fail_input(who, "needs " + std::to_string(k) + " segment lengths, got " + std::to_string(lengths_.size()));
    if (de_boor_.size() != layout_.ordinates())
        fail_input(who, "needs " + std::to_string(layout_.ordinates()) + " de Boor ordinates, got " +
                            std::to_string(de_boor_.size()));
    require_valid_values(who.c_str(), lengths_, de_boor_.data(), static_cast<std::size_t>(de_boor_.size()));
    w_.push_back(0.0);
    for (int j = 0; j < k; ++j) w_.push_back(w_.back() + lengths_[static_cast<std::size_t>(j)]);
    const std::vector<double> v = farin_knots();
    basis_knots_ = v;
    basis_knots_.insert(basis_knots_.begin(), w_.front());
    basis_knots_.push_back(w_.back());
    bezier_.resize(k, p + 1);
    for (int j = 0; j < k; ++j) {
        const int last = layout_.last_knot_of_breakpoint(j);
        double u[8], c[5], b[5];  // p ≤ 4
        local_farin_knots_into(j, u);
        for (int m = 0; m <= p; ++m) c[m] = de_boor_(last - p + 1 + m);
        detail::bezier_from_de_boor(p, u, c, b);
        for (int m = 0; m <= p; ++m) bezier_(j, m) = b[m];
    }
}

void TangentAngleSpline::require_valid_values(const char* who, const std::vector<double>& lengths,
                                              const double* de_boor, std::size_t ordinates) {
    for (std::size_t j = 0; j < lengths.size(); ++j)
        if (!std::isfinite(lengths[j]) || lengths[j] <= 0)
            fail_input(who, "segment " + std::to_string(j) + " has length " + full_precision(lengths[j]) +
                                " (finite and > 0 required)");
    for (std::size_t i = 0; i < ordinates; ++i)
        if (!std::isfinite(de_boor[i]))
            fail_input(
                who, "de Boor ordinate B_" + std::to_string(i) + " = " + full_precision(de_boor[i]) + " is not finite");
}

TangentAngleSpline TangentAngleSpline::from_unknowns(const KnotLayout& layout, const Eigen::VectorXd& u) {
    const int l = layout.independent_lengths();
    if (u.size() != l + layout.ordinates())
        fail_input(
            "intrinsic::TangentAngleSpline::from_unknowns",
            "u needs " + std::to_string(l + layout.ordinates()) + " entries (eq 2), got " + std::to_string(u.size()));
    std::vector<double> lengths;
    for (int j = 0; j < layout.segments(); ++j) lengths.push_back(u(layout.length_index(j)));
    return TangentAngleSpline(layout, lengths, u.tail(layout.ordinates()));
}

std::vector<double> TangentAngleSpline::local_farin_knots(int segment) const {
    std::vector<double> out(static_cast<std::size_t>(2 * layout_.degree()));
    local_farin_knots_into(segment, out.data());
    return out;
}

void TangentAngleSpline::local_farin_knots_into(int segment, double* out) const {
    local_farin_knots_into(layout_, lengths_, segment, out);
}

void TangentAngleSpline::local_farin_knots_into(const KnotLayout& layout, const std::vector<double>& lengths,
                                                int segment, double* out) {
    const int p = layout.degree(), k0 = layout.last_knot_of_breakpoint(segment) - p + 1;
    for (int m = 0; m < 2 * p; ++m) {
        const int g = layout.breakpoint_of_knot(k0 + m);
        double x = 0.0;
        for (int i = segment; i < g; ++i) x += lengths[static_cast<std::size_t>(i)];
        for (int i = g; i < segment; ++i) x -= lengths[static_cast<std::size_t>(i)];
        out[m] = x;
    }
}

std::vector<double> TangentAngleSpline::farin_knots() const {
    std::vector<double> v;
    for (int i = 0; i < layout_.farin_knot_count(); ++i)
        v.push_back(w_[static_cast<std::size_t>(layout_.breakpoint_of_knot(i))]);
    return v;
}

std::vector<double> TangentAngleSpline::greville_abscissae() const {
    const std::vector<double> v = farin_knots();
    const int p = degree();
    std::vector<double> g;
    for (int i = 0; i < layout_.ordinates(); ++i) {
        double s = 0.0;
        for (int m = 0; m < p; ++m) s += v[static_cast<std::size_t>(i + m)];
        g.push_back(s / p);
    }
    return g;
}

int TangentAngleSpline::segment_at(double s) const {
    if (!(s >= 0.0 && s <= length()))
        fail_input("intrinsic::TangentAngleSpline",
                   "arc length s = " + full_precision(s) + " outside [0, " + full_precision(length()) + "]");
    const auto it = std::upper_bound(w_.begin(), w_.end(), s);
    return std::min(static_cast<int>(it - w_.begin()) - 1, segments() - 1);
}

Eigen::VectorXd TangentAngleSpline::jet(double s, int order) const { return jet_in_segment(segment_at(s), s, order); }

Eigen::VectorXd TangentAngleSpline::jet_in_segment(int j, double s, int order) const {
    if (order < 0) fail_input("intrinsic::TangentAngleSpline::jet", "order must be ≥ 0, got " + std::to_string(order));
    Eigen::VectorXd out(order + 1);
    if (order <= 7) {
        jet_in_segment_into(j, s, order, out.data());
        return out;
    }
    const int p = degree(), span = checked_span(j, s);
    const Eigen::MatrixXd N = basis_function_derivatives(p, basis_knots_, span, s, order);
    out.setZero();
    for (int d = 0; d <= order; ++d)
        for (int m = 0; m <= p; ++m) out(d) += N(d, m) * de_boor_(span - p + m);
    return out;
}

int TangentAngleSpline::checked_span(int j, double s) const {
    const char* who = "intrinsic::TangentAngleSpline::jet";
    if (j < 0 || j >= segments())
        fail_input(who, "segment " + std::to_string(j) + " outside 0.." + std::to_string(segments() - 1));
    const double lo = w_[static_cast<std::size_t>(j)], hi = w_[static_cast<std::size_t>(j) + 1];
    if (!(s >= lo && s <= hi))
        fail_input(who, "s = " + full_precision(s) + " outside segment " + std::to_string(j) + " [" +
                            full_precision(lo) + ", " + full_precision(hi) + "]");
    return layout_.last_knot_of_breakpoint(j) + 1;
}

void TangentAngleSpline::jet_in_segment_into(int j, double s, int order, double* out) const {
    if (order < 0 || order > 7)
        fail_input("intrinsic::TangentAngleSpline::jet_in_segment_into",
                   "order must be 0..7, got " + std::to_string(order));
    const int p = degree(), span = checked_span(j, s);
    BasisDerivatives N;
    basis_function_derivatives_into(p, basis_knots_, span, s, order, N);
    for (int d = 0; d <= order; ++d) {
        out[d] = 0.0;
        for (int m = 0; m <= p; ++m) out[d] += N(d, m) * de_boor_(span - p + m);
    }
}

double TangentAngleSpline::angle(int segment, bool at_end) const {
    return at_end ? bezier_(segment, degree()) : bezier_(segment, 0);
}

double TangentAngleSpline::curvature(int segment, bool at_end) const {
    const int p = degree();
    const double d = lengths_[static_cast<std::size_t>(segment)];
    return at_end ? p * (bezier_(segment, p) - bezier_(segment, p - 1)) / d
                  : p * (bezier_(segment, 1) - bezier_(segment, 0)) / d;
}

namespace {

// The integrals and weights for degree P (a template constant, so that the loops over the
// ordinates unroll; P < 0: the degree is b's), on plain arrays: b copied in, the weights summed in
// w[2][5] and copied out. The same operations in the same order for every P, so the same values.
template <int P>
Eigen::Vector2d direction_integrals_of_degree(
    const Eigen::Ref<const Eigen::VectorXd, 0, Eigen::InnerStride<>>& ordinates, double tau, double (*w)[5]) {
    const int p = P >= 0 ? P : static_cast<int>(ordinates.size()) - 1;
    double b[5];
    for (int r = 0; r <= p; ++r) b[r] = ordinates(r);
    double bound = 0.0;
    for (int r = 0; r < p; ++r) bound = std::max(bound, std::abs(p * (b[r + 1] - b[r])));
    const int pieces = std::max(1, static_cast<int>(std::ceil(bound * tau / kRadiansPerPiece)));
    const auto& rule = rule16();
    const double* nodes = rule.nodes().data();
    const double* weights = rule.weights().data();
    double sum0 = 0.0, sum1 = 0.0, w0[5] = {0.0, 0.0, 0.0, 0.0, 0.0},
           w1[5] = {0.0, 0.0, 0.0, 0.0, 0.0};  // local: kept in registers
    const bool weighted = w != nullptr;
    const double h = tau / pieces;
    const double* table = tau == 1.0 ? tabulated_basis(p, pieces) : nullptr;
    for (int m = 0; m < pieces; ++m) {
        const double a = m * h;
        for (int q = 0; q < kNodes; ++q) {
            const double wq = 0.5 * h * weights[q];
            double computed[5];
            const double* B = computed;
            if (table) {
                B = table + (m * kNodes + q) * 5;
            } else {
                const double t = a + 0.5 * h * (nodes[q] + 1.0);
                bernstein_basis_values(p, t, std::span<double>(computed, static_cast<std::size_t>(p) + 1));
            }
            double psi = 0.0;
            for (int r = 0; r <= p; ++r) psi += b[r] * B[r];
            const double c = std::cos(psi), s = std::sin(psi);
            sum0 += wq * c;
            sum1 += wq * s;
            if (weighted)
                for (int r = 0; r <= p; ++r) {
                    w0[r] += wq * c * B[r];
                    w1[r] += wq * s * B[r];
                }
        }
    }
    if (weighted)
        for (int r = 0; r <= p; ++r) w[0][r] = w0[r], w[1][r] = w1[r];
    return {sum0, sum1};
}

template <class Weights>
Eigen::Vector2d direction_integrals_with(const Eigen::Ref<const Eigen::VectorXd, 0, Eigen::InnerStride<>>& b,
                                         double tau, Weights* weights) {
    const int p = static_cast<int>(b.size()) - 1;
    if (p < 0 || p > 4)
        fail_input("intrinsic::direction_integrals", "Bézier degree must be 0..4, got " + std::to_string(p));
    if (!(tau >= 0.0 && tau <= 1.0))
        fail_input("intrinsic::direction_integrals", "tau = " + full_precision(tau) + " outside [0, 1]");
    if (weights && tau != 1.0)
        fail_input("intrinsic::direction_integrals", "weighted integrals need tau = 1, got " + full_precision(tau));
    double w[2][5];
    double(*out)[5] = weights ? w : nullptr;
    Eigen::Vector2d sum;
    switch (p) {  // the designs' degrees unrolled
        case 2: sum = direction_integrals_of_degree<2>(b, tau, out); break;
        case 3: sum = direction_integrals_of_degree<3>(b, tau, out); break;
        case 4: sum = direction_integrals_of_degree<4>(b, tau, out); break;
        default: sum = direction_integrals_of_degree<-1>(b, tau, out); break;
    }
    if (weights) {
        weights->resize(2, p + 1);
        for (int r = 0; r <= p; ++r) (*weights)(0, r) = w[0][r], (*weights)(1, r) = w[1][r];
    }
    return sum;
}

}  // namespace

Eigen::Vector2d direction_integrals(const Eigen::Ref<const Eigen::VectorXd, 0, Eigen::InnerStride<>>& b, double tau,
                                    Eigen::Matrix<double, 2, Eigen::Dynamic>* weights) {
    return direction_integrals_with(b, tau, weights);
}

Eigen::Vector2d direction_integrals(const Eigen::Ref<const Eigen::VectorXd, 0, Eigen::InnerStride<>>& b, double tau,
                                    DirectionWeights* weights) {
    return direction_integrals_with(b, tau, weights);
}

}  // namespace cagd::intrinsic
