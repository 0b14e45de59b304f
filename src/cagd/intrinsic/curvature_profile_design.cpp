#include "cagd/intrinsic/curvature_profile_design.hpp"

#if CAGD_WITH_CERES
#include <ceres/ceres.h>
#endif
#include <ceres/jet.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/optional_dependencies.hpp"
#include "cagd/intrinsic/detail/bezier_extraction.hpp"
#include "cagd/numeric/banded_or_sparse_lu.hpp"
#include "cagd/numeric/sparse_lu.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace cagd::intrinsic {

namespace {

constexpr double kPi = std::numbers::pi;

int span_count(const CurvatureProfileProblem& P) { return static_cast<int>(P.points.rows()) - (P.closed ? 0 : 1); }

Eigen::Vector2d chord(const CurvatureProfileProblem& P, int span) {
    const Eigen::Index n = P.points.rows();
    const Eigen::Index a = span, b = (span + 1) % n;
    return (P.points.row(b) - P.points.row(a)).transpose();
}

double data_scale(const CurvatureProfileProblem& P) {
    double s = 1.0;
    for (int i = 0; i < span_count(P); ++i) s = std::max(s, chord(P, i).norm());
    return s;
}

int shape_rows(SegmentShape s, int p) {
    switch (s) {
        case SegmentShape::free: return 0;
        case SegmentShape::line: return p;
        case SegmentShape::arc: return p - 1;
        case SegmentShape::linear_curvature: return 1;
    }
    return 0;
}

// Newton's safeguards. The Moore–Penrose step treats singular values below kRankThreshold · σ_max
// as zero: the Jacobian's entries are O(1) in the data scale and exact, so 1e-10 separates true
// rank deficiency (σ ~ ε) from conditioning. A step shorter than kStalledStep · (1 + ‖u‖∞) is the
// rounding of u: Newton has settled. A step may shrink a span length to kKeptLengthFraction of
// itself at most (halving λ until it does), so lengths stay positive.
constexpr double kRankThreshold = 1e-10;
constexpr double kStalledStep = 1e-13;
constexpr double kKeptLengthFraction = 0.2;

// Forward derivatives of a segment's Bézier ordinates with respect to its 2p knots and p + 1
// de Boor ordinates: 3p + 1 slots, the degree a template argument (ceres::Jet zeroes all its slots
// on construction: slots sized for degree 4 cost a degree-2 segment twice the work).
constexpr int kMaxJetDegree = 4;
template <int P>
using JetOfDegree = ceres::Jet<double, 3 * P + 1>;

// The Bézier ordinates of segment j and their exact derivatives with respect to the local de Boor
// ordinates (columns first_ordinate..+p) and the local segment lengths (first_segment.., at most
// 2p − 1 of them). Sizes are dynamic within fixed storage: no allocation per segment and Newton
// iteration.
constexpr int kMaxOrdinates = kMaxJetDegree + 1;
using Ordinates = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxOrdinates, 1>;
struct SegmentJet {
    Ordinates b;
    int first_ordinate = 0, first_segment = 0;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxOrdinates, kMaxOrdinates> db_dc;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxOrdinates, 2 * kMaxJetDegree> db_dw;
};

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
    TangentAngleSpline::local_farin_knots_into(L, psi.lengths, j, v);  // the extraction is invariant under a shift of all knots
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
            throw std::logic_error("cagd::intrinsic::segment_jet: degree " + std::to_string(psi.layout.degree()) + " is outside the layouts' 2..4");
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
    RowWriter(const KnotLayout& L, std::vector<Eigen::Triplet<double>>* t, JacobianSlots* slots = nullptr) : L_(L), t_(t), slots_(slots) {}
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
        const Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, 2 * kMaxJetDegree> gw = g.transpose() * s.db_dw;
        for (int m = 0; m < gc.size(); ++m) entry(row, l + s.first_ordinate + m, gc(m));
        for (int i = 0; i < gw.size(); ++i) entry(row, L_.length_index(s.first_segment + i), gw(i));
    }

private:
    const KnotLayout& L_;
    std::vector<Eigen::Triplet<double>>* t_;
    JacobianSlots* slots_;
};

std::string fmt(double v) { return full_precision(v); }

}  // namespace

int closing_turns(const CurvatureProfileProblem& P) {
    if (P.turns != 0) return P.turns;
    double area = 0.0;
    const Eigen::Index n = P.points.rows();
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index j = (i + 1) % n;
        area += P.points(i, 0) * P.points(j, 1) - P.points(j, 0) * P.points(i, 1);
    }
    return area >= 0 ? 1 : -1;
}

const char* to_string(SegmentShape shape) {
    switch (shape) {
        case SegmentShape::free: return "free";
        case SegmentShape::line: return "line";
        case SegmentShape::arc: return "arc";
        case SegmentShape::linear_curvature: return "linear_curvature";
    }
    return "?";
}

