#include "cagd/intrinsic/curvature_profile_design.hpp"

#include <ceres/jet.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/intrinsic/detail/bezier_extraction.hpp"
#include "cagd/intrinsic/detail/design_system.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace cagd::intrinsic {

using detail::chord;
using detail::DesignWorkspace;
using detail::kMaxJetDegree;
using detail::kMaxOrdinates;
using detail::Ordinates;
using detail::SegmentJet;
using detail::shape_rows;
using detail::span_count;

namespace {

// Forward derivatives of a segment's Bézier ordinates with respect to its 2p knots and p + 1
// de Boor ordinates: 3p + 1 slots, the degree a template argument (ceres::Jet zeroes all its slots
// on construction: slots sized for degree 4 cost a degree-2 segment twice the work).
template <int P>
using JetOfDegree = ceres::Jet<double, 3 * P + 1>;

// ψ as the Newton iterations see it: the layout, the segment lengths and the de Boor ordinates read
// from the unknowns (checked as TangentAngleSpline checks them), without building the spline (its
// breakpoints, knot vectors and Bézier table, a twentieth of an iteration at 10^5 points).
struct DesignPsi {
    const KnotLayout& layout;
    const std::vector<double>& lengths;  // Δw_j, one per segment
    const double* de_boor;               // B_0..B_q
};

template <int P>
void segment_jet_of_degree(const DesignPsi& psi, int j, SegmentJet& out) {
    using Jet = JetOfDegree<P>;
    const KnotLayout& L = psi.layout;
    const int k0 = L.last_knot_of_breakpoint(j) - P + 1;
    double v[2 * P];
    TangentAngleSpline::local_farin_knots_into(L, psi.lengths, j,
                                               v);  // the extraction is invariant under a shift of all knots
    Jet u[2 * P], c[P + 1], b[P + 1];
    for (int m = 0; m < 2 * P; ++m) u[m] = Jet(v[m], m);
    for (int m = 0; m <= P; ++m) c[m] = Jet(psi.de_boor[k0 + m], 2 * P + m);
    detail::bezier_from_de_boor_of_degree<P>(u, c, b);
    const int g0 = L.breakpoint_of_knot(k0), g1 = L.breakpoint_of_knot(k0 + 2 * P - 1);
    out.b.resize(P + 1);
    out.first_ordinate = k0;
    out.first_segment = g0;
    out.db_dc.resize(P + 1, P + 1);
    out.db_dw.setZero(P + 1, std::max(g1 - g0, 1));
    for (int r = 0; r <= P; ++r) {
        out.b(r) = b[r].a;
        for (int m = 0; m <= P; ++m) out.db_dc(r, m) = b[r].v(2 * P + m);
        // knot m sits at w_{g(m)} = Σ_{i < g(m)} Δw_i: ∂/∂Δw_i = Σ_{m : g(m) > i} ∂/∂u_m.
        for (int m = 0; m < 2 * P; ++m) {
            const int g = L.breakpoint_of_knot(k0 + m);
            for (int i = g0; i < g; ++i) out.db_dw(r, i - g0) += b[r].v(m);
        }
    }
}

void segment_jet(const DesignPsi& psi, int j, SegmentJet& out) {
    switch (psi.layout.degree()) {
        case 2: segment_jet_of_degree<2>(psi, j, out); return;
        case 3: segment_jet_of_degree<3>(psi, j, out); return;
        case 4: segment_jet_of_degree<4>(psi, j, out); return;
        default:
            throw std::logic_error("cagd::intrinsic::segment_jet: degree " + std::to_string(psi.layout.degree()) +
                                   " is outside the layouts' 2..4");
    }
}

// Where J's entries go: triplets (the first evaluation, and whenever the pattern is not known), or
// straight into the value array of the last J, entry i added at the slot where triplet i was
// summed (JacobianSlots, checked as assemble_jacobian checks it): the same sums in the same order,
// so the same J, without the triplets' 16 bytes per entry written and read back.
struct JacobianSlots {
    double* value = nullptr;
    const int *inner = nullptr, *outer = nullptr, *slot = nullptr;
    std::size_t count = 0, next = 0;
    bool failed = false;  // an entry not where it was: the caller rebuilds J from triplets
};

class RowWriter {
public:
    RowWriter(const KnotLayout& L, std::vector<Eigen::Triplet<double>>* t, JacobianSlots* slots = nullptr)
        : L_(L), t_(t), slots_(slots) {}
    bool writes() const { return t_ || slots_; }
    // One entry of J.
    void entry(int row, int col, double v) const {
        if (slots_) {
            JacobianSlots& d = *slots_;
            if (d.next < d.count) {
                const int k = d.slot[d.next];
                if (d.inner[k] == row && k >= d.outer[col] && k < d.outer[col + 1]) {
                    d.value[k] += v;
                    ++d.next;
                    return;
                }
            }
            d.failed = true;
            ++d.next;
            return;
        }
        if (t_) t_->emplace_back(row, col, v);
    }
    // Row `row` depends on b_j through gradient g (∂f/∂b_{j,·}) and directly on Δw_j with `direct`.
    // Every entry that can be nonzero is written, even when it is zero at this u, so that J's
    // pattern depends on the layout alone (assemble_jacobian and the LU analyses reuse it).
    void add(int row, const SegmentJet& s, int j, const Ordinates& g, double direct) const {
        if (!writes()) return;
        add(row, s, j, g);
        entry(row, L_.length_index(j), direct);
    }
    // The same for a row with no direct dependence on Δw_j (shape and tangent-angle rows).
    void add(int row, const SegmentJet& s, int /*j*/, const Ordinates& g) const {
        if (!writes()) return;
        const int l = L_.independent_lengths();
        const Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, kMaxOrdinates> gc = g.transpose() * s.db_dc;
        const Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, 2 * kMaxJetDegree> gw =
            g.transpose() * s.db_dw;
        for (int m = 0; m < gc.size(); ++m) entry(row, l + s.first_ordinate + m, gc(m));
        for (int i = 0; i < gw.size(); ++i) entry(row, L_.length_index(s.first_segment + i), gw(i));
    }

private:
    const KnotLayout& L_;
    std::vector<Eigen::Triplet<double>>* t_;
    JacobianSlots* slots_;
};

// J from the triplets. The pattern depends on the layout, not on u, so from the second Newton
// iteration on each triplet's entry is found where it was (checked: its row, and its column's
// range) and the values are summed there in triplet order, as setFromTriplets sums duplicates: the
// same J, bit for bit, without the sort and transposition. Any triplet whose entry is not where it
// was (a pattern that changed) rebuilds J from the triplets.
void assemble_jacobian(int rows, int cols, DesignWorkspace& w, Eigen::SparseMatrix<double>& J) {
    const std::vector<Eigen::Triplet<double>>& t = w.triplets;
    bool same = J.rows() == rows && J.cols() == cols && J.isCompressed() && w.slots.size() == t.size();
    const int* outer = J.outerIndexPtr();
    const int* inner = J.innerIndexPtr();
    for (std::size_t i = 0; same && i < t.size(); ++i) {
        const int k = w.slots[i], c = t[i].col();
        same = inner[k] == t[i].row() && k >= outer[c] && k < outer[c + 1];
    }
    if (same) {
        double* value = J.valuePtr();
        std::fill(value, value + J.nonZeros(), 0.0);
        for (std::size_t i = 0; i < t.size(); ++i) value[w.slots[i]] += t[i].value();
        return;
    }
    J.resize(rows, cols);
    J.setFromTriplets(t.begin(), t.end());
    J.makeCompressed();
    w.slots.resize(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        const int c = t[i].col();
        const int* first = J.innerIndexPtr() + J.outerIndexPtr()[c];
        const int* last = J.innerIndexPtr() + J.outerIndexPtr()[c + 1];
        w.slots[i] = static_cast<int>(std::lower_bound(first, last, t[i].row()) - J.innerIndexPtr());
    }
}

// One evaluation of f(u) (and J(u), when `write` writes) into `out`.
void design_system_pass(const CurvatureProfileProblem& P, const Eigen::VectorXd& u, bool with_jacobian,
                        const RowWriter& write, DesignWorkspace& workspace, DesignSystem& out) {
    const KnotLayout& L = P.layout;
    const int p = L.degree(), k = L.segments(), rows = design_equations(P), cols = design_unknowns(P),
              l = L.independent_lengths();
    const char* who = "intrinsic::design_system";
    if (u.size() != cols)
        fail_input(who, "u needs " + std::to_string(cols) + " entries (eq 2), got " + std::to_string(u.size()));
    std::vector<double>& lengths = workspace.lengths;
    lengths.resize(static_cast<std::size_t>(k));
    for (int j = 0; j < k; ++j) lengths[static_cast<std::size_t>(j)] = u(L.length_index(j));
    TangentAngleSpline::require_valid_values(who, lengths, u.data() + l, static_cast<std::size_t>(cols - l));
    const DesignPsi psi{L, lengths, u.data() + l};
    std::vector<SegmentJet>& jets = workspace.jets;
    jets.resize(static_cast<std::size_t>(k));
    for (int j = 0; j < k; ++j) segment_jet(psi, j, jets[static_cast<std::size_t>(j)]);
    out.f.resize(rows);
    Eigen::VectorXd& row_scale = workspace.row_scale;  // each row's factor to a dimensionless equation
    row_scale.setOnes(rows);
    int row = 0;

    // eq (3): interpolation.
    for (int i = 0; i < L.spans(); ++i) {
        Eigen::Vector2d sum = Eigen::Vector2d::Zero();
        for (int j = L.first_segment(i); j < L.end_segment(i); ++j) {
            const SegmentJet& s = jets[static_cast<std::size_t>(j)];
            const double d = lengths[static_cast<std::size_t>(j)];
            DirectionWeights W;
            const Eigen::Vector2d I = direction_integrals(s.b, 1.0, with_jacobian ? &W : nullptr);
            sum += d * I;
            if (with_jacobian) {
                write.add(row, s, j, -d * W.row(1).transpose(), I(0));
                write.add(row + 1, s, j, d * W.row(0).transpose(), I(1));
            }
        }
        out.f.segment<2>(row) = sum - chord(P, i);
        row_scale.segment<2>(row).setConstant(1.0 / chord(P, i).norm());  // relative to the chord
        row += 2;
    }
    // eq (4): segment shapes.
    for (int j = 0; j < k; ++j) {
        const SegmentJet& s = jets[static_cast<std::size_t>(j)];
        auto linear_row = [&](const Ordinates& g) {
            out.f(row) = g.dot(s.b);
            write.add(row, s, j, g);
            ++row;
        };
        Ordinates g = Ordinates::Zero(p + 1);
        switch (P.shapes[static_cast<std::size_t>(j)]) {
            case SegmentShape::free: break;
            case SegmentShape::line:
                for (int r = 1; r <= p; ++r) {
                    g.setZero();
                    g(r) = 1.0, g(0) = -1.0;
                    linear_row(g);
                }
                break;
            case SegmentShape::arc:
                for (int r = 1; r < p; ++r) {
                    g.setZero();
                    g(r - 1) = 1.0, g(r) = -2.0, g(r + 1) = 1.0;
                    linear_row(g);
                }
                break;
            case SegmentShape::linear_curvature:
                g << -1.0, 3.0, -3.0, 1.0;
                linear_row(g);
                break;
        }
    }
    // eq (4): breakpoint conditions.
    auto angle_row = [&](int g, bool at_end, double sign) {  // adds sign·ψ(w_g) to the current row
        const int j = at_end ? g - 1 : g;
        const SegmentJet& s = jets[static_cast<std::size_t>(j)];
        Ordinates gr = Ordinates::Zero(p + 1);
        gr(at_end ? p : 0) = sign;
        write.add(row, s, j, gr);
        return sign * s.b(at_end ? p : 0);
    };
    auto curvature_row = [&](int g, bool at_end, double sign) {  // adds sign·κ(w_g^∓)
        const int j = at_end ? g - 1 : g;
        const SegmentJet& s = jets[static_cast<std::size_t>(j)];
        const double d = lengths[static_cast<std::size_t>(j)];
        Ordinates gr = Ordinates::Zero(p + 1);
        const int hi = at_end ? p : 1, lo = at_end ? p - 1 : 0;
        gr(hi) = sign * p / d, gr(lo) = -sign * p / d;
        const double kappa = p * (s.b(hi) - s.b(lo)) / d;
        write.add(row, s, j, gr, -sign * kappa / d);
        return sign * kappa;
    };
    // adds sign·κ^(m)(w_g^∓) = sign·ψ^(m+1): the (m+1)-th forward difference of the Bézier ordinates
    // at t = 0 (backward at t = 1) times p!/(p − m − 1)!, over Δw_j^(m+1).
    // The row is multiplied by chord^(m+1) (`chord`: a data length, not an unknown), so that it is
    // dimensionless like an angle row and rounds like one: κ'' of a short span is large.
    auto curvature_derivative_row = [&](int g, bool at_end, int m, double sign, double chord_length) {
        const int j = at_end ? g - 1 : g, e = m + 1;
        const SegmentJet& s = jets[static_cast<std::size_t>(j)];
        const double d = lengths[static_cast<std::size_t>(j)];
        double factor = 1.0, scale = 1.0;
        for (int i = 0; i < e; ++i) factor *= p - i, scale *= d / chord_length;
        Ordinates gr = Ordinates::Zero(p + 1);
        double binomial = 1.0;  // C(e, i)
        for (int i = 0; i <= e; ++i) {
            const double coefficient =
                ((e - i) % 2 == 0 ? 1.0 : -1.0) * binomial;  // Δ^e b_0 = Σ (−1)^(e−i) C(e, i) b_i
            gr(at_end ? p - e + i : i) = sign * factor * coefficient / scale;
            binomial = binomial * (e - i) / (i + 1);
        }
        const double value = gr.dot(s.b);
        write.add(row, s, j, gr, -e * value / d);
        return value;
    };
    for (const auto& c : P.conditions) {
        using K = DesignCondition::Kind;
        if (c.kind == K::tangent_angle) {
            out.f(row) = angle_row(c.index, c.index == k, 1.0) - c.value;
        } else if (c.kind == K::segment_length) {
            out.f(row) = lengths[static_cast<std::size_t>(c.index)] - c.value;
            write.entry(row, L.length_index(c.index), 1.0);
            row_scale(row) = 1.0 / chord(P, L.span_of_segment(c.index)).norm();
        } else if (c.kind == K::curvature_derivative) {
            const double h = chord(P, L.span_of_segment(c.from_left ? c.index - 1 : c.index)).norm();
            out.f(row) =
                curvature_derivative_row(c.index, c.from_left, c.order, 1.0, h) - std::pow(h, c.order + 1) * c.value;
        } else {
            const double target = c.kind == K::curvature ? c.value : 1.0 / c.value;
            out.f(row) = curvature_row(c.index, c.from_left, 1.0) - target;
            row_scale(row) = chord(P, L.span_of_segment(c.from_left ? c.index - 1 : c.index)).norm();
        }
        ++row;
    }
    if (P.closed) {
        out.f(row) = angle_row(k, true, 1.0) + angle_row(0, false, -1.0) - 2.0 * std::numbers::pi * closing_turns(P);
        ++row;
        const double h = 0.5 * (chord(P, 0).norm() + chord(P, L.spans() - 1).norm());
        out.f(row) = curvature_row(k, true, 1.0) + curvature_row(0, false, -1.0);
        row_scale(row) = h;
        ++row;
        for (int m = 1; m + 2 <= P.closing_continuity; ++m) {
            out.f(row) = curvature_derivative_row(k, true, m, 1.0, h) + curvature_derivative_row(0, false, m, -1.0, h);
            ++row;
        }
    }
    out.f.array() *= row_scale.array();
}

// J's rows times the pass's row scales (J in compressed column-major form).
void scale_jacobian_rows(const Eigen::VectorXd& scale, Eigen::SparseMatrix<double>& J) {
    double* value = J.valuePtr();
    const int* inner = J.innerIndexPtr();
    for (Eigen::Index k = 0; k < J.nonZeros(); ++k) value[k] *= scale(inner[k]);
}

}  // namespace

