#include "cagd/spline/bezier.hpp"

#include <boost/math/special_functions/binomial.hpp>
#include <boost/math/special_functions/factorials.hpp>
#include <cmath>
#include <string>

#include "cagd/core/bernstein_polynomial.hpp"
#include "cagd/core/errors.hpp"

namespace cagd {

BezierCurve::BezierCurve(Eigen::MatrixXd control_points, double a, double b, BezierEvaluation method)
    : control_(std::move(control_points)), a_(a), b_(b), method_(method) {
    const std::string who = "cagd::BezierCurve";
    if (control_.rows() < 1) fail_input(who, "needs at least one control point");
    if (!std::isfinite(a) || !std::isfinite(b) || !(a < b))
        fail_input(
            who, "parameter interval [" + full_precision(a) + ", " + full_precision(b) + "] must be finite with a < b");
    if (method_ == BezierEvaluation::power_basis) monomial_ = monomial_from_bernstein(control_);
}

Eigen::MatrixXd monomial_from_bernstein(const Eigen::MatrixXd& control) {
    const int p = static_cast<int>(control.rows()) - 1;
    Eigen::MatrixXd monomial = Eigen::MatrixXd::Zero(p + 1, control.cols());
    for (int k = 0; k <= p; ++k) {
        double binom_pk = 1.0;  // C(p, k)
        for (int i = 1; i <= k; ++i) binom_pk = binom_pk * (p - k + i) / i;
        double binom_kj = 1.0;  // C(k, j), updated in j
        for (int j = 0; j <= k; ++j) {
            if (j > 0) binom_kj = binom_kj * (k - j + 1) / j;
            const double sign = ((k - j) % 2 == 0) ? 1.0 : -1.0;
            monomial.row(k) += sign * binom_pk * binom_kj * control.row(j);
        }
    }
    return monomial;
}

Eigen::MatrixXd bernstein_from_monomial(const Eigen::MatrixXd& monomial) {
    const int p = static_cast<int>(monomial.rows()) - 1;
    Eigen::MatrixXd control = Eigen::MatrixXd::Zero(p + 1, monomial.cols());
    for (int j = 0; j <= p; ++j) {
        double binom_jk = 1.0, binom_pk = 1.0;  // C(j, k), C(p, k), updated in k
        for (int k = 0; k <= j; ++k) {
            if (k > 0) {
                binom_jk = binom_jk * (j - k + 1) / k;
                binom_pk = binom_pk * (p - k + 1) / k;
            }
            control.row(j) += (binom_jk / binom_pk) * monomial.row(k);
        }
    }
    return control;
}

Eigen::MatrixXd BezierCurve::whole_jet(double t, int order) const {
    if (!(t >= a_ && t <= b_))
        fail_input("cagd::BezierCurve::jet",
                   "t = " + full_precision(t) + " outside [" + full_precision(a_) + ", " + full_precision(b_) + "]");
    if (order < 0) fail_input("cagd::BezierCurve::jet", "order must be >= 0");
    const double s = std::min(1.0, std::max(0.0, (t - a_) / (b_ - a_)));
    const double scale = 1.0 / (b_ - a_);
    Eigen::MatrixXd result = Eigen::MatrixXd::Zero(order + 1, control_.cols());
    if (method_ == BezierEvaluation::power_basis) {
        const int p = degree();
        for (int k = 0; k <= order && k <= p; ++k) {
            // d^k/ds^k Σ a_m s^m = Σ_{m ≥ k} m!/(m−k)! a_m s^{m−k}, by Horner.
            Eigen::RowVectorXd acc = Eigen::RowVectorXd::Zero(control_.cols());
            for (int m = p; m >= k; --m) {
                double falling = 1.0;
                for (int i = 0; i < k; ++i) falling *= (m - i);
                acc = acc * s + falling * monomial_.row(m);
            }
            result.row(k) = acc * std::pow(scale, k);
        }
        return result;
    }
    Eigen::MatrixXd diff = control_;  // k-th forward differences, scaled
    double factor = 1.0;
    for (int k = 0; k <= order && k <= degree(); ++k) {
        if (k > 0) {
            const Eigen::Index m = diff.rows() - 1;
            diff = (diff.bottomRows(m) - diff.topRows(m)).eval();
            factor *= static_cast<double>(degree() - k + 1) * scale;
        }
        if (method_ == BezierEvaluation::bernstein) {
            const std::vector<double> basis = bernstein_basis_values(static_cast<int>(diff.rows()) - 1, s);
            Eigen::RowVectorXd acc = Eigen::RowVectorXd::Zero(control_.cols());
            for (Eigen::Index j = 0; j < diff.rows(); ++j) acc += basis[static_cast<std::size_t>(j)] * diff.row(j);
            result.row(k) = factor * acc;
            continue;
        }
        Eigen::MatrixXd work = diff;  // de Casteljau
        for (Eigen::Index r = work.rows() - 1; r > 0; --r)
            for (Eigen::Index i = 0; i < r; ++i) work.row(i) = (1.0 - s) * work.row(i) + s * work.row(i + 1);
        result.row(k) = factor * work.row(0);
    }
    return result;
}

Eigen::MatrixXd bezier_from_end_jets(int p, double h, const Eigen::MatrixXd& J0, const Eigen::MatrixXd& J1) {
    const int from_start = p / 2, from_end = p - p / 2 - 1;
    if (p < 0 || !(h > 0.0) || J0.rows() <= from_start || J1.rows() <= std::max(from_end, 0) || J0.cols() != J1.cols())
        fail_input("cagd::bezier_from_end_jets", "needs degree >= 0, h > 0 and jets of orders " +
                                                     std::to_string(from_start) + " and " + std::to_string(from_end) +
                                                     " at the ends; got degree " + std::to_string(p) +
                                                     ", h = " + full_precision(h));
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(p + 1, J0.cols());
    for (int k = 0; k <= p; ++k) {
        const bool start = k <= from_start;
        const int kk = start ? k : p - k;
        const double step = start ? h : -h;
        double hj = 1.0;
        for (int j = 0; j <= kk; ++j) {
            const double c =
                boost::math::binomial_coefficient<double>(static_cast<unsigned>(kk), static_cast<unsigned>(j)) /
                boost::math::falling_factorial(static_cast<double>(p), static_cast<unsigned>(j));
            b.row(k) += c * hj * (start ? J0.row(j) : J1.row(j));
            hj *= step;
        }
    }
    return b;
}

}  // namespace cagd