std::vector<SegmentShape> parse_span_shapes(const std::string& text) {
    std::vector<SegmentShape> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        item.erase(0, item.find_first_not_of(" \t"));
        item.erase(item.find_last_not_of(" \t") + 1);
        if (item == "free")
            out.push_back(SegmentShape::free);
        else if (item == "line")
            out.push_back(SegmentShape::line);
        else if (item == "arc")
            out.push_back(SegmentShape::arc);
        else if (item == "clothoid" || item == "linear_curvature")
            out.push_back(SegmentShape::linear_curvature);
        else
            fail_input("intrinsic::parse_span_shapes", "span " + std::to_string(out.size()) + ": \"" + item + "\" is not a shape (allowed: free, line, arc, clothoid)");
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

std::vector<SegmentShape> segment_shapes(const KnotLayout& layout, const std::vector<SegmentShape>& span_shapes) {
    if (static_cast<int>(span_shapes.size()) != layout.spans())
        fail_input("intrinsic::segment_shapes", "needs one shape per span (" + std::to_string(layout.spans()) + "), got " + std::to_string(span_shapes.size()));
    std::vector<SegmentShape> out;
    for (int j = 0; j < layout.segments(); ++j) out.push_back(span_shapes[static_cast<std::size_t>(layout.span_of_segment(j))]);
    return out;
}

KnotLayout span_layout(const std::vector<SegmentShape>& span_shapes) {
    if (span_shapes.empty()) fail_input("intrinsic::span_layout", "needs at least one span");
    const int n = static_cast<int>(span_shapes.size());
    std::vector<int> mult{2}, index;
    for (int i = 1; i < n; ++i) {
        const auto a = span_shapes[static_cast<std::size_t>(i) - 1], b = span_shapes[static_cast<std::size_t>(i)];
        const bool rigid = a == SegmentShape::line || a == SegmentShape::arc || b == SegmentShape::line || b == SegmentShape::arc;
        mult.push_back(rigid ? 2 : 1);
    }
    mult.push_back(2);
    for (int i = 0; i < n; ++i) index.push_back(i);
    return KnotLayout(2, std::vector<int>(static_cast<std::size_t>(n), 1), mult, index);
}

void require_valid_problem(const CurvatureProfileProblem& P, const std::string& who) {
    require_valid_points(P.points, P.closed ? 3 : 2, true, P.closed, who);
    if (P.points.cols() != 2) fail_input(who, "points must be planar (2 columns), got " + std::to_string(P.points.cols()));
    const int n = span_count(P);
    if (P.layout.spans() != n)
        fail_input(who, "the knot layout has " + std::to_string(P.layout.spans()) + " spans but the " + std::to_string(P.points.rows()) +
                            (P.closed ? " points of a closed curve make " : " points make ") + std::to_string(n));
    if (static_cast<int>(P.shapes.size()) != P.layout.segments())
        fail_input(who, "needs one shape per segment (" + std::to_string(P.layout.segments()) + "), got " + std::to_string(P.shapes.size()));
    for (std::size_t j = 0; j < P.shapes.size(); ++j)
        if (P.shapes[j] == SegmentShape::linear_curvature && P.layout.degree() != 3)
            fail_input(who, "segment " + std::to_string(j) + ": linear_curvature needs a degree-3 ψ (a degree-2 ψ has linear curvature on every segment)");
    using K = DesignCondition::Kind;
    for (const auto& c : P.conditions) {
        const int top = P.layout.segments() - (c.kind == K::segment_length ? 1 : 0);
        if (c.index < 0 || c.index > top)
            fail_input(who, std::string(c.kind == K::segment_length ? "segment" : "breakpoint") + " index " + std::to_string(c.index) + " of a condition is outside 0.." +
                                std::to_string(top));
        if (!std::isfinite(c.value)) fail_input(who, "condition value " + fmt(c.value) + " is not finite");
        if (c.kind == K::curvature_radius && c.value == 0.0) fail_input(who, "curvature radius 0 at breakpoint " + std::to_string(c.index));
        if (c.kind == K::segment_length && !(c.value > 0)) fail_input(who, "segment length " + fmt(c.value) + " for segment " + std::to_string(c.index) + " must be > 0");
        const bool one_sided = c.kind == K::curvature || c.kind == K::curvature_radius || c.kind == K::curvature_derivative;
        if (one_sided && ((c.from_left && c.index == 0) || (!c.from_left && c.index == P.layout.segments())))
            fail_input(who, "curvature at breakpoint " + std::to_string(c.index) + " needs the side that has a segment");
        if (c.kind == K::curvature_derivative && (c.order < 1 || c.order > P.layout.degree() - 2))
            fail_input(who, "curvature derivative of order " + std::to_string(c.order) + " at breakpoint " + std::to_string(c.index) + ": a degree-" +
                                std::to_string(P.layout.degree()) + " ψ allows orders 1.." + std::to_string(P.layout.degree() - 2));
    }
    if (P.closed && std::abs(P.turns) > 100) fail_input(who, "turns = " + std::to_string(P.turns) + " is implausible (|turns| ≤ 100)");
    if (P.closed && (P.closing_continuity < 2 || P.closing_continuity > P.layout.degree()))
        fail_input(who, "closing continuity G" + std::to_string(P.closing_continuity) + " is outside G2..G" + std::to_string(P.layout.degree()) + " for a degree-" +
                            std::to_string(P.layout.degree()) + " ψ");
}

int design_unknowns(const CurvatureProfileProblem& P) { return P.layout.independent_lengths() + P.layout.ordinates(); }

int design_equations(const CurvatureProfileProblem& P) {
    int m = 2 * P.layout.spans() + static_cast<int>(P.conditions.size()) + (P.closed ? P.closing_continuity : 0);
    for (auto s : P.shapes) m += shape_rows(s, P.layout.degree());
    return m;
}

std::vector<std::string> design_equation_labels(const CurvatureProfileProblem& P) {
    std::vector<std::string> out;
    const int p = P.layout.degree();
    for (int i = 0; i < P.layout.spans(); ++i) {
        out.push_back("interpolation x, span " + std::to_string(i));
        out.push_back("interpolation y, span " + std::to_string(i));
    }
    for (int j = 0; j < P.layout.segments(); ++j) {
        const std::string seg = ", segment " + std::to_string(j);
        switch (P.shapes[static_cast<std::size_t>(j)]) {
            case SegmentShape::free: break;
            case SegmentShape::line:
                for (int r = 1; r <= p; ++r) out.push_back("line" + seg + ", b" + std::to_string(r) + " − b0");
                break;
            case SegmentShape::arc:
                for (int r = 1; r < p; ++r) out.push_back("arc" + seg + ", second difference at b" + std::to_string(r));
                break;
            case SegmentShape::linear_curvature: out.push_back("linear curvature" + seg + ", third difference"); break;
        }
    }
    for (const auto& c : P.conditions) {
        using K = DesignCondition::Kind;
        if (c.kind == K::segment_length) {
            out.push_back("length of segment " + std::to_string(c.index));
            continue;
        }
        const std::string what = c.kind == K::tangent_angle  ? "tangent angle"
                                 : c.kind == K::curvature    ? "curvature"
                                 : c.kind == K::curvature_radius ? "curvature radius"
                                                              : "curvature derivative " + std::to_string(c.order);
        out.push_back(what + " at breakpoint " + std::to_string(c.index));
    }
    if (P.closed) {
        out.push_back("closed: tangent angles differ by 2π·turns");
        out.push_back("closed: end curvatures equal");
        for (int d = 1; d + 2 <= P.closing_continuity; ++d) out.push_back("closed: end curvature derivatives " + std::to_string(d) + " equal");
    }
    return out;
}

namespace {

// The per-iteration arrays of design_system, kept by Newton from one iteration to the next: at
// 10^6 points they are hundreds of MB, and fresh pages each iteration cost a tenth of the solve.
struct DesignWorkspace {
    std::vector<double> lengths;  // Δw_j from u
    std::vector<SegmentJet> jets;
    std::vector<Eigen::Triplet<double>> triplets;  // J's entries while its pattern is not known (freed once it is)
    std::vector<int> slots;                        // entry i's place in the last Jacobian's value array
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
void design_system_pass(const CurvatureProfileProblem& P, const Eigen::VectorXd& u, bool with_jacobian, const RowWriter& write, DesignWorkspace& workspace,
                        DesignSystem& out) {
    const KnotLayout& L = P.layout;
    const int p = L.degree(), k = L.segments(), rows = design_equations(P), cols = design_unknowns(P), l = L.independent_lengths();
    const char* who = "intrinsic::design_system";
    if (u.size() != cols) fail_input(who, "u needs " + std::to_string(cols) + " entries (eq 2), got " + std::to_string(u.size()));
    std::vector<double>& lengths = workspace.lengths;
    lengths.resize(static_cast<std::size_t>(k));
    for (int j = 0; j < k; ++j) lengths[static_cast<std::size_t>(j)] = u(L.length_index(j));
    TangentAngleSpline::require_valid_values(who, lengths, u.data() + l, static_cast<std::size_t>(cols - l));
    const DesignPsi psi{L, lengths, u.data() + l};
    std::vector<SegmentJet>& jets = workspace.jets;
    jets.resize(static_cast<std::size_t>(k));
    for (int j = 0; j < k; ++j) segment_jet(psi, j, jets[static_cast<std::size_t>(j)]);
    out.f.resize(rows);
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
            const double coefficient = ((e - i) % 2 == 0 ? 1.0 : -1.0) * binomial;  // Δ^e b_0 = Σ (−1)^(e−i) C(e, i) b_i
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
        } else if (c.kind == K::curvature_derivative) {
            const double h = chord(P, L.span_of_segment(c.from_left ? c.index - 1 : c.index)).norm();
            out.f(row) = curvature_derivative_row(c.index, c.from_left, c.order, 1.0, h) - std::pow(h, c.order + 1) * c.value;
        } else {
            const double target = c.kind == K::curvature ? c.value : 1.0 / c.value;
            out.f(row) = curvature_row(c.index, c.from_left, 1.0) - target;
        }
        ++row;
    }
    if (P.closed) {
        out.f(row) = angle_row(k, true, 1.0) + angle_row(0, false, -1.0) - 2.0 * kPi * closing_turns(P);
        ++row;
        out.f(row) = curvature_row(k, true, 1.0) + curvature_row(0, false, -1.0);
        ++row;
        const double h = 0.5 * (chord(P, 0).norm() + chord(P, L.spans() - 1).norm());
        for (int m = 1; m + 2 <= P.closing_continuity; ++m) {
            out.f(row) = curvature_derivative_row(k, true, m, 1.0, h) + curvature_derivative_row(0, false, m, -1.0, h);
            ++row;
        }
    }
}

// f(u) (and J(u)) into `out`, whose arrays (and J's pattern) are reused from call to call. Once J's
// pattern is known, J's entries are summed in place (JacobianSlots); should one not be where it
// was, the evaluation is redone with triplets and J rebuilt from them.
void design_system_into(const CurvatureProfileProblem& P, const Eigen::VectorXd& u, bool with_jacobian, DesignWorkspace& workspace, DesignSystem& out) {
    const int rows = design_equations(P), cols = design_unknowns(P);
    Eigen::SparseMatrix<double>& J = out.jacobian;
    if (with_jacobian && J.rows() == rows && J.cols() == cols && J.isCompressed() && !workspace.slots.empty()) {
        std::fill(J.valuePtr(), J.valuePtr() + J.nonZeros(), 0.0);
        JacobianSlots slots{J.valuePtr(), J.innerIndexPtr(), J.outerIndexPtr(), workspace.slots.data(), workspace.slots.size()};
        design_system_pass(P, u, true, RowWriter(P.layout, nullptr, &slots), workspace, out);
        if (!slots.failed && slots.next == slots.count) return;
    }
    std::vector<Eigen::Triplet<double>>& triplets = workspace.triplets;
    triplets.clear();
    design_system_pass(P, u, with_jacobian, RowWriter(P.layout, with_jacobian ? &triplets : nullptr), workspace, out);
    if (!with_jacobian) return;
    assemble_jacobian(rows, cols, workspace, J);
    std::vector<Eigen::Triplet<double>>().swap(triplets);  // the next evaluations write in place: free their memory
}

}  // namespace

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
    for (int j = 0; j < k; ++j) row_key.insert(row_key.end(), static_cast<std::size_t>(shape_rows(P.shapes[static_cast<std::size_t>(j)], p)), j + 0.5);
    for (const auto& c : P.conditions) row_key.push_back(c.kind == DesignCondition::Kind::segment_length ? c.index + 0.5 : c.index);
    if (P.closed) row_key.insert(row_key.end(), static_cast<std::size_t>(P.closing_continuity), 0.0);  // they join both ends: no place makes them narrow
    auto positions = [](const std::vector<double>& key) {
        std::vector<int> order(key.size()), position(key.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[static_cast<std::size_t>(a)] < key[static_cast<std::size_t>(b)]; });
        for (std::size_t i = 0; i < order.size(); ++i) position[static_cast<std::size_t>(order[i])] = static_cast<int>(i);
        return position;
    };
    return {positions(row_key), positions(column_key)};
}