namespace detail {

// f(u) (and J(u)) into `out`, whose arrays (and J's pattern) are reused from call to call. Once J's
// pattern is known, J's entries are summed in place (JacobianSlots); should one not be where it
// was, the evaluation is redone with triplets and J rebuilt from them.
void design_system_into(const CurvatureProfileProblem& P, const Eigen::VectorXd& u, bool with_jacobian,
                        DesignWorkspace& workspace, DesignSystem& out) {
    const int rows = design_equations(P), cols = design_unknowns(P);
    Eigen::SparseMatrix<double>& J = out.jacobian;
    if (with_jacobian && J.rows() == rows && J.cols() == cols && J.isCompressed() && !workspace.slots.empty()) {
        std::fill(J.valuePtr(), J.valuePtr() + J.nonZeros(), 0.0);
        JacobianSlots slots{J.valuePtr(), J.innerIndexPtr(), J.outerIndexPtr(), workspace.slots.data(),
                            workspace.slots.size()};
        design_system_pass(P, u, true, RowWriter(P.layout, nullptr, &slots), workspace, out);
        if (!slots.failed && slots.next == slots.count) {
            scale_jacobian_rows(workspace.row_scale, J);
            return;
        }
    }
    std::vector<Eigen::Triplet<double>>& triplets = workspace.triplets;
    triplets.clear();
    design_system_pass(P, u, with_jacobian, RowWriter(P.layout, with_jacobian ? &triplets : nullptr), workspace, out);
    if (!with_jacobian) return;
    assemble_jacobian(rows, cols, workspace, J);
    scale_jacobian_rows(workspace.row_scale, J);
    std::vector<Eigen::Triplet<double>>().swap(triplets);  // the next evaluations write in place: free their memory
}

}  // namespace detail

