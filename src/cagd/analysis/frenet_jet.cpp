#include "cagd/analysis/frenet_jet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::analysis {

FrenetJet frenet_jet(const Eigen::Ref<const Eigen::MatrixXd>& D) {
    const char* who = "cagd::analysis::frenet_jet";
    if (D.rows() < 2) fail_input(who, "needs r' and r'' (2 rows of derivatives), got " + std::to_string(D.rows()));
    if (D.cols() != 2 && D.cols() != 3)
        fail_input(who, "needs a curve of dimension 2 or 3, got " + std::to_string(D.cols()));
    FrenetJet f;
    // |r′| as every length of the library computes it (the square root of the squared norm), and
    // by Eigen's scaled norm where that square under- or overflows.
    const double v2 = D.row(0).squaredNorm();
    const double v = v2 >= std::numeric_limits<double>::min() && v2 <= std::numeric_limits<double>::max()
                         ? std::sqrt(v2)
                         : D.row(0).stableNorm();
    f.speed = v;
    f.regular = v > 0.0;
    if (!f.regular) return f;
    // The formulas above with v = 1, on the jet reparametrised to unit speed: row k divided by v
    // k + 1 times. No power of v is formed, so nothing over- or underflows at any representable
    // scale of the curve or of its parameter (v³ did at 1e±103) unless the quantity itself does.
    const Eigen::Index rows = std::min<Eigen::Index>(D.rows(), 4);
    std::array<Eigen::Vector3d, 4> U;  // U[k] = r^(k+1) of unit speed (z = 0 in the plane)
    U.fill(Eigen::Vector3d::Zero());
    for (Eigen::Index k = 0; k < rows; ++k)
        for (Eigen::Index c = 0; c < D.cols(); ++c) {
            double x = D(k, c);
            for (Eigen::Index i = 0; i <= k; ++i) x /= v;
            U[static_cast<std::size_t>(k)](c) = x;
        }
    const double along = U[0].dot(U[1]);  // r′·r″
    if (D.cols() == 2) {
        const double x1 = U[0](0), y1 = U[0](1);
        const double cross = x1 * U[1](1) - y1 * U[1](0);
        f.curvature = cross;
        if (rows >= 3) f.curvature_rate = (x1 * U[2](1) - y1 * U[2](0)) - 3.0 * cross * along;
        return f;
    }
    const Eigen::Vector3d &d1 = U[0], &d2 = U[1];
    const Eigen::Vector3d w = d1.cross(d2);
    const double wn = w.norm();
    f.curvature = wn;
    if (rows < 3) return f;
    const Eigen::Vector3d &d3 = U[2], w1 = d1.cross(d3);  // w′ = r′ × r‴
    if (!(wn > 0.0)) {
        f.curvature_rate = 0.0;
        return f;
    }
    // With the binormal b = w/|w| (w·x/|w|² = b·x/|w|: no product of two large factors).
    const Eigen::Vector3d b = w / wn;
    f.curvature_rate = b.dot(w1) - 3.0 * wn * along;
    const double b3 = b.dot(d3);
    f.torsion = b3 / wn;
    if (rows >= 4) f.torsion_rate = (b.dot(U[3]) - 2.0 * b3 * b.dot(w1) / wn) / wn;
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
