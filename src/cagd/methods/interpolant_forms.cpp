#include "cagd/methods/interpolant_forms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
// Boost 1.74's pchip.hpp and makima.hpp call isnan unqualified on a double, which only compiles if
// std::isnan is visible where the templates are defined.
using std::isnan;
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/pchip.hpp>

#include "cagd/core/errors.hpp"
#include "cagd/core/finite.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace cagd::methods {

namespace {

std::vector<double> unit_nodes(Eigen::Index nodes) {
    std::vector<double> u(static_cast<std::size_t>(nodes));
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = static_cast<double>(i);
    return u;
}

// Boost's slopes at the nodes. Boost keeps them private; its public prime(x) reads one with a binary
// search (2n searches through megabytes: five times the construction at 10^6 points). Boost's
// documented rules are local and cheap, so they are computed here in O(n), in the order Boost's
// pchip and makima evaluate them (below), and every construction checks them bit for bit against
// Boost's own on kCheckedBlocks sampled blocks, both ends included; should any differ (another
// Boost, another rounding), every slope is read from Boost block by block instead. Either way the
// slopes are Boost's bit for bit (tests/methods/test_boost_peers.cpp holds all nodes to this).
//
// Reading from Boost by blocks: the slope at node k depends on the nodes k − reach … k + reach
// only (pchip: reach 1; makima: reach 2) and, at the ends, on the end nodes; so interpolators over
// blocks of kSlopeBlock nodes, each extended by `reach` nodes on either side, compute every slope
// with the same arithmetic on the same values, and each search stays in cache.
constexpr Eigen::Index kSlopeBlock = 256;
// Sampled blocks checked per construction and coordinate: both ends (their own rules) and evenly
// spaced interior blocks. 8 blocks of 256: Boost interpolates about 2,000 nodes again (with their
// reach), 0.2 % of the nodes of a construction at 10^6 points.
constexpr Eigen::Index kCheckedBlocks = 8;

// Boost's slopes for the nodes a ≤ k < b into out[k − a], from one interpolator over a … b widened
// by `reach`.
template <class Interpolator>
void boost_slopes_in(const std::vector<double>& tau, const double* y, Eigen::Index reach, Eigen::Index a, Eigen::Index b, double* out) {
    const Eigen::Index n = static_cast<Eigen::Index>(tau.size());
    const Eigen::Index lo = std::max<Eigen::Index>(0, a - reach), hi = std::min(n, b + reach);
    std::vector<double> x(tau.begin() + lo, tau.begin() + hi), v(y + lo, y + hi);
    const Interpolator f(std::move(x), std::move(v));
    for (Eigen::Index k = a; k < b; ++k) out[k - a] = f.prime(tau[static_cast<std::size_t>(k)]);
}

// The blocks [a, b) that cover 0 … n − 1, with no short last block (Boost needs four points).
template <class Visit>
void for_each_slope_block(Eigen::Index n, Visit visit) {
    for (Eigen::Index a = 0; a < n;) {
        Eigen::Index b = std::min(n, a + kSlopeBlock);
        if (n - b < kSlopeBlock / 4) b = n;
        visit(a, b);
        a = b;
    }
}

// Where node k's slope s (dy/dτ) goes in one coordinate of the Hermite form's slope column: m_k = s
// (PiecewiseHermiteCurve::from_node_slopes forms d0_k = h_k m_k and d1_{k−1} = h_{k−1} m_k).
struct NodeSlopeSink {
    double* m;
    std::size_t n;  // nodes
    void put(std::size_t k, double s) const { m[k] = s; }
    bool holds(std::size_t k, double s) const { return bits_of(m[k]) == bits_of(s); }  // bit for bit
};

// Boost pchip's rule (Fritsch–Butland): with secants d_k = Δy_k / h_k, h_k = τ_{k+1} − τ_k, the
// slope at an interior node is 0 where d_{k−1} and d_k differ in sign or either is 0, else the
// weighted harmonic mean (w1 + w2)/(w1/d_{k−1} + w2/d_k), w1 = 2h_k + h_{k−1}, w2 = h_k + 2h_{k−1};
// at the ends the one-sided secant. Each secant is formed once (the same value as Boost's twice).
void pchip_rule_slopes(const std::vector<double>& x, const double* y, const NodeSlopeSink& out) {
    const std::size_t n = x.size();
    double hkm1 = x[1] - x[0], dkm1 = (y[1] - y[0]) / hkm1;
    out.put(0, dkm1);
    for (std::size_t k = 1; k + 1 < n; ++k) {
        const double hk = x[k + 1] - x[k], dk = (y[k + 1] - y[k]) / hk;
        const double w1 = 2 * hk + hkm1, w2 = hk + 2 * hkm1;
        out.put(k, ((dk > 0 && dkm1 < 0) || (dk < 0 && dkm1 > 0) || dk == 0 || dkm1 == 0) ? 0.0 : (w1 + w2) / (w1 / dkm1 + w2 / dk));
        hkm1 = hk;
        dkm1 = dk;
    }
    out.put(n - 1, dkm1);
}

// Boost makima's rule (Akima's weights, modified): with secants m_i, the slope at node i is
// (w1 m_{i−1} + w2 m_i)/(w1 + w2), w1 = |m_{i+1} − m_i| + |m_{i+1} + m_i|/2,
// w2 = |m_{i−1} − m_{i−2}| + |m_{i−1} + m_{i−2}|/2, 0 where that is 0/0; beyond the ends the
// secants are extrapolated quadratically (m_{−1} = 2m_0 − m_1, m_{−2} = 2m_{−1} − m_0, and so at
// the other end).
double makima_weighted(double wa, double ma, double wb, double mb) {
    const double s = (wa * ma + wb * mb) / (wa + wb);
    return std::isnan(s) ? 0.0 : s;
}
double makima_weight(double m1, double m0) { return std::abs(m1 - m0) + std::abs(m1 + m0) / 2; }

void makima_rule_slopes(const std::vector<double>& x, const double* y, const NodeSlopeSink& out) {
    const std::size_t n = x.size();
    const auto secant = [&](std::size_t i) { return (y[i + 1] - y[i]) / (x[i + 1] - x[i]); };
    {
        const double m2 = secant(2), m1 = secant(1), m0 = secant(0);
        const double mm1 = 2 * m0 - m1, mm2 = 2 * mm1 - m0;
        out.put(0, makima_weighted(makima_weight(m1, m0), mm1, makima_weight(mm1, mm2), m0));
        out.put(1, makima_weighted(makima_weight(m2, m1), m0, makima_weight(m0, mm1), m1));
    }
    // Each secant and each weight once (the same values as Boost's recomputed ones): node i takes
    // w1 = W_i and w2 = W_{i−2}, W_k = makima_weight(m_{k+1}, m_k).
    double mim1 = secant(1), mi = secant(2), w_im2 = makima_weight(mim1, secant(0)), w_im1 = makima_weight(mi, mim1);
    for (std::size_t i = 2; i + 2 < n; ++i) {
        const double mip1 = secant(i + 1), w_i = makima_weight(mip1, mi);
        out.put(i, makima_weighted(w_i, mim1, w_im2, mi));
        mim1 = mi;
        mi = mip1;
        w_im2 = w_im1;
        w_im1 = w_i;
    }
    const double mnm4 = secant(n - 4), mnm3 = secant(n - 3), mnm2 = secant(n - 2);
    const double mnm1 = 2 * mnm2 - mnm3, mn = 2 * mnm1 - mnm2;
    out.put(n - 2, makima_weighted(makima_weight(mnm1, mnm2), mnm3, makima_weight(mnm3, mnm4), mnm2));
    out.put(n - 1, makima_weighted(makima_weight(mn, mnm1), mnm2, makima_weight(mnm2, mnm3), mnm1));
}

// Whether the derivatives `out` holds are those of Boost's slopes, bit for bit, on kCheckedBlocks
// blocks spread over the nodes (or on every block).
template <class Interpolator>
bool rule_slopes_match_boost(const std::vector<double>& tau, const double* y, Eigen::Index reach, const NodeSlopeSink& out, bool every_block = false) {
    const Eigen::Index n = static_cast<Eigen::Index>(tau.size());
    std::vector<std::pair<Eigen::Index, Eigen::Index>> blocks;
    for_each_slope_block(n, [&](Eigen::Index a, Eigen::Index b) { blocks.emplace_back(a, b); });
    const std::size_t count = blocks.size(), checked = every_block ? count : std::min<std::size_t>(count, kCheckedBlocks);
    std::vector<double> boost_slopes(static_cast<std::size_t>(2 * kSlopeBlock));  // a block is shorter than two
    for (std::size_t j = 0; j < checked; ++j) {
        const auto [a, b] = blocks[checked == 1 ? 0 : j * (count - 1) / (checked - 1)];
        boost_slopes.resize(static_cast<std::size_t>(b - a));
        boost_slopes_in<Interpolator>(tau, y, reach, a, b, boost_slopes.data());
        for (Eigen::Index k = a; k < b; ++k)
            if (!out.holds(static_cast<std::size_t>(k), boost_slopes[static_cast<std::size_t>(k - a)])) return false;
    }
    return true;
}

template <class Interpolator, class Rule>
Interpolant componentwise_chord_interpolant(const char* function, const PointList& p, Eigen::Index reach, Rule rule) {
    if (p.rows() < 4) fail_input(function, "needs at least 4 points (Boost's pchip and makima), got " + std::to_string(p.rows()));
    std::vector<double> h = chord_lengths(p, false);
    const Eigen::Index n = p.rows();
    Eigen::MatrixXd nodes = p, m(n, p.cols());
    {  // the chord-length parameters live only while the slopes are filled (peak memory)
        std::vector<double> tau{0.0};
        tau.reserve(h.size() + 1);
        for (double hk : h) tau.push_back(tau.back() + hk);
        for (Eigen::Index c = 0; c < p.cols(); ++c) {
            const double* y = p.col(c).data();
            const NodeSlopeSink out{m.col(c).data(), static_cast<std::size_t>(n)};
            rule(tau, y, out);
            if (!rule_slopes_match_boost<Interpolator>(tau, y, reach, out)) {
                std::vector<double> block;
                for_each_slope_block(n, [&](Eigen::Index a, Eigen::Index b) {
                    block.resize(static_cast<std::size_t>(b - a));
                    boost_slopes_in<Interpolator>(tau, y, reach, a, b, block.data());
                    for (Eigen::Index k = a; k < b; ++k) out.put(static_cast<std::size_t>(k), block[static_cast<std::size_t>(k - a)]);
                });
            }
        }
    }
    auto curve = std::make_shared<spline::PiecewiseHermiteCurve>(spline::PiecewiseHermiteCurve::from_node_slopes(std::move(nodes), std::move(m), h));
    return unit_span_interpolant(std::move(curve), n, std::move(h));
}

// Boost catmull_rom's derivative at its own node i, s = t_i: the Barry–Goldman pyramid
// differentiated by the product rule, as Boost's prime(s) forms it, the same operations in the same
// order (so the same bits; checked against Boost below). t0 … t3 are Boost's parameters
// t_{i−1} … t_{i+2}, P0 … P3 its points there, and r_ab = 1/(t_b − t_a), the reciprocals Boost
// forms (neighbouring nodes share them: node i + 1's r01, r12, r02 are node i's r12, r23, r13).
// (Boost's B1 weighs A1 and A2 by A2's factors; at s = t_i both are P_i, so the value is the
// pyramid's.)
struct CatmullRomReciprocals {
    double r01, r12, r23, r13, r02;
};

template <std::size_t D>
[[gnu::always_inline]] inline std::array<double, D> catmull_rom_slope_at_node(double t0, double t1, double t2, double t3, const CatmullRomReciprocals& r,
                                                                              const std::array<const double*, 4>& P, Eigen::Index stride) {
    const double s = t1;
    const auto x = [&](int point, std::size_t c) { return P[static_cast<std::size_t>(point)][static_cast<Eigen::Index>(c) * stride]; };
    std::array<double, D> A1, A1p, A2, A2p, B1, A3, A3p, B2, B1p, B2p, Cp;
    double denom = r.r01, k1 = (t1 - s) * denom, k2 = (s - t0) * denom;
    for (std::size_t c = 0; c < D; ++c) A1[c] = k1 * x(0, c) + k2 * x(1, c);
    for (std::size_t c = 0; c < D; ++c) A1p[c] = denom * (x(1, c) - x(0, c));
    denom = r.r12, k1 = (t2 - s) * denom, k2 = (s - t1) * denom;
    for (std::size_t c = 0; c < D; ++c) A2[c] = k1 * x(1, c) + k2 * x(2, c);
    for (std::size_t c = 0; c < D; ++c) A2p[c] = denom * (x(2, c) - x(1, c));
    for (std::size_t c = 0; c < D; ++c) B1[c] = k1 * A1[c] + k2 * A2[c];
    denom = r.r23, k1 = (t3 - s) * denom, k2 = (s - t2) * denom;
    for (std::size_t c = 0; c < D; ++c) A3[c] = k1 * x(2, c) + k2 * x(3, c);
    for (std::size_t c = 0; c < D; ++c) A3p[c] = denom * (x(3, c) - x(2, c));
    denom = r.r13, k1 = (t3 - s) * denom, k2 = (s - t1) * denom;
    for (std::size_t c = 0; c < D; ++c) B2[c] = k1 * A2[c] + k2 * A3[c];
    denom = r.r02;
    for (std::size_t c = 0; c < D; ++c) B1p[c] = denom * (A2[c] - A1[c] + (t2 - s) * A1p[c] + (s - t0) * A2p[c]);
    denom = r.r13;
    for (std::size_t c = 0; c < D; ++c) B2p[c] = denom * (A3[c] - A2[c] + (t3 - s) * A2p[c] + (s - t1) * A3p[c]);
    denom = r.r12;
    for (std::size_t c = 0; c < D; ++c) Cp[c] = denom * (B2[c] - B1[c] + (t2 - s) * B1p[c] + (s - t1) * B2p[c]);
    return Cp;
}

// The pyramid for the nodes k0 … k0 + count − 1 of a block (see rule_into below): node k0 + i has
// the parameters T[i … i + 3], the reciprocals R1[i … i + 2], R2[i … i + 1] and the points
// x + k − 1 … x + k + 2 (columns `stride` apart); its slope goes to m0[k], m1[k] (and m2[k]). The
// outputs alias nothing else (__restrict), so the compiler computes several nodes at a time.
template <std::size_t D>
[[gnu::always_inline]] inline void catmull_rom_block(const double* __restrict T, const double* __restrict R1, const double* __restrict R2, const double* __restrict x,
                                                     Eigen::Index stride, Eigen::Index k0, Eigen::Index count, double* __restrict m0, double* __restrict m1,
                                                     double* __restrict m2) {
    for (Eigen::Index i = 0; i < count; ++i) {
        const Eigen::Index k = k0 + i;
        const std::array<double, D> d = catmull_rom_slope_at_node<D>(T[i], T[i + 1], T[i + 2], T[i + 3], {R1[i], R1[i + 1], R1[i + 2], R2[i + 1], R2[i]},
                                                                     {x + k - 1, x + k, x + k + 1, x + k + 2}, stride);
        m0[k] = d[0];
        m1[k] = d[1];
        if constexpr (D == 3) m2[k] = d[2];
    }
}

// The same compiled twice on x86-64 Linux, for the baseline and for AVX2 (four doubles per
// instruction instead of two), the one for this CPU chosen when the program loads (GCC's
// target_clones). AVX2 alone, without FMA: the same operations, each rounded as in the baseline,
// so the same bits (the construction's check against Boost compares them on every build).
#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__) && !defined(__clang__)
#define CAGD_PYRAMID_CLONES [[gnu::target_clones("avx2", "default")]]
#else
#define CAGD_PYRAMID_CLONES
#endif
CAGD_PYRAMID_CLONES void catmull_rom_block_planar(const double* T, const double* R1, const double* R2, const double* x, Eigen::Index stride, Eigen::Index k0,
                                                  Eigen::Index count, double* m0, double* m1) {
    catmull_rom_block<2>(T, R1, R2, x, stride, k0, count, m0, m1, nullptr);
}
CAGD_PYRAMID_CLONES void catmull_rom_block_space(const double* T, const double* R1, const double* R2, const double* x, Eigen::Index stride, Eigen::Index k0,
                                                 Eigen::Index count, double* m0, double* m1, double* m2) {
    catmull_rom_block<3>(T, R1, R2, x, stride, k0, count, m0, m1, m2);
}
#undef CAGD_PYRAMID_CLONES

// An allocator that leaves the elements it makes without arguments uninitialised: the points handed
// to Boost are written right after (value-initialising them first zeroed 16 MB at 10^6 points).
template <class T>
struct UninitialisedAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = UninitialisedAllocator<U>;
    };
    UninitialisedAllocator() = default;
    template <class U>
    UninitialisedAllocator(const UninitialisedAllocator<U>&) noexcept {}
    template <class U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};