DesignSystem design_system(const CurvatureProfileProblem& P, const Eigen::VectorXd& u, bool with_jacobian) {
    DesignWorkspace workspace;
    DesignSystem out;
    design_system_into(P, u, with_jacobian, workspace, out);
    return out;
}

DesignBandOrdering design_band_ordering(const CurvatureProfileProblem& P) {
    require_valid_problem(P, "intrinsic::design_band_ordering");
    const KnotLayout& L = P.layout;
    const int p = L.degree(), l = L.independent_lengths(), k = L.segments();
    // Each unknown's place: the mean centre (j + ½) of the segments j whose Bézier ordinates or
    // length it enters; each equation's: that of the segment or breakpoint it is written at.
    std::vector<double> column_key(static_cast<std::size_t>(design_unknowns(P)), 0.0), weight(column_key.size(), 0.0);
    for (int j = 0; j < k; ++j) {
        const double centre = j + 0.5;
        const std::size_t length = static_cast<std::size_t>(L.length_index(j));
        column_key[length] += centre, weight[length] += 1.0;
        const int k0 = L.last_knot_of_breakpoint(j) - p + 1;
        for (int m = 0; m <= p; ++m) {
            const std::size_t c = static_cast<std::size_t>(l + k0 + m);
            column_key[c] += centre, weight[c] += 1.0;
        }
    }
    for (std::size_t c = 0; c < column_key.size(); ++c)
        if (weight[c] > 0) column_key[c] /= weight[c];
    std::vector<double> row_key;
    row_key.reserve(static_cast<std::size_t>(design_equations(P)));
    for (int i = 0; i < L.spans(); ++i) row_key.insert(row_key.end(), 2, 0.5 * (L.first_segment(i) + L.end_segment(i)));
    for (int j = 0; j < k; ++j)
        row_key.insert(row_key.end(), static_cast<std::size_t>(shape_rows(P.shapes[static_cast<std::size_t>(j)], p)),
                       j + 0.5);
    for (const auto& c : P.conditions)
        row_key.push_back(c.kind == DesignCondition::Kind::segment_length ? c.index + 0.5 : c.index);
    if (P.closed)
        row_key.insert(row_key.end(), static_cast<std::size_t>(P.closing_continuity),
                       0.0);  // they join both ends: no place makes them narrow
    auto positions = [](const std::vector<double>& key) {
        std::vector<int> order(key.size()), position(key.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            return key[static_cast<std::size_t>(a)] < key[static_cast<std::size_t>(b)];
        });
        for (std::size_t i = 0; i < order.size(); ++i)
            position[static_cast<std::size_t>(order[i])] = static_cast<int>(i);
        return position;
    };
    return {positions(row_key), positions(column_key)};
}