Eigen::VectorXd c2_start(const CurvatureProfileProblem& P) {
    require_valid_problem(P, "intrinsic::c2_start");
    const KnotLayout& L = P.layout;
    const spline::PiecewiseHermiteCurve c2 = spline::cubic_spline_interpolant(P.points, spline::ParameterSpacing::chord_length, P.closed);
    const int n = L.spans();
    std::vector<double> span_length(static_cast<std::size_t>(n)), seg(static_cast<std::size_t>(L.segments()));
    for (int i = 0; i < n; ++i) {
        span_length[static_cast<std::size_t>(i)] = analysis::piece_arc_length(c2, i, i + 1, 1);  // one cubic piece, one 20-point rule: ample for a start
        const int a = L.first_segment(i), b = L.end_segment(i);
        for (int j = a; j < b; ++j) seg[static_cast<std::size_t>(j)] = span_length[static_cast<std::size_t>(i)] / (b - a);
    }
    const int l = L.independent_lengths();
    Eigen::VectorXd u = Eigen::VectorXd::Zero(l + L.ordinates());
    Eigen::VectorXd count = Eigen::VectorXd::Zero(l);
    for (int j = 0; j < L.segments(); ++j) u(L.length_index(j)) += seg[static_cast<std::size_t>(j)], count(L.length_index(j)) += 1;
    for (int i = 0; i < l; ++i) u(i) /= count(i);
    std::vector<double> lengths;
    for (int j = 0; j < L.segments(); ++j) lengths.push_back(u(L.length_index(j)));
    const TangentAngleSpline shape(L, lengths, Eigen::VectorXd::Zero(L.ordinates()));
    const std::vector<double> g = shape.greville_abscissae();
    // Span start positions in the (start) arc length.
    std::vector<double> span_start;
    for (int i = 0; i <= n; ++i) span_start.push_back(shape.breakpoints()[static_cast<std::size_t>(i < n ? L.first_segment(i) : L.segments())]);
    double previous = 0.0;
    for (int i = 0; i < L.ordinates(); ++i) {
        const double s = g[static_cast<std::size_t>(i)];
        int span = static_cast<int>(std::upper_bound(span_start.begin(), span_start.end(), s) - span_start.begin()) - 1;
        span = std::clamp(span, 0, n - 1);
        const double frac =
            std::clamp((s - span_start[static_cast<std::size_t>(span)]) / (span_start[static_cast<std::size_t>(span) + 1] - span_start[static_cast<std::size_t>(span)]), 0.0, 1.0);
        const Eigen::MatrixXd j = c2.jet(span + frac, 1);
        double a = std::atan2(j(1, 1), j(1, 0));
        if (i > 0) a += 2.0 * kPi * std::round((previous - a) / (2.0 * kPi));
        u(l + i) = previous = a;
    }
    return u;
}

