#include "cagd/methods/interpolant_forms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
// Boost 1.74's pchip.hpp and makima.hpp call isnan unqualified on a double, which only compiles if
// std::isnan is visible where the templates are defined.
using std::isnan;
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/pchip.hpp>

#include "cagd/core/errors.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace cagd::methods {

namespace {

std::vector<double> unit_nodes(Eigen::Index nodes) {
    std::vector<double> u(static_cast<std::size_t>(nodes));
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = static_cast<double>(i);
    return u;
}

// Boost's slopes at the nodes, read through its public prime(x) (the slopes themselves are
// private). One interpolator over all n points costs a binary search per node (2n searches through
// megabytes: five times the construction at 10^6 points). Boost's slope at node k depends on the
// nodes k − reach … k + reach only (pchip: reach 1, the harmonic mean of the neighbouring secants;
// makima: reach 2, four secants) and, at the ends, on the end nodes; so interpolators over
// overlapping blocks of kSlopeBlock nodes, each extended by `reach` nodes on either side, compute
// every slope with the same arithmetic on the same values: the slopes are Boost's bit for bit, and
// each search runs over a block that stays in cache.
constexpr Eigen::Index kSlopeBlock = 256;

template <class Interpolator>
void boost_slopes_by_blocks(const std::vector<double>& tau, const Eigen::VectorXd& y, Eigen::Index reach, Eigen::Ref<Eigen::VectorXd> slopes) {
    const Eigen::Index n = static_cast<Eigen::Index>(tau.size());
    for (Eigen::Index a = 0; a < n;) {
        Eigen::Index b = std::min(n, a + kSlopeBlock);
        if (n - b < kSlopeBlock / 4) b = n;  // no short last block (Boost needs four points)
        const Eigen::Index lo = std::max<Eigen::Index>(0, a - reach), hi = std::min(n, b + reach);
        std::vector<double> x(tau.begin() + lo, tau.begin() + hi), v(y.data() + lo, y.data() + hi);
        const Interpolator f(std::move(x), std::move(v));
        for (Eigen::Index k = a; k < b; ++k) slopes(k) = f.prime(tau[static_cast<std::size_t>(k)]);
        a = b;
    }
}

template <class Interpolator>
Interpolant componentwise_chord_interpolant(const PointList& p, Eigen::Index reach) {
    const std::vector<double> h = chord_lengths(p, false);
    Eigen::MatrixXd slopes(p.rows(), p.cols());
    {  // the chord-length parameters live only while the slopes are read (peak memory)
        std::vector<double> tau{0.0};
        tau.reserve(h.size() + 1);
        for (double hk : h) tau.push_back(tau.back() + hk);
        for (Eigen::Index c = 0; c < p.cols(); ++c) boost_slopes_by_blocks<Interpolator>(tau, p.col(c), reach, slopes.col(c));
    }
    return hermite_from_slopes(p, slopes, h, false);
}

template <std::size_t D>
Interpolant catmull_rom_interpolant(const PointList& p, bool closed) {
    using Point = std::array<double, D>;
    std::vector<Point> pts(static_cast<std::size_t>(p.rows()));
    for (Eigen::Index k = 0; k < p.rows(); ++k)
        for (std::size_t c = 0; c < D; ++c) pts[static_cast<std::size_t>(k)][c] = p(k, static_cast<Eigen::Index>(c));
    // Boost's centripetal parameters are a running sum of |ΔP|^½ over the points and, after them,
    // the chords P_{n−1}P_0 and P_0P_1 (its wrap-around ghost nodes, also for open curves). If the
    // points span many orders of magnitude (chords of 1e-69 beside 1e100), a short chord's term
    // vanishes in that sum, two parameters coincide, and Boost's span search reads past its
    // arrays (found by fuzzing). Each term must therefore exceed 1e-12 of the sum (ε is 1.1e-16).
    {
        std::vector<double> terms;
        terms.reserve(static_cast<std::size_t>(p.rows()) + 1);
        double sum = 0.0;
        for (Eigen::Index k = 0; k <= p.rows(); ++k) {
            const Eigen::Index a = k % p.rows(), b = (k + 1) % p.rows();  // k = n−1, n: the ghost chords
            terms.push_back(std::sqrt((p.row(b) - p.row(a)).norm()));
            sum += terms.back();
        }
        for (std::size_t k = 0; k < terms.size(); ++k)
            if (!(terms[k] > 1e-12 * sum))
                fail_input("cagd::methods::boost_catmull_rom_interpolant", "the chord from point " + std::to_string(k % pts.size()) + " is " + full_precision(terms[k] * terms[k]) +
                                                                               " long against a centripetal parameter sum of " + full_precision(sum) +
                                                                               ": it vanishes in double precision (the points span too many orders of magnitude)");
    }
    const Eigen::Index n = p.rows(), spans = closed ? n : n - 1;
    std::vector<double> h;
    h.reserve(static_cast<std::size_t>(spans));
    Eigen::MatrixXd slopes(n, p.cols());
    {  // Boost's spline lives only while its parameters and slopes are read (peak memory)
        const boost::math::catmull_rom<Point> cr(std::move(pts), closed, 0.5);
        for (Eigen::Index k = 0; k < spans; ++k)
            h.push_back((k + 1 == n ? cr.max_parameter() : cr.parameter_at_point(static_cast<std::size_t>(k + 1))) - cr.parameter_at_point(static_cast<std::size_t>(k)));
        for (Eigen::Index k = 0; k < n; ++k) {
            // prime at the last open node is the last span's end derivative (Boost evaluates the
            // span on the left at s = max_parameter); every other node is a span start.
            const Point d = cr.prime(cr.parameter_at_point(static_cast<std::size_t>(k)));
            for (std::size_t c = 0; c < D; ++c) slopes(k, static_cast<Eigen::Index>(c)) = d[c];
        }
    }
    return hermite_from_slopes(p, slopes, h, closed);
}

}  // namespace

