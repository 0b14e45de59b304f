#include "cagd/analysis/arc_length_parameter.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <string>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::analysis {

namespace {
// Gauss–Kronrod depth and tolerance of the pieces' lengths (as accurate_arc_length).
constexpr int kInverseKronrodDepth = 15;
constexpr double kInversePieceRelTol = 1e-13;
// Newton's stopping precision: 50 bits of t, and at most 100 steps (it converges quadratically
// where the speed is smooth; bisection bounds the rest).
constexpr int kInverseNewtonBits = 50;
constexpr std::uintmax_t kInverseNewtonSteps = 100;
// Subintervals of the Gauss–Legendre rule for ∫_{t_k}^{t} |r'| inside a piece.
constexpr int kInversePartialPieces = 4;
// How far two computations of the length may differ (each to about 1e-13..1e-12 relative).
constexpr double kLengthAgreement = 1e-11;

double inverse_speed_at(const Curve& c, double t) { return c.derivatives(t, 1).row(0).norm(); }
}  // namespace

ArcLengthParameter::ArcLengthParameter(std::shared_ptr<const Curve> curve) : curve_(std::move(curve)) {
    if (!curve_) fail_input("cagd::analysis::ArcLengthParameter", "no curve");
    breaks_ = curve_->breakpoints();
    cumulative_.assign(breaks_.size(), 0.0);
    for (std::size_t k = 0; k + 1 < breaks_.size(); ++k)
        cumulative_[k + 1] = cumulative_[k] + boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
                                                  [&](double t) { return inverse_speed_at(*curve_, t); }, breaks_[k],
                                                  breaks_[k + 1], kInverseKronrodDepth, kInversePieceRelTol);
}

double ArcLengthParameter::parameter_at(double s) const {
    const double total = length();
    // Lengths computed elsewhere (accurate_arc_length) agree with this one to about 1e-12: an s that
    // far beyond L is L.
    if (!(s >= 0.0 && s <= total * (1.0 + kLengthAgreement)))
        fail_input("cagd::analysis::ArcLengthParameter::parameter_at",
                   "s = " + full_precision(s) + "; allowed [0, " + full_precision(total) + "] (the curve's length)");
    if (s >= total) return breaks_.back();
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
    const std::size_t k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - cumulative_.begin() - 1, 0));
    const double a = breaks_[k], b = breaks_[k + 1], target = s - cumulative_[k];
    if (!(cumulative_[k + 1] > cumulative_[k])) return a;  // a piece of length 0
    const double guess = a + (b - a) * target / (cumulative_[k + 1] - cumulative_[k]);
    std::uintmax_t steps = kInverseNewtonSteps;
    return boost::math::tools::newton_raphson_iterate(
        [&](double t) {
            return std::make_pair(arc_length(*curve_, a, t, kInversePartialPieces) - target,
                                  inverse_speed_at(*curve_, t));
        },
        guess, a, b, kInverseNewtonBits, steps);
}

}  // namespace cagd::analysis