template <std::size_t D>
using BoostCatmullRom = boost::math::catmull_rom<std::array<double, D>, std::vector<std::array<double, D>, UninitialisedAllocator<std::array<double, D>>>>;

// The slopes of Boost's centripetal Catmull–Rom spline at the nodes, its own (prime at each node's
// parameter: a binary search each, 10^6 of them cost three times Boost's construction) or by the
// rule above in O(n).
template <std::size_t D>
struct CatmullRomSlopes {
    using Point = std::array<double, D>;
    const BoostCatmullRom<D>& cr;
    const PointList& p;
    // Boost's public parameter_at_point(j) is its t_{j+1}: node k's parameter is t_{k+1}; after the
    // nodes come the ghost nodes' t_{n+1}, t_{n+2}.
    double t(Eigen::Index j) const { return cr.parameter_at_point(static_cast<std::size_t>(j - 1)); }
    // Boost's slope at node k (at the last open node the last span's end derivative: Boost
    // evaluates the span on the left at s = max_parameter).
    Point boost(Eigen::Index k) const { return cr.prime(t(k + 1)); }
    // By the rule, nodes a ≤ k < b, 1 ≤ a, into the columns m[c][k]: node k is Boost's node
    // i = k + 1, its points P_{k−1 … k+2} wrapped (node 0 would need Boost's private t_0). Where
    // no point wraps (k + 2 < n), by blocks of kRuleBlock nodes: the block's parameters and their
    // reciprocals first (r_01, r_12, r_23 of node k are R1[k], R1[k+1], R1[k+2]; r_02, r_13 are
    // R2[k], R2[k+1]: the same quotients of the same differences as one node at a time), then the
    // pyramid node by node with nothing carried from one node to the next, which the compiler
    // computes two nodes at a time.
    void rule_into(Eigen::Index a, Eigen::Index b, const std::array<double*, D>& m) const {
        const Eigen::Index n = p.rows();
        const double* x = p.data();
        const Eigen::Index unwrapped_end = std::max(a, std::min(b, n - 2));
        constexpr Eigen::Index kRuleBlock = 256;
        double T[kRuleBlock + 3], R1[kRuleBlock + 2], R2[kRuleBlock + 1];
        for (Eigen::Index k0 = a; k0 < unwrapped_end; k0 += kRuleBlock) {
            const Eigen::Index count = std::min(kRuleBlock, unwrapped_end - k0);
            for (Eigen::Index i = 0; i < count + 3; ++i) T[i] = t(k0 + i);
            for (Eigen::Index i = 0; i < count + 2; ++i) R1[i] = 1 / (T[i + 1] - T[i]);
            for (Eigen::Index i = 0; i < count + 1; ++i) R2[i] = 1 / (T[i + 2] - T[i]);
            if constexpr (D == 2)
                catmull_rom_block_planar(T, R1, R2, x, n, k0, count, m[0], m[1]);
            else
                catmull_rom_block_space(T, R1, R2, x, n, k0, count, m[0], m[1], m[2]);
        }
        for (Eigen::Index k = unwrapped_end; k < b; ++k) {
            const CatmullRomReciprocals r{1 / (t(k + 1) - t(k)), 1 / (t(k + 2) - t(k + 1)), 1 / (t(k + 3) - t(k + 2)), 1 / (t(k + 3) - t(k + 1)), 1 / (t(k + 2) - t(k))};
            const std::array<const double*, 4> P{&p(k - 1, 0), &p(k, 0), &p(k + 1 < n ? k + 1 : k + 1 - n, 0), &p(k + 2 < n ? k + 2 : k + 2 - n, 0)};
            const std::array<double, D> d = catmull_rom_slope_at_node<D>(t(k), t(k + 1), t(k + 2), t(k + 3), r, P, n);
            for (std::size_t c = 0; c < D; ++c) m[c][k] = d[c];
        }
    }
    static bool same(const Point& a, const Point& b) {
        for (std::size_t c = 0; c < D; ++c)
            if (bits_of(a[c]) != bits_of(b[c])) return false;
        return true;
    }
};