std::vector<double> CurvatureProfileSolution::segment_lengths() const {
    std::vector<double> out;
    if (!curve) return out;
    return curve->tangent_angle().segment_lengths();
}

namespace {

std::string worst_equation(const CurvatureProfileProblem& P, const Eigen::VectorXd& f) {
    Eigen::Index i = 0;
    f.cwiseAbs().maxCoeff(&i);
    return design_equation_labels(P)[static_cast<std::size_t>(i)] + " (|f| = " + fmt(std::abs(f(i))) + ")";
}

void finish_ok(const CurvatureProfileProblem& P, CurvatureProfileSolution& sol) {
    sol.curve.emplace(P.points.row(0).transpose(), TangentAngleSpline::from_unknowns(P.layout, sol.u));
}

}  // namespace

CurvatureProfileSolution solve_curvature_profile(const CurvatureProfileProblem& P, const Eigen::VectorXd& start, const NewtonOptions& options) {
    const std::string who = "intrinsic::solve_curvature_profile";
    require_valid_problem(P, who);
    if (options.max_iterations < 1 || !(options.tolerance > 0)) fail_input(who, "needs max_iterations ≥ 1 and tolerance > 0");
    if (!(options.required_contraction >= 0 && options.required_contraction < 1))
        fail_input(who, "needs 0 ≤ required_contraction < 1, got " + fmt(options.required_contraction));
    CurvatureProfileSolution sol;
    sol.unknowns = design_unknowns(P);
    sol.equations = design_equations(P);
    if (start.size() != sol.unknowns) fail_input(who, "start vector needs " + std::to_string(sol.unknowns) + " entries (eq 2), got " + std::to_string(start.size()));
    const int l = P.layout.independent_lengths();
    for (int i = 0; i < l; ++i)
        if (!(start(i) > 0) || !std::isfinite(start(i))) fail_input(who, "start length S_" + std::to_string(i) + " = " + fmt(start(i)) + " (finite and > 0 required)");
    if (options.step != NewtonStep::pseudo_inverse && sol.equations != sol.unknowns)
        fail_input(who, std::string("the ") + (options.step == NewtonStep::sparse_lu ? "sparse" : "banded") + " LU step needs a square system; this one has " +
                            std::to_string(sol.equations) + " equations and " + std::to_string(sol.unknowns) + " unknowns (use the pseudo-inverse)");
    const double tol = options.tolerance * data_scale(P);
    // The banded step says which LU it took once the band is known (below).
    const char* method = options.step == NewtonStep::pseudo_inverse ? "Newton with the Moore–Penrose step"
                         : options.step == NewtonStep::banded_lu    ? "Newton with banded LU"
                                                                    : "Newton with sparse LU";
    sol.u = start;
    // The Jacobian's sparsity pattern depends on the layout only, so its symbolic analysis (the
    // column ordering, a tenth of a sparse step's cost) is done once and redone only if the
    // pattern ever differs; the numeric factorisation is the same either way.
    numeric::BandedOrSparseLu lu;  // banded_lu: the band of the analysed pattern, when narrow
    std::vector<int> analysed_outer, analysed_inner;
    DesignWorkspace workspace;
    DesignSystem sys;
    double previous_residual = std::numeric_limits<double>::infinity();
    for (int it = 0;; ++it) {
        // A diverging iterate winds ψ by hundreds of turns between neighbouring ordinates; the
        // integrals of such a segment cost O(turning) and mean nothing: stop it as unconverged.
        const Eigen::VectorXd ordinates = sol.u.tail(P.layout.ordinates());
        const double turning = ordinates.size() > 1 ? (ordinates.tail(ordinates.size() - 1) - ordinates.head(ordinates.size() - 1)).lpNorm<Eigen::Infinity>() : 0.0;
        if (!(turning <= kMaxOrdinateTurning)) {
            sol.outcome = {Status::no_convergence, std::string(method) + " diverged at iteration " + std::to_string(it) + ": neighbouring tangent-angle ordinates differ by " +
                                                       fmt(turning) + " rad (limit " + fmt(kMaxOrdinateTurning) + ")"};
            return sol;
        }
        design_system_into(P, sol.u, true, workspace, sys);
        const double res = sys.f.lpNorm<Eigen::Infinity>();
        if (!std::isfinite(res)) {
            sol.outcome = {Status::no_convergence, std::string(method) + ": the residual became non-finite at iteration " + std::to_string(it)};
            return sol;
        }
        if (res <= tol) {
            sol.history.push_back({it, res, 0.0, 1.0, sol.rank});
            finish_ok(P, sol);
            return sol;
        }
        if (options.required_contraction > 0 && it > 0 && !(res <= options.required_contraction * previous_residual)) {
            sol.history.push_back({it, res, 0.0, 1.0, sol.rank});
            sol.outcome = {Status::no_convergence, std::string(method) + " from the given start does not contract: ‖f‖∞ = " + fmt(res) + " after " + fmt(previous_residual) +
                                                       " (required: at most " + fmt(options.required_contraction) + " of it)"};
            return sol;
        }
        previous_residual = res;
        if (it == options.max_iterations) {
            sol.history.push_back({it, res, 0.0, 1.0, sol.rank});
            sol.outcome = {Status::no_convergence, std::string(method) + " from the given start did not reach ‖f‖∞ ≤ " + fmt(tol) + " in " +
                                                       std::to_string(options.max_iterations) + " iterations: ‖f‖∞ = " + fmt(res) + ", worst equation " + worst_equation(P, sys.f) +
                                                       "; " + std::to_string(sol.equations) + " equations, " + std::to_string(sol.unknowns) + " unknowns, rank " +
                                                       std::to_string(sol.rank)};
            return sol;
        }
        Eigen::VectorXd delta;
        if (options.step == NewtonStep::pseudo_inverse) {
            // The threshold before the decomposition: the Z factor is built for the rank the
            // threshold gives at compute time, and solve() applies it for the rank it gives then.
            // Set afterwards, a lower rank would make solve() apply Z reflectors never computed.
            Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
            cod.setThreshold(kRankThreshold);
            cod.compute(Eigen::MatrixXd(sys.jacobian));
            sol.rank = static_cast<int>(cod.rank());
            delta = cod.solve(sys.f);
        } else {
            const Eigen::SparseMatrix<double>& J = sys.jacobian;
            const std::span<const int> outer(J.outerIndexPtr(), static_cast<std::size_t>(J.outerSize()) + 1), inner(J.innerIndexPtr(), static_cast<std::size_t>(J.nonZeros()));
            if (!J.isCompressed() || !std::equal(outer.begin(), outer.end(), analysed_outer.begin(), analysed_outer.end()) ||
                !std::equal(inner.begin(), inner.end(), analysed_inner.begin(), analysed_inner.end())) {
                if (options.step == NewtonStep::banded_lu && numeric::BandedLu::available()) {
                    DesignBandOrdering order = design_band_ordering(P);
                    lu.analyze(J, std::move(order.rows), std::move(order.columns), kMaxBandStorageRows);
                } else {
                    lu.analyze(J, {}, {}, 0);
                }
                method = lu.banded() ? "Newton with banded LU" : "Newton with sparse LU";
                analysed_outer.assign(outer.begin(), outer.end());
                analysed_inner.assign(inner.begin(), inner.end());
            }
            if (!lu.factorize(J)) {
                sol.outcome = {Status::no_convergence, std::string(method) + ": the Jacobian is singular at iteration " + std::to_string(it) + " (use the pseudo-inverse step)"};
                return sol;
            }
            delta = lu.solve(sys.f);
        }
        if (!delta.allFinite()) {
            sol.outcome = {Status::no_convergence, std::string(method) + ": non-finite step at iteration " + std::to_string(it)};
            return sol;
        }
        double lambda = 1.0;
        for (int i = 0; i < l; ++i)
            while (sol.u(i) - lambda * delta(i) < kKeptLengthFraction * sol.u(i)) lambda *= 0.5;
        const double step = lambda * delta.lpNorm<Eigen::Infinity>();
        sol.history.push_back({it, res, step, lambda, sol.rank});
        if (step <= kStalledStep * (1.0 + sol.u.lpNorm<Eigen::Infinity>())) {
            sol.outcome = {Status::no_solution, std::string(method) + " settled on a least-squares point with ‖f‖∞ = " + fmt(res) + " > " + fmt(tol) +
                                                    ": the conditions are inconsistent for these points (worst equation " + worst_equation(P, sys.f) + "; " +
                                                    std::to_string(sol.equations) + " equations, " + std::to_string(sol.unknowns) + " unknowns, rank " + std::to_string(sol.rank) +
                                                    ")"};
            return sol;
        }
        sol.u -= lambda * delta;
    }
}

