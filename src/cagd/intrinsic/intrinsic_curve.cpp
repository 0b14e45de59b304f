#include "cagd/intrinsic/intrinsic_curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"

namespace cagd::intrinsic {

IntrinsicCurve::IntrinsicCurve(Eigen::Vector2d start, TangentAngleSpline psi) : psi_(std::move(psi)) {
    if (!start.allFinite())
        fail_input("intrinsic::IntrinsicCurve",
                   "start point (" + full_precision(start(0)) + ", " + full_precision(start(1)) + ") is not finite");
    const int k = psi_.segments();
    points_.resize(k + 1, 2);
    points_.row(0) = start.transpose();
    for (int j = 0; j < k; ++j)
        points_.row(j + 1) = points_.row(j) + psi_.segment_lengths()[static_cast<std::size_t>(j)] *
                                                  direction_integrals(psi_.bezier().row(j).transpose()).transpose();
}

double IntrinsicCurve::segment_offset_bound(const IntrinsicCurve& other, int j) const {
    const char* who = "intrinsic::IntrinsicCurve::segment_offset_bound";
    if (j < 0 || j >= psi_.segments() || j >= other.psi_.segments())
        fail_input(who, "segment " + std::to_string(j) + " is not one of both curves (" +
                            std::to_string(psi_.segments()) + " and " + std::to_string(other.psi_.segments()) +
                            " segments)");
    if (psi_.degree() != other.psi_.degree())
        fail_input(who, "tangent angles of degree " + std::to_string(psi_.degree()) + " and " +
                            std::to_string(other.psi_.degree()) + " have no common Bézier ordinates");
    const double d = psi_.segment_lengths()[static_cast<std::size_t>(j)],
                 e = other.psi_.segment_lengths()[static_cast<std::size_t>(j)];
    const double angle = (psi_.bezier().row(j) - other.psi_.bezier().row(j)).cwiseAbs().maxCoeff();
    const double bound = (points_.row(j) - other.points_.row(j)).norm() + std::abs(d - e) + std::min(d, e) * angle;
    // The rounding's scale: the positions, the lengths, and ψ's ordinates times the length (ψ itself
    // rounds relative to its own size, which an unwrapped tangent angle can make large).
    const double turning =
        std::max(psi_.bezier().row(j).cwiseAbs().maxCoeff(), other.psi_.bezier().row(j).cwiseAbs().maxCoeff());
    const double magnitude =
        points_.row(j).cwiseAbs().maxCoeff() + other.points_.row(j).cwiseAbs().maxCoeff() + (d + e) * (1.0 + turning);
    return (bound + 1e-13 * magnitude) * (1.0 + 1e-12);
}

std::optional<double> IntrinsicCurve::span_offset_bound(const Curve& other, double t0, double t1, double u0,
                                                        double u1) const {
    const auto* o = dynamic_cast<const IntrinsicCurve*>(&other);
    if (o == nullptr || o->psi_.degree() != psi_.degree()) return std::nullopt;
    const std::vector<double>&w = psi_.breakpoints(), &v = o->psi_.breakpoints();
    const auto j = std::lower_bound(w.begin(), w.end(), t0) - w.begin();
    if (j + 1 >= static_cast<std::ptrdiff_t>(w.size()) || j + 1 >= static_cast<std::ptrdiff_t>(v.size()) ||
        !(w[static_cast<std::size_t>(j)] == t0 && w[static_cast<std::size_t>(j) + 1] == t1 &&
          v[static_cast<std::size_t>(j)] == u0 && v[static_cast<std::size_t>(j) + 1] == u1))
        return std::nullopt;
    const double parameter_rounding =
        16.0 * std::numeric_limits<double>::epsilon() * (std::abs(t0) + std::abs(t1) + std::abs(u0) + std::abs(u1));
    return segment_offset_bound(*o, static_cast<int>(j)) + parameter_rounding;
}

namespace {
// r(s) in segment j at local τ = (s − w_j)/d_j: r_j + d_j ∫_0^τ (cos ψ, sin ψ) dt. At τ = 0 the
// integral is +0 and at τ = 1 it is the one the constructor summed into r_{j+1}, so both ends are
// taken from the stored points, bit for bit as the quadrature gives them (+ 0.0: r_j + d_j·(+0)
// turns a −0 coordinate into +0), without its 16 sines and cosines per piece — a sampled curve
// asks for every join twice.
Eigen::RowVector2d position_in_segment(const Eigen::MatrixXd& points, const TangentAngleSpline& psi, int j, double d,
                                       double tau) {
    if (tau == 0.0) return points.row(j).array() + 0.0;
    if (tau == 1.0) return points.row(j + 1);
    return points.row(j) + d * direction_integrals(psi.bezier().row(j).transpose(), tau).transpose();
}

// Rows first.. of a jet: d^k r/ds^k, k = 1..order, from the ψ jet a = (ψ, ψ', …) of segment j.
template <class Jet, class Out>
void write_derivative_rows(const Jet& a, int order, Out& out, int first) {
    const Eigen::RowVector2d e(std::cos(a(0)), std::sin(a(0))), n(-std::sin(a(0)), std::cos(a(0)));
    out.row(first) = e;
    if (order >= 2) out.row(first + 1) = a(1) * n;
    if (order >= 3) out.row(first + 2) = a(2) * n - a(1) * a(1) * e;
    if (order >= 4) out.row(first + 3) = (a(3) - a(1) * a(1) * a(1)) * n - 3.0 * a(1) * a(2) * e;
}
}  // namespace

void IntrinsicCurve::evaluate_jet(double s, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const {
    const int order = first + static_cast<int>(out.rows()) - 1;
    if (order > 4) fail_input("intrinsic::IntrinsicCurve::jet", "order must be in 0..4, got " + std::to_string(order));
    int j = 0;
    if (side == JetSide::left) {
        const std::vector<double>& w = psi_.breakpoints();
        j = static_cast<int>(std::lower_bound(w.begin(), w.end(), s) - w.begin()) - 1;  // w_j < s ≤ w_{j+1}
    } else {
        j = psi_.segment_at(s);
    }
    if (first == 0) {
        const double w = psi_.breakpoints()[static_cast<std::size_t>(j)],
                     d = psi_.segment_lengths()[static_cast<std::size_t>(j)];
        out.row(0) = position_in_segment(points_, psi_, j, d, std::min(1.0, std::max(0.0, (s - w) / d)));
        if (order == 0) return;
    }
    double a[4];
    psi_.jet_in_segment_into(j, s, order - 1, a);
    write_derivative_rows(Eigen::Map<const Eigen::VectorXd>(a, order), order, out, 1 - first);
}

std::vector<ProfileSample> curvature_profile_samples(const IntrinsicCurve& curve, int per_segment) {
    if (per_segment < 1)
        fail_input("intrinsic::curvature_profile_samples",
                   "per_segment must be ≥ 1, got " + std::to_string(per_segment));
    const TangentAngleSpline& psi = curve.tangent_angle();
    std::vector<ProfileSample> out;
    for (int j = 0; j < psi.segments(); ++j) {
        const double a = psi.breakpoints()[static_cast<std::size_t>(j)],
                     d = psi.segment_lengths()[static_cast<std::size_t>(j)];
        for (int m = 0; m <= per_segment; ++m) {
            const double s = std::min(a + d * m / per_segment, curve.length());
            const Eigen::MatrixXd r = curve.jet(s, 0);
            const Eigen::VectorXd k = psi.jet_in_segment(j, std::max(a, s), 1);
            out.push_back({s, r(0, 0), r(0, 1), k(0), k(1), j});
        }
    }
    return out;
}

}  // namespace cagd::intrinsic