// How catmull_rom_interpolant takes the slopes: by the rule, checked against Boost on sampled blocks
// (as pchip and makima), or the rule spoilt by one ulp (for the test that the check notices).
enum class SlopeRule { checked, spoilt };

// Boost's centripetal Catmull–Rom spline through p. Its parameters are a running sum of |ΔP|^½
// over the points and, after them, the chords P_{n−1}P_0 and P_0P_1 (its wrap-around ghost nodes,
// also for open curves). If the points span many orders of magnitude (chords of 1e-69 beside
// 1e100), a short chord's term vanishes in that sum, two parameters coincide, and Boost's span
// search reads past its arrays (found by fuzzing). So each of the n + 1 steps of its parameters
// must exceed 1e-12 of their sum (ε is 1.1e-16), checked here before anything searches them
// (Boost's construction only adds). The spans' parameter lengths h_k = t_{k+2} − t_{k+1} (Boost's
// numbering; step k of those), k < spans, go to `h` in the same pass.
template <std::size_t D>
BoostCatmullRom<D> boost_catmull_rom(const PointList& p, bool closed, std::vector<double>* h = nullptr) {
    // Boost's construction resizes its points to n + 3 (the ghost nodes): with that capacity
    // reserved, it does so in place instead of copying them to a new array.
    std::vector<std::array<double, D>, UninitialisedAllocator<std::array<double, D>>> pts;
    pts.reserve(static_cast<std::size_t>(p.rows()) + 3);
    pts.resize(static_cast<std::size_t>(p.rows()));
    for (Eigen::Index k = 0; k < p.rows(); ++k)
        for (std::size_t c = 0; c < D; ++c) pts[static_cast<std::size_t>(k)][c] = p(k, static_cast<Eigen::Index>(c));
    BoostCatmullRom<D> cr(std::move(pts), closed, 0.5);
    const Eigen::Index n = p.rows(), spans = closed ? n : n - 1;
    const auto t = [&](Eigen::Index j) { return cr.parameter_at_point(static_cast<std::size_t>(j)); };  // Boost's t_{j+1}
    const double sum = t(n + 1);                                                                        // t_1 = 0
    const double shortest = 1e-12 * sum;
    // An OR over all steps (vectorises); the culprit searched only on failure. Steps 0 … spans − 1
    // also go to h.
    std::vector<double> unused;
    std::vector<double>& steps = h ? *h : unused;
    steps.resize(static_cast<std::size_t>(spans));
    unsigned short_steps = 0;
    for (Eigen::Index j = 0; j < spans; ++j) {
        const double step = t(j + 1) - t(j);
        short_steps |= !(step > shortest);
        steps[static_cast<std::size_t>(j)] = step;
    }
    for (Eigen::Index j = spans; j <= n; ++j) short_steps |= !(t(j + 1) - t(j) > shortest);
    if (short_steps != 0)
        for (Eigen::Index j = 0; j <= n; ++j)
            if (!(t(j + 1) - t(j) > shortest)) {
                const Eigen::Index a = j % n, b = (j + 1) % n;  // j = n − 1, n: the ghost chords
                fail_input("cagd::methods::boost_catmull_rom_interpolant", "the chord from point " + std::to_string(a) + " is " + full_precision((p.row(b) - p.row(a)).norm()) +
                                                                               " long against a centripetal parameter sum of " + full_precision(sum) +
                                                                               ": it vanishes in double precision (the points span too many orders of magnitude)");
            }
    return cr;
}