CurvatureProfileSolution solve_curvature_profile(const CurvatureProfileProblem& P, const NewtonOptions& options) { return solve_curvature_profile(P, c2_start(P), options); }

#if CAGD_WITH_CERES
namespace {

struct DesignResidual {
    const CurvatureProfileProblem* problem;
    int unknowns;
    bool operator()(double const* const* parameters, double* residuals) const {
        const Eigen::Map<const Eigen::VectorXd> u(parameters[0], unknowns);
        for (int i = 0; i < problem->layout.independent_lengths(); ++i)
            if (!(u(i) > 0)) return false;
        const Eigen::VectorXd f = design_system(*problem, u, false).f;
        std::copy(f.data(), f.data() + f.size(), residuals);
        return f.allFinite();
    }
};

}  // namespace

namespace {

// The Levenberg–Marquardt cross-check. Its Jacobian is a central difference (error ~ε^(2/3) ≈
// 4e-11 relative), so it is accepted at ‖f‖∞ ≤ kLmAcceptance · scale, three digits above Newton's
// exact-Jacobian tolerance (NewtonOptions::tolerance, 1e-12): what it checks is the span lengths,
// to 1e-8 (fig2, fig3). Its own stopping rules are set below any reachable value so that only the
// iteration limit (LM takes tens of iterations here) or a stall ends it.
constexpr double kLmAcceptance = 1e-9;
constexpr int kLmIterations = 500;
constexpr double kLmFunctionTolerance = 1e-20, kLmGradientTolerance = 1e-20, kLmParameterTolerance = 1e-15;
// Span lengths are kept above this fraction of the data scale (a zero length is a degenerate span).
constexpr double kLmShortestSpan = 1e-6;

}  // namespace
#endif

