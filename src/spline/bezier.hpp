#pragma once
// Bézier curves r(t) = Σ_{j=0}^{p} B_{j,p}(s) b_j, s = (t − a)/(b − a), t ∈ [a, b].
// Evaluation by de Casteljau on the control polygon and its forward differences
// (hodographs): numerically stable for any degree, O(p²) per derivative order.
// Preconditions: at least one control point, finite a < b.
#include <Eigen/Dense>
#include <vector>

#include "core/curve.hpp"

namespace cagd {

class BezierCurve : public Curve {
public:
    explicit BezierCurve(Eigen::MatrixXd control_points, double a = 0.0, double b = 1.0);
    int degree() const { return static_cast<int>(control_.rows()) - 1; }
    const Eigen::MatrixXd& control_points() const { return control_; }
    int dimension() const override { return static_cast<int>(control_.cols()); }
    double t_min() const override { return a_; }
    double t_max() const override { return b_; }
    Eigen::MatrixXd jet(double t, int order) const override;
    std::vector<double> breakpoints() const override { return {a_, b_}; }

private:
    Eigen::MatrixXd control_;
    double a_, b_;
};

}  // namespace cagd