template <std::size_t D>
Interpolant catmull_rom_interpolant(const PointList& p, bool closed, SlopeRule rule = SlopeRule::checked) {
    using Point = std::array<double, D>;
    using spline::PiecewiseHermiteCurve;
    const Eigen::Index n = p.rows(), spans = closed ? n : n - 1;
    std::vector<double> h;  // the spans' parameter lengths: a closed curve's last span ends at t_{n+1} (max_parameter), an open one's at t_n
    std::shared_ptr<const PiecewiseHermiteCurve> curve;
    {  // Boost's spline lives only while its parameters and slopes are read (peak memory)
        const BoostCatmullRom<D> cr = boost_catmull_rom<D>(p, closed, &h);
        const CatmullRomSlopes<D> at{cr, p};
        // The slopes block by block as the curve takes them (each block checked while in cache):
        // node 0 Boost's own, the others by the rule.
        const auto fill = [&](Eigen::Index a, Eigen::Index b, double* const* m) {
            if (a == 0) {
                const Point d = at.boost(0);
                for (std::size_t c = 0; c < D; ++c) m[c][0] = d[c];
                a = 1;
            }
            std::array<double*, D> columns;
            for (std::size_t c = 0; c < D; ++c) columns[c] = m[c];
            at.rule_into(a, b, columns);
            if (rule == SlopeRule::spoilt)
                for (Eigen::Index k = a; k < b; ++k) m[0][k] = std::nextafter(m[0][k], std::numeric_limits<double>::infinity());
        };
        curve = std::make_shared<const PiecewiseHermiteCurve>(PiecewiseHermiteCurve::from_points_and_slope_blocks(p, closed, fill, h));
        // The check, bit for bit: kCheckedBlocks blocks of kSlopeBlock nodes spread over 1 … n − 1,
        // both ends included. Should any derivative differ, every slope is Boost's.
        const Eigen::MatrixXd& m = curve->node_slopes();
        const auto holds = [&](Eigen::Index k, const Point& d) {
            for (std::size_t c = 0; c < D; ++c)
                if (bits_of(m(k, static_cast<Eigen::Index>(c))) != bits_of(d[c])) return false;
            return true;
        };
        const Eigen::Index blocks = std::max<Eigen::Index>(1, (n - 1) / kSlopeBlock), checked = std::min(blocks, kCheckedBlocks);
        bool same = true;
        for (Eigen::Index j = 0; j < checked && same; ++j) {
            const Eigen::Index block = checked == 1 ? 0 : j * (blocks - 1) / (checked - 1);
            const Eigen::Index a = 1 + block * kSlopeBlock, b = block + 1 == blocks ? n : a + kSlopeBlock;
            for (Eigen::Index k = a; k < b && same; ++k) same = holds(k, at.boost(k));
        }
        if (!same) {
            Eigen::MatrixXd boost_slopes(n, p.cols());
            for (Eigen::Index k = 0; k < n; ++k) {
                const Point d = at.boost(k);
                for (std::size_t c = 0; c < D; ++c) boost_slopes(k, static_cast<Eigen::Index>(c)) = d[c];
            }
            curve.reset();
            Eigen::MatrixXd nodes(spans + 1, p.cols());
            nodes.topRows(n) = p;
            if (closed) nodes.row(n) = p.row(0);
            // (closed: n slopes for n spans; from_node_slopes repeats m_0 as m_n)
            curve = std::make_shared<const PiecewiseHermiteCurve>(PiecewiseHermiteCurve::from_node_slopes(std::move(nodes), std::move(boost_slopes), h));
        }
    }
    return unit_span_interpolant(std::move(curve), spans + 1, std::move(h));
}

}  // namespace

