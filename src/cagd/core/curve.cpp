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
    if (!(u >= 0.0 && u <= pieces))
        fail_input(who, "u = " + full_precision(u) + " outside [0, " + std::to_string(pieces) + "]");
    fail_input(who, "order must be >= 0, got " + std::to_string(order));
}

PieceLocation locate_unit_piece_from_left(const char* who, double u, int pieces, int order) {
    if (!(u > 0.0 && u <= pieces))
        fail_input(who, "left limit at u = " + full_precision(u) + " needs u in (0, " + std::to_string(pieces) + "]");
    if (order < 0) fail_input(who, "order must be >= 0, got " + std::to_string(order));
    const int s = std::max(static_cast<int>(std::ceil(u)) - 1, 0);
    return {s, u - s};
}

namespace {
// The conveniences' checks, once for every curve.
void require_order(const char* who, int order, int least) {
    if (order < least) fail_input(who, "order must be >= " + std::to_string(least) + ", got " + std::to_string(order));
}
void require_inside(const Curve& c, const char* who, double t, JetSide side) {
    const double a = c.t_min(), b = c.t_max();
    if (side == JetSide::left ? !(t > a && t <= b) : !(t >= a && t <= b))
        fail_input(who, "t = " + full_precision(t) + " outside " + (side == JetSide::left ? "(" : "[") +
                            full_precision(a) + ", " + full_precision(b) + "]" +
                            (side == JetSide::left ? " (a left limit needs t > t_min)" : ""));
}

// Rows first..order of the jet at t, from `side`, after the checks every curve shares.
Eigen::MatrixXd evaluated(const Curve& c, const char* who, double t, int order, int first, JetSide side) {
    require_order(who, order, first);
    require_inside(c, who, t, side);
    Eigen::MatrixXd out(order + 1 - first, c.dimension());
    c.evaluate_jet(t, first, side, out);
    return out;
}
}  // namespace

Eigen::MatrixXd Curve::jet(double t, int order) const {
    return evaluated(*this, "cagd::Curve::jet", t, order, 0, JetSide::right);
}
Eigen::MatrixXd Curve::jet_from_left(double t, int order) const {
    return evaluated(*this, "cagd::Curve::jet_from_left", t, order, 0, JetSide::left);
}
Eigen::MatrixXd Curve::derivatives(double t, int order) const {
    return evaluated(*this, "cagd::Curve::derivatives", t, order, 1, JetSide::right);
}

void reject_jet_capacity(const char* who, int rows, int dimension) {
    fail_input(who, "a JetMatrix holds 1.." + std::to_string(kJetCapacity) + " rows and 1..3 columns, asked for " +
                        std::to_string(rows) + " x " + std::to_string(dimension));
}

void Curve::jet_into(double t, int order, JetMatrix& out) const {
    require_jet_capacity("cagd::Curve::jet_into", order + 1, dimension());
    require_inside(*this, "cagd::Curve::jet_into", t, JetSide::right);
    out.resize(order + 1, dimension());
    evaluate_jet(t, 0, JetSide::right, out);
}

void Curve::derivatives_into(double t, int order, JetMatrix& out) const {
    require_jet_capacity("cagd::Curve::derivatives_into", order, dimension());
    require_inside(*this, "cagd::Curve::derivatives_into", t, JetSide::right);
    out.resize(order, dimension());
    evaluate_jet(t, 1, JetSide::right, out);
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

}  // namespace cagd
