#include "cagd/analysis/frenet_jet.hpp"

#include <cmath>
#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::analysis {

FrenetJet frenet_jet(const Eigen::Ref<const Eigen::MatrixXd>& D) {
    const char* who = "cagd::analysis::frenet_jet";
    if (D.rows() < 2) fail_input(who, "needs r' and r'' (2 rows of derivatives), got " + std::to_string(D.rows()));
    if (D.cols() != 2 && D.cols() != 3)
        fail_input(who, "needs a curve of dimension 2 or 3, got " + std::to_string(D.cols()));
    FrenetJet f;
    const double v2 = D.row(0).squaredNorm(), v = std::sqrt(v2);
    f.speed = v;
    f.regular = v2 > 0.0;
    if (!f.regular) return f;
    const double along = D.row(0).dot(D.row(1));  // r′·r″
    if (D.cols() == 2) {
        const double x1 = D(0, 0), y1 = D(0, 1);
        const double cross = x1 * D(1, 1) - y1 * D(1, 0);
        f.curvature = cross / (v2 * v);
        if (D.rows() >= 3)
            f.curvature_rate = ((x1 * D(2, 1) - y1 * D(2, 0)) * v2 - 3.0 * cross * along) / (v2 * v2 * v2);
        return f;
    }
    const Eigen::Vector3d d1 = D.row(0).transpose(), d2 = D.row(1).transpose();
    const Eigen::Vector3d w = d1.cross(d2);
    const double wn = w.norm();
    f.curvature = wn / (v2 * v);
    if (D.rows() < 3) return f;
    const Eigen::Vector3d d3 = D.row(2).transpose(), w1 = d1.cross(d3);  // w′ = r′ × r‴
    f.curvature_rate = wn > 0.0 ? (w.dot(w1) / wn - 3.0 * wn * along / v2) / (v2 * v2) : 0.0;
    const double w2 = wn * wn;
    if (!(w2 > 0.0)) return f;
    const double num = w.dot(d3);
    f.torsion = num / w2;
    if (D.rows() >= 4) f.torsion_rate = (w.dot(D.row(3).transpose()) * w2 - num * 2.0 * w.dot(w1)) / (w2 * w2) / v;
    return f;
}

int sign_changes(const std::vector<int>& signs, bool closed) {
    int first = 0, last = 0, changes = 0;
    for (int sign : signs) {
        if (sign == 0) continue;
        if (last != 0 && sign != last) ++changes;
        if (first == 0) first = sign;
        last = sign;
    }
    if (closed && first != 0 && last != first) ++changes;
    return changes;
}

}  // namespace cagd::analysis