Eigen::VectorXd c2_start(const CurvatureProfileProblem& P) {
    require_valid_problem(P, "intrinsic::c2_start");
    const KnotLayout& L = P.layout;
    const spline::PiecewiseHermiteCurve c2 =
        spline::cubic_spline_interpolant(P.points, spline::ParameterSpacing::chord_length, P.closed);
    const int n = L.spans();
    std::vector<double> span_length(static_cast<std::size_t>(n)), seg(static_cast<std::size_t>(L.segments()));
    for (int i = 0; i < n; ++i) {
        span_length[static_cast<std::size_t>(i)] =
            analysis::piece_arc_length(c2, i, i + 1, 1);  // one cubic piece, one 20-point rule: ample for a start
        const int a = L.first_segment(i), b = L.end_segment(i);
        for (int j = a; j < b; ++j)
            seg[static_cast<std::size_t>(j)] = span_length[static_cast<std::size_t>(i)] / (b - a);
    }
    const int l = L.independent_lengths();
    Eigen::VectorXd u = Eigen::VectorXd::Zero(l + L.ordinates());
    Eigen::VectorXd count = Eigen::VectorXd::Zero(l);
    for (int j = 0; j < L.segments(); ++j)
        u(L.length_index(j)) += seg[static_cast<std::size_t>(j)], count(L.length_index(j)) += 1;
    for (int i = 0; i < l; ++i) u(i) /= count(i);
    std::vector<double> lengths;
    for (int j = 0; j < L.segments(); ++j) lengths.push_back(u(L.length_index(j)));
    const TangentAngleSpline shape(L, lengths, Eigen::VectorXd::Zero(L.ordinates()));
    const std::vector<double> g = shape.greville_abscissae();
    // Span start positions in the (start) arc length.
    std::vector<double> span_start;
    for (int i = 0; i <= n; ++i)
        span_start.push_back(shape.breakpoints()[static_cast<std::size_t>(i < n ? L.first_segment(i) : L.segments())]);
    double previous = 0.0;
    for (int i = 0; i < L.ordinates(); ++i) {
        const double s = g[static_cast<std::size_t>(i)];
        int span = static_cast<int>(std::upper_bound(span_start.begin(), span_start.end(), s) - span_start.begin()) - 1;
        span = std::clamp(span, 0, n - 1);
        const double frac = std::clamp(
            (s - span_start[static_cast<std::size_t>(span)]) /
                (span_start[static_cast<std::size_t>(span) + 1] - span_start[static_cast<std::size_t>(span)]),
            0.0, 1.0);
        const Eigen::MatrixXd j = c2.jet(span + frac, 1);
        double a = std::atan2(j(1, 1), j(1, 0));
        if (i > 0) a += 2.0 * std::numbers::pi * std::round((previous - a) / (2.0 * std::numbers::pi));
        u(l + i) = previous = a;
    }
    return u;
}

}  // namespace cagd::intrinsic