Interpolant unit_span_interpolant(std::shared_ptr<const Curve> curve, Eigen::Index nodes, std::vector<double> dtau_du) {
    return {std::move(curve), unit_nodes(nodes), std::move(dtau_du)};
}

Interpolant boost_pchip_interpolant(const PointList& p) {
    return componentwise_chord_interpolant<boost::math::interpolators::pchip<std::vector<double>>>("cagd::methods::boost_pchip_interpolant", p, 1, pchip_rule_slopes);
}

Interpolant boost_makima_interpolant(const PointList& p) {
    return componentwise_chord_interpolant<boost::math::interpolators::makima<std::vector<double>>>("cagd::methods::boost_makima_interpolant", p, 2, makima_rule_slopes);
}

namespace {

template <class Interpolator, class Rule>
bool rule_matches_everywhere(const PointList& p, Eigen::Index reach, Rule rule) {
    const std::vector<double> h = chord_lengths(p, false);
    std::vector<double> tau{0.0};
    for (double hk : h) tau.push_back(tau.back() + hk);
    std::vector<double> m(tau.size());
    for (Eigen::Index c = 0; c < p.cols(); ++c) {
        const NodeSlopeSink out{m.data(), tau.size()};
        rule(tau, p.col(c).data(), out);
        if (!rule_slopes_match_boost<Interpolator>(tau, p.col(c).data(), reach, out, true)) return false;
    }
    return true;
}

}  // namespace

