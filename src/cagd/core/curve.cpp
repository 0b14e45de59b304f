#include "cagd/core/curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cagd/core/errors.hpp"

namespace cagd {

std::vector<double> unit_piece_breakpoints(int pieces) {
    std::vector<double> b(static_cast<std::size_t>(pieces) + 1);
    for (std::size_t k = 0; k < b.size(); ++k) b[k] = static_cast<double>(k);
    return b;
}

void reject_unit_piece(const char* who, double u, int pieces, int order) {
    if (!(u >= 0.0 && u <= pieces)) fail_input(who, "u = " + full_precision(u) + " outside [0, " + std::to_string(pieces) + "]");
    fail_input(who, "order must be >= 0, got " + std::to_string(order));
}

PieceLocation locate_unit_piece_from_left(const char* who, double u, int pieces, int order) {
    if (!(u > 0.0 && u <= pieces)) fail_input(who, "left limit at u = " + full_precision(u) + " needs u in (0, " + std::to_string(pieces) + "]");
    if (order < 0) fail_input(who, "order must be >= 0, got " + std::to_string(order));
    const int s = std::max(static_cast<int>(std::ceil(u)) - 1, 0);
    return {s, u - s};
}

Eigen::MatrixXd Curve::derivatives(double t, int order) const {
    if (order < 1) fail_input("cagd::Curve::derivatives", "order must be >= 1, got " + std::to_string(order));
    return jet(t, order).bottomRows(order);
}

void reject_jet_capacity(const char* who, int rows, int dimension) {
    fail_input(who, "a JetMatrix holds 1.." + std::to_string(kJetCapacity) + " rows and 1..3 columns, asked for " + std::to_string(rows) + " x " + std::to_string(dimension));
}

void Curve::jet_into(double t, int order, JetMatrix& out) const {
    require_jet_capacity("cagd::Curve::jet_into", order + 1, dimension());
    out = jet(t, order);
}

void Curve::jets_into(const double* t, std::size_t count, int order, double* out) const {
    const int dim = dimension();
    require_jet_capacity("cagd::Curve::jets_into", order + 1, dim);
    const std::size_t stride = static_cast<std::size_t>((order + 1) * dim);
    JetMatrix jet;
    for (std::size_t k = 0; k < count; ++k) {
        jet_into(t[k], order, jet);
        double* o = out + k * stride;
        for (int r = 0; r <= order; ++r)
            for (int c = 0; c < dim; ++c) o[r * dim + c] = jet(r, c);
    }
}

void Curve::derivatives_into(double t, int order, JetMatrix& out) const {
    require_jet_capacity("cagd::Curve::derivatives_into", order, dimension());
    out = derivatives(t, order);
}

Eigen::MatrixXd Curve::jet_from_left(double t, int order) const {
    if (breakpoints().size() > 2) throw std::logic_error("cagd::Curve::jet_from_left: a curve of several pieces must override it");
    if (!(t > t_min() && t <= t_max()))
        fail_input("cagd::Curve::jet_from_left", "t = " + full_precision(t) + " outside (" + full_precision(t_min()) + ", " + full_precision(t_max()) + "]");
    return jet(t, order);
}

}  // namespace cagd
