#include "cagd/numeric/alexa_product.hpp"

#include <cmath>
#include <complex>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>

#include "cagd/core/errors.hpp"

namespace cagd::numeric {

namespace {

// The eigenvalues of the check from the complex Schur form, Eigen::ComplexSchur<MatrixXcd>, the one
// the logarithm's Schur–Parlett method instantiates anyway (EigenSolver would add about 9 s of
// compile time).
Eigen::VectorXcd eigenvalues(const Eigen::MatrixXd& m) {
    return Eigen::ComplexSchur<Eigen::MatrixXcd>(m.cast<std::complex<double>>(), false).matrixT().diagonal();
}

// The principal square root, likewise from the complex Schur form (MatrixXcd::sqrt: Schur, then
// the triangular recurrence). For a real matrix without eigenvalues on the closed negative real
// axis it is real; its imaginary part is rounding and is dropped. Eigen's real-Schur square root
// (MatrixXd::sqrt) gives the same root but cost 25 s of compile time on its own.
Eigen::MatrixXd principal_sqrt(const Eigen::MatrixXd& m) {
    return Eigen::MatrixXcd(Eigen::MatrixXcd(m.cast<std::complex<double>>()).sqrt()).real();
}

void check_pair(const char* who, const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    if (a.rows() != a.cols() || b.rows() != b.cols() || a.rows() != b.rows() || a.rows() == 0)
        fail_input(who, "needs two square matrices of one size, got " + std::to_string(a.rows()) + "x" +
                            std::to_string(a.cols()) + " and " + std::to_string(b.rows()) + "x" +
                            std::to_string(b.cols()));
    if (!a.allFinite() || !b.allFinite()) fail_input(who, "matrix entries must be finite");
    for (const Eigen::MatrixXd* m : {&a, &b}) {
        const Eigen::VectorXcd ev = eigenvalues(*m);
        for (Eigen::Index i = 0; i < ev.size(); ++i)
            if (ev(i).real() <= 0.0 && std::abs(ev(i).imag()) <= 1e-12 * (1.0 + std::abs(ev(i))))
                fail_input(who, "eigenvalue " + full_precision(ev(i).real()) +
                                    (ev(i).imag() == 0.0 ? "" : " + " + full_precision(ev(i).imag()) + "i") +
                                    " on the closed negative real axis: no real principal logarithm (a rotation must "
                                    "be by less than pi)");
    }
}

}  // namespace

Eigen::MatrixXd alexa_product(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    check_pair("cagd::numeric::alexa_product", a, b);
    const Eigen::MatrixXd la = a.log(), lb = b.log();
    return (la + lb).exp();
}

Eigen::MatrixXd alexa_product_limit(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, int halvings) {
    const char* who = "cagd::numeric::alexa_product_limit";
    check_pair(who, a, b);
    if (halvings < 0 || halvings > 60)
        fail_input(who, "halvings k = " + std::to_string(halvings) + " outside 0..60 (n = 2^k)");
    Eigen::MatrixXd ra = a, rb = b;
    for (int i = 0; i < halvings; ++i) {
        ra = principal_sqrt(ra);
        rb = principal_sqrt(rb);
    }
    Eigen::MatrixXd p = ra * rb;
    for (int i = 0; i < halvings; ++i) p = p * p;
    return p;
}

double alexa_limit_error_coefficient(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    check_pair("cagd::numeric::alexa_limit_error_coefficient", a, b);
    const Eigen::MatrixXd la = a.log(), lb = b.log();
    const Eigen::Index n = a.rows();
    Eigen::MatrixXd block = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    block.topLeftCorner(n, n) = la + lb;
    block.bottomRightCorner(n, n) = la + lb;
    block.topRightCorner(n, n) = (la * lb - lb * la) / 2.0;
    const Eigen::MatrixXd e = block.exp();
    return e.topRightCorner(n, n).norm();
}

Eigen::Matrix3d rotation_from_vector(const Eigen::Vector3d& phi) {
    if (!phi.allFinite()) fail_input("cagd::numeric::rotation_from_vector", "rotation vector must be finite");
    const double angle = phi.norm();
    if (angle == 0.0) return Eigen::Matrix3d::Identity();
    return Eigen::AngleAxisd(angle, phi / angle).toRotationMatrix();
}

}  // namespace cagd::numeric