std::vector<double> chord_lengths(const PointList& p, bool closed) {
    const Eigen::Index n = p.rows(), spans = closed ? n : n - 1;
    std::vector<double> h(static_cast<std::size_t>(std::max<Eigen::Index>(spans, 0)));
    for (Eigen::Index k = 0; k < spans; ++k) h[static_cast<std::size_t>(k)] = (p.row(k + 1 == n ? 0 : k + 1) - p.row(k)).norm();
    return h;
}

Interpolant unit_span_interpolant(std::shared_ptr<const Curve> curve, Eigen::Index nodes, std::vector<double> dtau_du) {
    return {std::move(curve), unit_nodes(nodes), std::move(dtau_du)};
}

Interpolant hermite_from_slopes(const PointList& p, const Eigen::MatrixXd& slopes, const std::vector<double>& h, bool closed) {
    const Eigen::Index n = p.rows(), spans = static_cast<Eigen::Index>(h.size());
    Eigen::MatrixXd nodes(spans + 1, p.cols()), d0(spans, p.cols()), d1(spans, p.cols());
    nodes.topRows(n) = p;
    if (closed) nodes.row(n) = p.row(0);
    // Column by column (contiguous, vectorised): d0_k = h_k s_k, d1_k = h_k s_{k+1}.
    const Eigen::Map<const Eigen::VectorXd> hk(h.data(), spans);
    const Eigen::Index inner = closed ? spans - 1 : spans;  // spans whose end slope is s_{k+1} without wrapping
    for (Eigen::Index c = 0; c < p.cols(); ++c) {
        d0.col(c) = hk.cwiseProduct(slopes.col(c).head(spans));
        d1.col(c).head(inner) = hk.head(inner).cwiseProduct(slopes.col(c).segment(1, inner));
        if (closed) d1(spans - 1, c) = hk(spans - 1) * slopes(0, c);
    }
    return unit_span_interpolant(std::make_shared<spline::PiecewiseHermiteCurve>(std::move(nodes), std::move(d0), std::move(d1)), spans + 1, h);
}

Interpolant boost_pchip_interpolant(const PointList& p) { return componentwise_chord_interpolant<boost::math::interpolators::pchip<std::vector<double>>>(p, 1); }

Interpolant boost_makima_interpolant(const PointList& p) { return componentwise_chord_interpolant<boost::math::interpolators::makima<std::vector<double>>>(p, 2); }

Interpolant boost_catmull_rom_interpolant(const PointList& p, bool closed) { return p.cols() == 2 ? catmull_rom_interpolant<2>(p, closed) : catmull_rom_interpolant<3>(p, closed); }

}  // namespace cagd::methods
