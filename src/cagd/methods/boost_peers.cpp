#include "cagd/methods/boost_peers.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>
// Boost 1.74's pchip.hpp and makima.hpp call isnan unqualified on a double, which only compiles if
// std::isnan is visible where the templates are defined.
using std::isnan;
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/pchip.hpp>

#include "cagd/core/errors.hpp"
#include "cagd/methods/detail/registration.hpp"
#include "cagd/spline/hermite_spline.hpp"

namespace cagd::methods {

namespace {

// One Boost interpolator per coordinate over the chord-length parameter; its slopes at the nodes.
template <class Interpolator>
Interpolant componentwise_chord_interpolant(const char* function, const PointList& p) {
    if (p.rows() < 4)
        fail_input(function, "needs at least 4 points (Boost's pchip and makima), got " + std::to_string(p.rows()));
    std::vector<double> h = chord_lengths(p, false);
    std::vector<double> tau{0.0};
    for (double hk : h) tau.push_back(tau.back() + hk);
    Eigen::MatrixXd slopes(p.rows(), p.cols());
    for (Eigen::Index c = 0; c < p.cols(); ++c) {
        const Interpolator f(std::vector<double>(tau),
                             std::vector<double>(p.col(c).data(), p.col(c).data() + p.rows()));
        for (Eigen::Index k = 0; k < p.rows(); ++k) slopes(k, c) = f.prime(tau[static_cast<std::size_t>(k)]);
    }
    auto curve = std::make_shared<const spline::PiecewiseHermiteCurve>(
        spline::PiecewiseHermiteCurve::from_node_slopes(p, std::move(slopes), h));
    return detail::unit_span_interpolant(std::move(curve), p.rows(), std::move(h));
}

template <std::size_t D>
Interpolant catmull_rom_interpolant(const PointList& p, bool closed) {
    // Boost refuses a first chord whose centripetal length |d|^(1/2) is below machine epsilon, an
    // absolute bound ("the first and last point should not be the same" for points 1e-40 apart). It
    // gets the points scaled by 4^−k, k = e/2 rounded toward 0 for their box diagonal in [2^(e−1), 2^e);
    // the curve is the same, its parameter and slopes scaled back by √(4^k) = 2^k (exact).
    int k = 0;
    std::frexp((p.colwise().maxCoeff() - p.colwise().minCoeff()).norm(), &k);
    k /= 2;
    std::vector<std::array<double, D>> points(static_cast<std::size_t>(p.rows()));
    for (Eigen::Index r = 0; r < p.rows(); ++r)
        for (std::size_t c = 0; c < D; ++c)
            points[static_cast<std::size_t>(r)][c] = std::ldexp(p(r, static_cast<Eigen::Index>(c)), -2 * k);
    const boost::math::catmull_rom<std::array<double, D>> cr(std::move(points), closed, 0.5);
    // Boost's parameter_at_point(j) is its t_{j+1}: node k at t_{k+1} = 0 for k = 0; after the
    // nodes its ghost nodes' t_{n+1} (a closed curve's end), t_{n+2}.
    const Eigen::Index n = p.rows(), spans = closed ? n : n - 1;
    const auto t = [&](Eigen::Index j) { return cr.parameter_at_point(static_cast<std::size_t>(j)); };
    const double sum = t(n + 1), shortest = 1e-12 * sum;
    for (Eigen::Index j = 0; j <= n; ++j)
        if (!(t(j + 1) - t(j) > shortest)) {
            const Eigen::Index a = j % n, b = (j + 1) % n;  // j = n − 1, n: the ghost chords
            fail_input("cagd::methods(boost-catmull-rom)",
                       "the chord from point " + std::to_string(a) + " is " +
                           full_precision((p.row(b) - p.row(a)).norm()) +
                           " long against a centripetal parameter sum of " + full_precision(std::ldexp(sum, k)) +
                           ": it vanishes in double precision (the points span too many orders of magnitude)");
        }
    std::vector<double> h(static_cast<std::size_t>(spans));
    for (Eigen::Index j = 0; j < spans; ++j) h[static_cast<std::size_t>(j)] = std::ldexp(t(j + 1) - t(j), k);
    Eigen::MatrixXd slopes(n, p.cols());
    for (Eigen::Index j = 0; j < n; ++j) {
        const std::array<double, D> d = cr.prime(t(j));
        for (std::size_t c = 0; c < D; ++c) slopes(j, static_cast<Eigen::Index>(c)) = std::ldexp(d[c], k);
    }
    Eigen::MatrixXd nodes(spans + 1, p.cols());
    nodes.topRows(n) = p;
    if (closed) nodes.row(n) = p.row(0);  // from_node_slopes repeats m_0 as m_n
    auto curve = std::make_shared<const spline::PiecewiseHermiteCurve>(
        spline::PiecewiseHermiteCurve::from_node_slopes(std::move(nodes), std::move(slopes), h));
    return detail::unit_span_interpolant(std::move(curve), spans + 1, std::move(h));
}

}  // namespace

Interpolant boost_pchip_interpolant(const PointList& p) {
    return componentwise_chord_interpolant<boost::math::interpolators::pchip<std::vector<double>>>(
        "cagd::methods::boost_pchip_interpolant", p);
}

Interpolant boost_makima_interpolant(const PointList& p) {
    return componentwise_chord_interpolant<boost::math::interpolators::makima<std::vector<double>>>(
        "cagd::methods::boost_makima_interpolant", p);
}

Interpolant boost_catmull_rom_interpolant(const PointList& p, bool closed) {
    return p.cols() == 2 ? catmull_rom_interpolant<2>(p, closed) : catmull_rom_interpolant<3>(p, closed);
}

}  // namespace cagd::methods
