#include "cagd/aesthetic/class_a.hpp"

#include <cmath>

#include "cagd/core/errors.hpp"

namespace cagd::aesthetic {

namespace {
void require_square(const Eigen::MatrixXd& m, const char* who) {
    if (m.rows() != m.cols() || m.rows() < 2 || m.rows() > 3)
        fail_input(who, "matrix must be 2x2 or 3x3, got " + std::to_string(m.rows()) + "x" + std::to_string(m.cols()));
    if (!m.allFinite()) fail_input(who, "matrix has a non-finite entry");
}
}  // namespace

ClassATest class_a_test(const Eigen::MatrixXd& m, double tolerance) {
    require_square(m, "cagd::aesthetic::class_a_test");
    const Eigen::Index d = m.rows();
    const Eigen::MatrixXd id = Eigen::MatrixXd::Identity(d, d);
    ClassATest r;
    r.min_eig_symmetric_part =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m.transpose() + m - 2.0 * id).eigenvalues().minCoeff();
    r.min_eig_gram = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m.transpose() * m - id).eigenvalues().minCoeff();
    r.singular_values = Eigen::JacobiSVD<Eigen::MatrixXd>(m).singularValues();
    r.eq1 = r.min_eig_symmetric_part >= -tolerance;
    r.eq2 = r.eq1 && r.min_eig_gram >= -tolerance;
    r.singular_at_least_one = r.singular_values.minCoeff() >= 1.0 - tolerance;
    r.cao_wang = true;
    for (Eigen::Index i = 0; i < d; ++i)
        for (Eigen::Index j = 0; j < d; ++j)
            if (i != j && 2.0 * r.singular_values(i) < r.singular_values(j) + 1.0 - tolerance) r.cao_wang = false;
    r.symmetric = (m - m.transpose()).norm() <= 1e-14 * m.norm();
    r.class_a = r.eq2 && r.singular_at_least_one && r.cao_wang;
    return r;
}

Eigen::Matrix2d typical_matrix(double theta, double scale) {
    if (!std::isfinite(theta) || !(scale > 0.0) || !std::isfinite(scale))
        fail_input("cagd::aesthetic::typical_matrix", "theta = " + full_precision(theta) +
                                                          ", scale = " + full_precision(scale) +
                                                          " (need finite theta, finite scale > 0)");
    Eigen::Matrix2d m;
    m << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
    return scale * m;
}

bool typical_matrix_condition(double theta, double scale) {
    if (!std::isfinite(theta) || !(scale > 0.0) || !std::isfinite(scale))
        fail_input("cagd::aesthetic::typical_matrix_condition", "theta = " + full_precision(theta) +
                                                                    ", scale = " + full_precision(scale) +
                                                                    " (need finite theta, finite scale > 0)");
    if (scale > 1.0) return std::cos(theta) > 1.0 / scale;
    if (scale < 1.0) return std::cos(theta) > scale;
    return false;  // s = 1: (4) is silent; Mᵀ + M − 2I = 2(cos θ − 1) I ≥ 0 only for θ = 0
}

Eigen::MatrixXd nonstationary_control_points(const Eigen::VectorXd& b0, const Eigen::VectorXd& db0,
                                             const std::vector<Eigen::MatrixXd>& matrices) {
    const char* who = "cagd::aesthetic::nonstationary_control_points";
    if (b0.size() != db0.size() || b0.size() < 2 || b0.size() > 3)
        fail_input(who, "b0 and db0 must both be 2- or 3-vectors");
    if (!b0.allFinite() || !db0.allFinite()) fail_input(who, "b0 or db0 has a non-finite entry");
    if (!(db0.norm() > 0.0)) fail_input(who, "db0 is the zero vector (zero-length first edge)");
    for (const auto& m : matrices) {
        require_square(m, who);
        if (m.rows() != b0.size()) fail_input(who, "matrix size does not match the dimension of b0");
    }
    const Eigen::Index n = static_cast<Eigen::Index>(matrices.size()) + 1;  // degree
    Eigen::MatrixXd pts(n + 1, b0.size());
    pts.row(0) = b0.transpose();
    Eigen::VectorXd edge = db0;
    for (Eigen::Index j = 0; j < n; ++j) {
        pts.row(j + 1) = pts.row(j) + edge.transpose();
        if (j + 1 < n) edge = matrices[static_cast<std::size_t>(j)] * edge;
    }
    return pts;
}

Eigen::MatrixXd class_a_control_points(const Eigen::VectorXd& b0, const Eigen::VectorXd& db0, const Eigen::MatrixXd& m,
                                       int degree) {
    if (degree < 1) fail_input("cagd::aesthetic::class_a_control_points", "degree " + std::to_string(degree) + " < 1");
    return nonstationary_control_points(b0, db0, std::vector<Eigen::MatrixXd>(static_cast<std::size_t>(degree - 1), m));
}

PlanarTransitions planar_transitions(const Eigen::MatrixXd& points) {
    const char* who = "cagd::aesthetic::planar_transitions";
    if (points.cols() != 2 || points.rows() < 3) fail_input(who, "needs at least 3 planar points");
    PlanarTransitions t;
    for (Eigen::Index j = 0; j + 2 < points.rows(); ++j) {
        const Eigen::Vector2d a = (points.row(j + 1) - points.row(j)).transpose(),
                              b = (points.row(j + 2) - points.row(j + 1)).transpose();
        if (!(a.norm() > 0.0) || !(b.norm() > 0.0)) fail_input(who, "zero-length edge at point " + std::to_string(j));
        t.rotations.push_back(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)));
        t.scales.push_back(b.norm() / a.norm());
    }
    return t;
}

}  // namespace cagd::aesthetic
