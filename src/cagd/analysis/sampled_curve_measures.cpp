#include "cagd/analysis/sampled_curve_measures.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "cagd/analysis/frenet_jet.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::analysis {

namespace {

// Signed (planar) or unsigned (3-D) curvature from first and second derivatives.
double sample_curvature(const Eigen::RowVectorXd& d1, const Eigen::RowVectorXd& d2, int index) {
    Eigen::MatrixXd D(2, d1.size());
    D << d1, d2;
    const FrenetJet f = frenet_jet(D);
    if (!f.regular)
        fail_input("cagd::analysis::sampled_curve_measures", "zero speed at sample " + std::to_string(index));
    return f.curvature;
}

}  // namespace

SampledCurveMeasures sampled_curve_measures(const CurveSamples& s) {
    const char* who = "cagd::analysis::sampled_curve_measures";
    const Eigen::MatrixXd& p = s.position;
    const Eigen::Index n = p.rows(), d = p.cols();
    if (n < 2) fail_input(who, "needs at least 2 samples, got " + std::to_string(n));
    if (d != 2 && d != 3) fail_input(who, "needs 2 or 3 coordinates, got " + std::to_string(d));
    if (!p.allFinite()) fail_input(who, "a position is not finite");
    if (s.first.has_value() != s.second.has_value())
        fail_input(who, "needs both first and second derivatives, or neither");
    if (s.first && (s.first->rows() != n || s.first->cols() != d || s.second->rows() != n || s.second->cols() != d))
        fail_input(who,
                   "derivative columns do not match the position's " + std::to_string(n) + " x " + std::to_string(d));
    if (s.first && (!s.first->allFinite() || !s.second->allFinite())) fail_input(who, "a derivative is not finite");
    if (!s.parameter.empty() && static_cast<Eigen::Index>(s.parameter.size()) != n)
        fail_input(who, "one parameter value per sample is needed");

    SampledCurveMeasures m;
    m.samples = static_cast<int>(n);
    m.has_curvature = s.first.has_value();
    std::vector<double> kappa(static_cast<std::size_t>(n), 0.0);
    double area = 0.0;
    m.curvature_min = std::numeric_limits<double>::infinity();
    m.curvature_max = -std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < n; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        if (m.has_curvature) {
            kappa[k] = sample_curvature(s.first->row(i), s.second->row(i), static_cast<int>(i));
            const double u = s.parameter.empty() ? static_cast<double>(i) : s.parameter[k];
            if (kappa[k] < m.curvature_min) m.curvature_min = kappa[k], m.curvature_min_at = u;
            if (kappa[k] > m.curvature_max) m.curvature_max = kappa[k], m.curvature_max_at = u;
        }
        if (i == 0) continue;
        const double ds = (p.row(i) - p.row(i - 1)).norm();
        m.polyline_length += ds;
        area += 0.5 * (p(i - 1, 0) * p(i, 1) - p(i, 0) * p(i - 1, 1));
        m.bending_energy += 0.5 * (kappa[k] * kappa[k] + kappa[k - 1] * kappa[k - 1]) * ds;
    }
    m.closed = (p.row(0) - p.row(n - 1)).norm() <= kClosedRelativeGap * (1 + m.polyline_length);
    if (m.closed && d == 2) m.enclosed_area = area;
    return m;
}

}  // namespace cagd::analysis