CurvatureProfileSolution solve_curvature_profile_levenberg_marquardt(const CurvatureProfileProblem& P, const Eigen::VectorXd& start) {
    const std::string who = "intrinsic::solve_curvature_profile_levenberg_marquardt";
    require_valid_problem(P, who);
    require_built_with(OptionalDependency::ceres, who);
#if CAGD_WITH_CERES
    CurvatureProfileSolution sol;
    sol.unknowns = design_unknowns(P);
    sol.equations = design_equations(P);
    if (start.size() != sol.unknowns) fail_input(who, "start vector needs " + std::to_string(sol.unknowns) + " entries (eq 2), got " + std::to_string(start.size()));
    sol.u = start;
    auto* cost = new ceres::DynamicNumericDiffCostFunction<DesignResidual, ceres::CENTRAL>(new DesignResidual{&P, sol.unknowns});
    cost->AddParameterBlock(sol.unknowns);
    cost->SetNumResiduals(sol.equations);
    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, sol.u.data());
    const double scale = data_scale(P);
    for (int i = 0; i < P.layout.independent_lengths(); ++i) problem.SetParameterLowerBound(sol.u.data(), i, kLmShortestSpan * scale);
    ceres::Solver::Options opt;
    opt.minimizer_type = ceres::TRUST_REGION;
    opt.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    opt.linear_solver_type = ceres::DENSE_QR;
    opt.max_num_iterations = kLmIterations;
    opt.function_tolerance = kLmFunctionTolerance;
    opt.gradient_tolerance = kLmGradientTolerance;
    opt.parameter_tolerance = kLmParameterTolerance;
    opt.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(opt, &problem, &summary);
    const Eigen::VectorXd f = design_system(P, sol.u, false).f;
    const double res = f.lpNorm<Eigen::Infinity>();
    sol.history.push_back({static_cast<int>(summary.iterations.size()), res, 0.0, 1.0, -1});
    if (res <= kLmAcceptance * scale) {
        finish_ok(P, sol);
        return sol;
    }
    sol.outcome = {summary.termination_type == ceres::CONVERGENCE ? Status::no_solution : Status::no_convergence,
                   "Ceres Levenberg–Marquardt (" + summary.message + ") ended with ‖f‖∞ = " + fmt(res) + ", worst equation " + worst_equation(P, f)};
    return sol;
