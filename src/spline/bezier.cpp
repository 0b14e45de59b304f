#include "spline/bezier.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace cagd {

BezierCurve::BezierCurve(Eigen::MatrixXd control_points, double a, double b)
    : control_(std::move(control_points)), a_(a), b_(b) {
    const std::string who = "cagd::BezierCurve";
    if (control_.rows() < 1) fail_input(who, "needs at least one control point");
    if (!std::isfinite(a) || !std::isfinite(b) || !(a < b))
        fail_input(who, "parameter interval [" + full_precision(a) + ", " + full_precision(b) +
                            "] must be finite with a < b");
}

Eigen::MatrixXd BezierCurve::jet(double t, int order) const {
    if (!(t >= a_ && t <= b_))
        fail_input("cagd::BezierCurve::jet", "t = " + full_precision(t) + " outside [" +
                                                 full_precision(a_) + ", " + full_precision(b_) + "]");
    if (order < 0) fail_input("cagd::BezierCurve::jet", "order must be >= 0");
    const double s = (t - a_) / (b_ - a_);
    const double scale = 1.0 / (b_ - a_);
    Eigen::MatrixXd result = Eigen::MatrixXd::Zero(order + 1, control_.cols());
    Eigen::MatrixXd diff = control_;   // k-th forward differences, scaled
    double factor = 1.0;
    for (int k = 0; k <= order && k <= degree(); ++k) {
        if (k > 0) {
            const Eigen::Index m = diff.rows() - 1;
            diff = (diff.bottomRows(m) - diff.topRows(m)).eval();
            factor *= static_cast<double>(degree() - k + 1) * scale;
        }
        Eigen::MatrixXd work = diff;   // de Casteljau
        for (Eigen::Index r = work.rows() - 1; r > 0; --r)
            for (Eigen::Index i = 0; i < r; ++i)
                work.row(i) = (1.0 - s) * work.row(i) + s * work.row(i + 1);
        result.row(k) = factor * work.row(0);
    }
    return result;
}

}  // namespace cagd
