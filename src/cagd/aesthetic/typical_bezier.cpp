#include "cagd/aesthetic/typical_bezier.hpp"

#include <cmath>

#include "cagd/aesthetic/class_a.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::aesthetic {

namespace {

void require_finite_alpha(double alpha, const char* who) {
    if (!std::isfinite(alpha)) fail_input(who, "alpha = " + full_precision(alpha) + " is not finite");
}

// Eq (20)–(21) divide by α and by α − 1.
void require_rotation_alpha(double alpha, const char* who) {
    require_finite_alpha(alpha, who);
    if (alpha == 0.0 || alpha == 1.0)
        fail_input(who, "alpha = " + full_precision(alpha) +
                            ": eq (20)-(21) divide by alpha and by alpha - 1 (allowed: alpha not 0 or 1)");
}

void require_degree(int degree, int minimum, const char* who) {
    if (degree < minimum) fail_input(who, "degree " + std::to_string(degree) + " < " + std::to_string(minimum));
}

void require_length(double length, const char* who) {
    if (!(length > 0.0) || !std::isfinite(length))
        fail_input(who, "length L = " + full_precision(length) + " must be finite and > 0");
}

TypicalPolygon polygon_from_edges(const std::vector<double>& lengths, const std::vector<double>& angles) {
    TypicalPolygon p;
    const Eigen::Index n = static_cast<Eigen::Index>(lengths.size());
    p.points = Eigen::MatrixXd::Zero(n + 1, 2);
    for (Eigen::Index j = 0; j < n; ++j) {
        const double l = lengths[static_cast<std::size_t>(j)], a = angles[static_cast<std::size_t>(j)];
        p.points.row(j + 1) = p.points.row(j) + Eigen::RowVector2d(l * std::cos(a), l * std::sin(a));
    }
    p.edge_lengths = lengths;
    for (std::size_t j = 0; j + 1 < lengths.size(); ++j) {
        p.rotations.push_back(angles[j + 1] - angles[j]);
        p.scales.push_back(lengths[j + 1] / lengths[j]);
    }
    return p;
}

double direction(double alpha, double s) { return alpha * std::pow(s, (alpha - 1.0) / alpha); }  // θ(s) of eq (15)

}  // namespace

TypicalPolygon scale_one_typical_polygon(double alpha, double length, int degree) {
    const char* who = "cagd::aesthetic::scale_one_typical_polygon";
    require_finite_alpha(alpha, who);
    if (!(alpha < 0.0 || alpha > 1.0))
        fail_input(who, "alpha = " + full_precision(alpha) +
                            ": eq (16) needs alpha < 0 or alpha > 1 (0 < alpha < 1: (j ds)^((alpha-1)/alpha) diverges "
                            "at j = 0; alpha = 1: all edges parallel; alpha = 0: division by alpha)");
    require_length(length, who);
    require_degree(degree, 1, who);
    const double ds = length / degree;
    std::vector<double> lengths(static_cast<std::size_t>(degree), ds), angles;
    for (int j = 0; j < degree; ++j) angles.push_back(direction(alpha, j * ds));
    return polygon_from_edges(lengths, angles);
}

TypicalPolygon constant_rotation_typical_polygon_by_angle(double alpha, double rotation, int degree) {
    const char* who = "cagd::aesthetic::constant_rotation_typical_polygon";
    require_rotation_alpha(alpha, who);
    if (!std::isfinite(rotation) || rotation == 0.0)
        fail_input(who, "rotation = " + full_precision(rotation) + " must be finite and non-zero");
    require_degree(degree, 2, who);
    const double turn = alpha > 1.0 ? 1.0 : -1.0;
    const double k = std::pow(std::abs(rotation) / std::abs(alpha - 1.0), alpha / (alpha - 1.0));
    std::vector<double> lengths, angles;
    for (int j = 0; j < degree; ++j) {
        lengths.push_back(std::pow(j + 1.0, 1.0 / (alpha - 1.0)) * k);
        angles.push_back(turn * std::abs(rotation) * j);
    }
    return polygon_from_edges(lengths, angles);
}

TypicalPolygon constant_rotation_typical_polygon(double alpha, double length, int degree) {
    const char* who = "cagd::aesthetic::constant_rotation_typical_polygon";
    require_rotation_alpha(alpha, who);
    require_length(length, who);
    require_degree(degree, 2, who);
    double sum = 0.0;  // Σ (j+1)^{1/(α−1)}
    for (int j = 0; j < degree; ++j) sum += std::pow(j + 1.0, 1.0 / (alpha - 1.0));
    const double k = length / sum;  // = (|Δθ|/|α−1|)^{α/(α−1)}
    const double rotation = std::abs(alpha - 1.0) * std::pow(k, (alpha - 1.0) / alpha);
    return constant_rotation_typical_polygon_by_angle(alpha, rotation, degree);
}

TypicalPolygon log_spiral_polygon(double a, double b, double rotation, int degree) {
    const char* who = "cagd::aesthetic::log_spiral_polygon";
    if (!std::isfinite(a) || !std::isfinite(b) || b == 0.0)
        fail_input(who, "a = " + full_precision(a) + ", b = " + full_precision(b) + " (need finite a, finite b != 0)");
    if (!std::isfinite(rotation) || rotation == 0.0)
        fail_input(who, "rotation = " + full_precision(rotation) + " must be finite and non-zero");
    require_degree(degree, 2, who);
    TypicalPolygon p;
    p.points.resize(degree + 1, 2);
    for (int j = 0; j <= degree; ++j) {
        const double t = j * rotation / b;
        p.points.row(j) << std::exp(a * t) * std::cos(b * t), std::exp(a * t) * std::sin(b * t);
    }
    for (int j = 0; j < degree; ++j) p.edge_lengths.push_back((p.points.row(j + 1) - p.points.row(j)).norm());
    const PlanarTransitions tr = planar_transitions(p.points);
    p.rotations = tr.rotations;
    p.scales = tr.scales;
    return p;
}

double first_order_rotation(double alpha, double ds, int j) {
    return alpha * (alpha - 1.0) / alpha * std::pow((j + 1.0) * ds, -1.0 / alpha) * ds;
}

double first_order_rotation_ratio(double alpha, int j) { return std::pow((j + 1.0) / (j + 2.0), 1.0 / alpha); }

double constant_rotation_scale_ratio(double alpha, int j) {
    return std::pow((j + 2.0) / (j + 1.0), 1.0 / (alpha - 1.0));
}

double exact_rotation_ratio(double alpha, int j) {
    return (direction(alpha, j + 3.0) - direction(alpha, j + 2.0)) /
           (direction(alpha, j + 2.0) - direction(alpha, j + 1.0));
}

}  // namespace cagd::aesthetic