#else
    (void)start;
    return {};
#endif
}

void add_natural_open_ends(CurvatureProfileProblem& problem) {
    if (problem.closed || problem.shapes.empty()) return;
    if (problem.shapes.front() == SegmentShape::free) problem.conditions.push_back({DesignCondition::Kind::curvature, 0, 0.0, false});
    if (problem.shapes.back() == SegmentShape::free) problem.conditions.push_back({DesignCondition::Kind::curvature, problem.layout.segments(), 0.0, true});
}

CurvatureProfileSolution solve_curvature_profile_auto(const CurvatureProfileProblem& problem, const NewtonOptions& options) {
    return solve_curvature_profile_auto(problem, c2_start(problem), options);
}

CurvatureProfileSolution solve_curvature_profile_auto(const CurvatureProfileProblem& problem, const Eigen::VectorXd& start, const NewtonOptions& options) {
    // The Moore–Penrose step forms the Jacobian densely: n² doubles and O(n³) work per iteration
    // Above 2000 unknowns the sparse-LU outcome is the answer.
    constexpr int kDenseFallbackUnknowns = 2000;
    // Above this the LU step goes first: from about 60 unknowns on, a sparse or banded LU solve
    // costs less than the dense one.
    constexpr int kLuStepAboveUnknowns = 64;
    const int m = design_equations(problem), n = design_unknowns(problem);
    if (m == n && n > kLuStepAboveUnknowns) {
        NewtonOptions lu = options;
        lu.step = NewtonStep::banded_lu;
        CurvatureProfileSolution sol = solve_curvature_profile(problem, start, lu);
        if ((sol.outcome.ok() && sol.curve) || n > kDenseFallbackUnknowns) return sol;
    }
    NewtonOptions dense = options;
    dense.step = NewtonStep::pseudo_inverse;
    return solve_curvature_profile(problem, start, dense);
}