bool detail::boost_rules_match_everywhere(const PointList& p) {
    require_valid_points(p, 4, true, false, "cagd::methods::detail::boost_rules_match_everywhere");
    return rule_matches_everywhere<boost::math::interpolators::pchip<std::vector<double>>>(p, 1, pchip_rule_slopes) &&
           rule_matches_everywhere<boost::math::interpolators::makima<std::vector<double>>>(p, 2, makima_rule_slopes);
}

Interpolant detail::boost_pchip_interpolant_with_a_spoilt_rule(const PointList& p) {
    return componentwise_chord_interpolant<boost::math::interpolators::pchip<std::vector<double>>>(
        "cagd::methods::detail::boost_pchip_interpolant_with_a_spoilt_rule", p, 1, [](const std::vector<double>& x, const double* y, const NodeSlopeSink& out) {
            pchip_rule_slopes(x, y, out);
            for (std::size_t k = 0; k + 1 < out.n; ++k) out.m[k] = std::nextafter(out.m[k], std::numeric_limits<double>::infinity());
        });
}

Interpolant boost_catmull_rom_interpolant(const PointList& p, bool closed) { return p.cols() == 2 ? catmull_rom_interpolant<2>(p, closed) : catmull_rom_interpolant<3>(p, closed); }

namespace {
template <std::size_t D>
bool catmull_rom_rule_matches_everywhere(const PointList& p, bool closed) {
    const auto cr = boost_catmull_rom<D>(p, closed);
    const CatmullRomSlopes<D> at{cr, p};
    Eigen::MatrixXd m(p.rows(), p.cols());
    std::array<double*, D> columns;
    for (std::size_t c = 0; c < D; ++c) columns[c] = m.col(static_cast<Eigen::Index>(c)).data();
    at.rule_into(1, p.rows(), columns);
    for (Eigen::Index k = 1; k < p.rows(); ++k) {
        std::array<double, D> d;
        for (std::size_t c = 0; c < D; ++c) d[c] = m(k, static_cast<Eigen::Index>(c));
        if (!CatmullRomSlopes<D>::same(at.boost(k), d)) return false;
    }
    return true;
}
}  // namespace

bool detail::boost_catmull_rom_rule_matches_everywhere(const PointList& p, bool closed) {
    require_valid_points(p, 4, true, closed, "cagd::methods::detail::boost_catmull_rom_rule_matches_everywhere");
    return p.cols() == 2 ? catmull_rom_rule_matches_everywhere<2>(p, closed) : catmull_rom_rule_matches_everywhere<3>(p, closed);
}

Interpolant detail::boost_catmull_rom_interpolant_with_a_spoilt_rule(const PointList& p, bool closed) {
    return p.cols() == 2 ? catmull_rom_interpolant<2>(p, closed, SlopeRule::spoilt) : catmull_rom_interpolant<3>(p, closed, SlopeRule::spoilt);
}

}  // namespace cagd::methods
