#include "cagd/surface/bezier_patch.hpp"

#include <cmath>
#include <string>

#include "cagd/core/bernstein_polynomial.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/spline/bezier.hpp"

namespace cagd::surface {

namespace {

const char* kPatchWho = "cagd::surface::BezierPatch";

// Rows a: the values (order 0), first or second derivatives of B_{i,d} at ts[a], i = 0 … d.
Eigen::MatrixXd basis_rows(int d, const std::vector<double>& ts, int order) {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(ts.size()), d + 1);
    if (order > d) return out;
    for (std::size_t a = 0; a < ts.size(); ++a) {
        const std::vector<double> b = bernstein_basis_values(d - order, ts[a]);
        const auto row = static_cast<Eigen::Index>(a);
        // d^k/dt^k B_{i,d} = d!/(d−k)! Σ_r (−1)^{k−r} C(k, r) B_{i−r,d−k}: the lower basis shifted.
        for (int i = 0; i + order <= d; ++i) {
            const double v = b[static_cast<std::size_t>(i)];
            if (order == 0) {
                out(row, i) += v;
            } else if (order == 1) {
                out(row, i) -= d * v;
                out(row, i + 1) += d * v;
            } else {
                const double c = static_cast<double>(d) * (d - 1);
                out(row, i) += c * v;
                out(row, i + 1) -= 2.0 * c * v;
                out(row, i + 2) += c * v;
            }
        }
    }
    return out;
}

void check_parameters(const std::vector<double>& ts, const char* name) {
    for (double t : ts)
        if (!(t >= 0.0 && t <= 1.0))
            fail_input(kPatchWho, std::string(name) + " = " + full_precision(t) + " outside [0, 1]");
}

}  // namespace

analysis::SurfaceJet2 SurfaceGrid::jet(Eigen::Index a, Eigen::Index b) const {
    analysis::SurfaceJet2 j;
    Eigen::Vector3d* out[6] = {&j.s, &j.su, &j.sv, &j.suu, &j.suv, &j.svv};
    for (std::size_t k = 0; k < 6; ++k)
        for (std::size_t c = 0; c < 3; ++c) (*out[k])(static_cast<Eigen::Index>(c)) = quantity[k][c](a, b);
    return j;
}

BezierPatch::BezierPatch(ControlNet net) : net_(std::move(net)) {
    if (net_[0].rows() < 1 || net_[0].cols() < 1) fail_input(kPatchWho, "empty control net");
    for (const Eigen::MatrixXd& c : net_) {
        if (c.rows() != net_[0].rows() || c.cols() != net_[0].cols())
            fail_input(kPatchWho, "coordinate matrices of different sizes (" + std::to_string(c.rows()) + "x" +
                                      std::to_string(c.cols()) + " vs " + std::to_string(net_[0].rows()) + "x" +
                                      std::to_string(net_[0].cols()) + ")");
        if (!c.allFinite()) fail_input(kPatchWho, "control points must be finite");
    }
}

Eigen::Vector3d BezierPatch::control_point(int i, int j) const {
    if (i < 0 || j < 0 || i > degree_u() || j > degree_v())
        fail_input(kPatchWho, "control point (" + std::to_string(i) + ", " + std::to_string(j) + ") outside the net");
    return {net_[0](i, j), net_[1](i, j), net_[2](i, j)};
}

SurfaceGrid BezierPatch::evaluate_grid(const std::vector<double>& us, const std::vector<double>& vs) const {
    check_parameters(us, "u");
    check_parameters(vs, "v");
    const int m = degree_u(), n = degree_v();
    const std::array<Eigen::MatrixXd, 3> bu{basis_rows(m, us, 0), basis_rows(m, us, 1), basis_rows(m, us, 2)};
    const std::array<Eigen::MatrixXd, 3> bv{basis_rows(n, vs, 0), basis_rows(n, vs, 1), basis_rows(n, vs, 2)};
    // (order in u, order in v) of S, S_u, S_v, S_uu, S_uv, S_vv.
    constexpr int orders[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    SurfaceGrid g;
    for (std::size_t c = 0; c < 3; ++c) {
        std::array<Eigen::MatrixXd, 3> left;  // Bu_k · P_c
        for (std::size_t k = 0; k < 3; ++k) left[k] = bu[k] * net_[c];
        for (std::size_t q = 0; q < 6; ++q)
            g.quantity[q][c] =
                left[static_cast<std::size_t>(orders[q][0])] * bv[static_cast<std::size_t>(orders[q][1])].transpose();
    }
    return g;
}

analysis::SurfaceJet2 BezierPatch::jet(double u, double v) const { return evaluate_grid({u}, {v}).jet(0, 0); }

analysis::SurfaceJet2 BezierPatch::jet_de_casteljau(double u, double v) const {
    check_parameters({u}, "u");
    check_parameters({v}, "v");
    const int m = degree_u(), n = degree_v();
    // Rows k of q[r]: ∂^r/∂v^r of the row curve i at v.
    std::array<Eigen::MatrixXd, 3> q;
    for (auto& qr : q) qr.resize(m + 1, 3);
    for (int i = 0; i <= m; ++i) {
        Eigen::MatrixXd row(n + 1, 3);
        for (int c = 0; c < 3; ++c) row.col(c) = net_[static_cast<std::size_t>(c)].row(i).transpose();
        const Eigen::MatrixXd jv = BezierCurve(row).jet(v, 2);
        for (std::size_t r = 0; r < 3; ++r) q[r].row(i) = jv.row(static_cast<Eigen::Index>(r));
    }
    const Eigen::MatrixXd j0 = BezierCurve(q[0]).jet(u, 2), j1 = BezierCurve(q[1]).jet(u, 1),
                          j2 = BezierCurve(q[2]).jet(u, 0);
    analysis::SurfaceJet2 j;
    j.s = j0.row(0).transpose();
    j.su = j0.row(1).transpose();
    j.suu = j0.row(2).transpose();
    j.sv = j1.row(0).transpose();
    j.suv = j1.row(1).transpose();
    j.svv = j2.row(0).transpose();
    return j;
}

}  // namespace cagd::surface