Eigen::VectorXd continuation_start(const CurvatureProfileProblem& P, const Eigen::VectorXd& start, const NewtonOptions& options) {
    require_valid_problem(P, "intrinsic::continuation_start");
    const KnotLayout& L = P.layout;
    const int n = L.spans(), p = L.degree();
    if (P.closed || start.size() != design_unknowns(P) || n < 4 * kContinuationWindowSpans) return start;
    const std::vector<SegmentShape> free(static_cast<std::size_t>(n), SegmentShape::free);
    if (!(L == span_layout(free)) || P.shapes != segment_shapes(L, free)) return start;
    for (const DesignCondition& c : P.conditions)
        if (c.kind == DesignCondition::Kind::segment_length || (c.index != 0 && c.index != n)) return start;
    for (int i = 0; i < L.independent_lengths(); ++i)
        if (!(start(i) > 0) || !std::isfinite(start(i))) return start;
    // The rows start leaves unsatisfied: the interpolation rows of spans i0..i1 only (span i: rows
    // 2i, 2i + 1; one segment per span, its own length and ordinates i..i + p).
    const Eigen::VectorXd f = design_system(P, start, false).f;
    const double tol = options.tolerance * data_scale(P);
    int i0 = n, i1 = -1;
    for (Eigen::Index r = 0; r < f.size(); ++r)
        if (!(std::abs(f(r)) <= tol)) {
            if (r >= 2 * n) return start;  // an end condition: not a moved point
            i0 = std::min(i0, static_cast<int>(r / 2)), i1 = std::max(i1, static_cast<int>(r / 2));
        }
    if (i1 < 0) return start;  // already solved
    const int a = std::max(0, i0 - kContinuationWindowSpans), b = std::min(n, i1 + 1 + kContinuationWindowSpans), m = b - a;
    if (4 * m > n) return start;
    // start's ψ at the window's ends: the first and last Bézier ordinates of segments a and b − 1.
    std::vector<double> lengths(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) lengths[static_cast<std::size_t>(j)] = start(L.length_index(j));
    const int l = L.independent_lengths();
    const auto psi_at = [&](int segment, bool at_end) {
        double knots[8], bezier[5];
        TangentAngleSpline::local_farin_knots_into(L, lengths, segment, knots);
        detail::bezier_from_de_boor(p, knots, start.data() + l + (L.last_knot_of_breakpoint(segment) - p + 1), bezier);
        return at_end ? bezier[p] : bezier[0];
    };
    const std::vector<SegmentShape> window_free(static_cast<std::size_t>(m), SegmentShape::free);
    CurvatureProfileProblem W{P.points.middleRows(a, m + 1), span_layout(window_free), {}, {}, false, 0};
    W.shapes = segment_shapes(W.layout, window_free);
    const double psi_a = psi_at(a, false);
    if (a > 0) W.conditions.push_back({.kind = DesignCondition::Kind::tangent_angle, .index = 0, .value = psi_a});
    if (b < n) W.conditions.push_back({.kind = DesignCondition::Kind::tangent_angle, .index = m, .value = psi_at(b - 1, true)});
    for (DesignCondition c : P.conditions) {
        if (a == 0 && c.index == 0) W.conditions.push_back(c);
        if (b == n && c.index == n) c.index = m, W.conditions.push_back(c);
    }
    // The window's own C2 start, turned by whole turns onto start's branch of ψ.
    Eigen::VectorXd w_start = c2_start(W);
    const int wl = W.layout.independent_lengths();
    w_start.tail(W.layout.ordinates()).array() += 2.0 * kPi * std::round((psi_a - w_start(wl)) / (2.0 * kPi));
    NewtonOptions cold = options;  // the window's own solve starts cold: no contraction required
    cold.required_contraction = 0.0;
    const CurvatureProfileSolution window = solve_curvature_profile_auto(W, w_start, cold);
    if (!(window.outcome.ok() && window.curve)) return start;
    // Set in: every window length; the ordinates whose p knots are the window's interior breakpoints
    // (the same blossom values as in the whole), and at an end of the curve the clamped ones too.
    Eigen::VectorXd u = start;
    for (int j = 0; j < m; ++j) u(L.length_index(a + j)) = window.u(W.layout.length_index(j));
    const int first = a == 0 ? 0 : p, last = b == n ? m + p - 1 : m - 1;
    for (int i = first; i <= last; ++i) u(l + a + i) = window.u(wl + i);
    return u;
}

}  // namespace cagd::intrinsic
