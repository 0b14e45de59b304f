#include "cagd/aesthetic/space_typical_bezier.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "cagd/core/errors.hpp"
#include "cagd/numeric/alexa_product.hpp"

namespace cagd::aesthetic {

namespace {
constexpr double kPi = std::numbers::pi;
}

const char* to_string(FrenetComposition c) {
    switch (c) {
        case FrenetComposition::alexa: return "alexa";
        case FrenetComposition::kappa_then_tau: return "kappa_then_tau";
        case FrenetComposition::tau_then_kappa: return "tau_then_kappa";
    }
    return "?";
}

Eigen::Matrix3d curvature_rotation(double angle) {
    return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}
Eigen::Matrix3d torsion_rotation(double angle) {
    return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()).toRotationMatrix();
}

Eigen::Matrix3d frenet_transition(double curvature_angle, double torsion_angle, FrenetComposition c) {
    const char* who = "cagd::aesthetic::frenet_transition";
    for (const auto& [name, v] : {std::pair{"curvature angle", curvature_angle}, {"torsion angle", torsion_angle}})
        if (!std::isfinite(v) || !(std::abs(v) < kPi))
            fail_input(who, std::string(name) + " = " + full_precision(v) + " must be finite with modulus < pi");
    const Eigen::Matrix3d rk = curvature_rotation(curvature_angle), rt = torsion_rotation(torsion_angle);
    switch (c) {
        case FrenetComposition::alexa: return numeric::alexa_product(rk, rt);
        case FrenetComposition::kappa_then_tau: return rk * rt;
        case FrenetComposition::tau_then_kappa: return rt * rk;
    }
    return rk * rt;
}

SpaceTypicalPolygon space_typical_polygon_from_rotations(const std::vector<double>& curvature_rotations,
                                                         const std::vector<double>& torsion_rotations,
                                                         double edge_length, FrenetComposition composition,
                                                         const Eigen::Matrix3d& initial_frame) {
    const char* who = "cagd::aesthetic::space_typical_polygon_from_rotations";
    if (curvature_rotations.size() != torsion_rotations.size())
        fail_input(who, std::to_string(curvature_rotations.size()) + " curvature rotations but " +
                            std::to_string(torsion_rotations.size()) + " torsion rotations");
    if (curvature_rotations.size() < 2)
        fail_input(who, "needs at least 2 rotations (degree >= 3), got " + std::to_string(curvature_rotations.size()));
    if (!(edge_length > 0.0) || !std::isfinite(edge_length))
        fail_input(who, "edge length = " + full_precision(edge_length) + " must be finite and > 0");
    if (!initial_frame.allFinite() ||
        !(initial_frame.transpose() * initial_frame).isApprox(Eigen::Matrix3d::Identity(), 1e-12) ||
        !(initial_frame.determinant() > 0.0))
        fail_input(who, "the initial frame must be orthonormal and right-handed");
    const std::size_t n = curvature_rotations.size() + 1;
    SpaceTypicalPolygon out;
    out.points.resize(static_cast<Eigen::Index>(n) + 1, 3);
    out.curvature_rotations = curvature_rotations;
    out.torsion_rotations = torsion_rotations;
    out.edge_length = edge_length;
    Eigen::Matrix3d f = initial_frame;
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    out.points.row(0) = b.transpose();
    for (std::size_t j = 0; j < n; ++j) {
        out.frames.push_back(f);
        b += edge_length * f.col(0);
        out.points.row(static_cast<Eigen::Index>(j) + 1) = b.transpose();
        if (j + 1 < n) f = f * frenet_transition(curvature_rotations[j], torsion_rotations[j], composition);
    }
    return out;
}

SpaceTypicalPolygon space_typical_polygon(const LogAestheticSpaceParameters& p, int degree,
                                          FrenetComposition composition) {
    const char* who = "cagd::aesthetic::space_typical_polygon";
    if (degree < 3)
        fail_input(who, "degree = " + std::to_string(degree) +
                            " < 3 (the torsion of a Bezier curve needs four control points)");
    p.curvature.validate(who, "curvature", p.length);
    p.torsion.validate(who, "torsion", p.length);
    const double ds = p.length / degree;
    std::vector<double> rk, rt;
    for (int j = 0; j + 1 < degree; ++j) {
        const double s0 = j * ds, s1 = (j + 1) * ds;
        rk.push_back(p.curvature.antiderivative(s1) - p.curvature.antiderivative(s0));
        rt.push_back(p.torsion.antiderivative(s1) - p.torsion.antiderivative(s0));
    }
    return space_typical_polygon_from_rotations(rk, rt, ds, composition);
}

PolygonFrenetAngles polygon_frenet_angles(const Eigen::MatrixXd& points) {
    const char* who = "cagd::aesthetic::polygon_frenet_angles";
    if (points.cols() != 3 || points.rows() < 4)
        fail_input(who, "needs at least 4 points in 3-D, got " + std::to_string(points.rows()) + "x" +
                            std::to_string(points.cols()));
    if (!points.allFinite()) fail_input(who, "points must be finite");
    std::vector<Eigen::Vector3d> e;
    for (Eigen::Index i = 0; i + 1 < points.rows(); ++i) {
        const Eigen::Vector3d d = (points.row(i + 1) - points.row(i)).transpose();
        if (d.norm() == 0.0)
            fail_input(who, "zero-length edge " + std::to_string(i) + " (points " + std::to_string(i) + " and " +
                                std::to_string(i + 1) + " coincide)");
        e.push_back(d.normalized());
    }
    PolygonFrenetAngles out;
    std::vector<Eigen::Vector3d> bin;
    for (std::size_t j = 0; j + 1 < e.size(); ++j) {
        const Eigen::Vector3d c = e[j].cross(e[j + 1]);
        out.turning.push_back(std::atan2(c.norm(), e[j].dot(e[j + 1])));
        if (c.norm() <= 1e-14)
            fail_input(who, "edges " + std::to_string(j) + " and " + std::to_string(j + 1) +
                                " are parallel: no osculating plane");
        bin.push_back(c.normalized());
    }
    for (std::size_t j = 0; j + 1 < bin.size(); ++j)
        out.dihedral.push_back(std::atan2(bin[j].cross(bin[j + 1]).dot(e[j + 1]), bin[j].dot(bin[j + 1])));
    return out;
}

}  // namespace cagd::aesthetic
