#include "cagd/surface/hosaka_patch.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "cagd/core/errors.hpp"
#include "cagd/core/points.hpp"

namespace cagd::surface {

namespace {

void require_unit(const char* who, double u, double v, int a, int b) {
    if (!(u >= 0.0 && u <= 1.0) || !(v >= 0.0 && v <= 1.0))
        fail_input(who, "(u, v) must lie in [0, 1]², got (" + full_precision(u) + ", " + full_precision(v) + ")");
    if (a < 0 || b < 0)
        fail_input(who, "derivative orders must be >= 0, got (" + std::to_string(a) + ", " + std::to_string(b) + ")");
}

// One edge's k-th derivative on [0, 1], relative to its start for k = 0 (eq 28's convention).
Eigen::VectorXd relative_edge(const Curve& c, double s, int k) {
    Eigen::VectorXd r = unit_edge_jet(c, s, k).row(k).transpose();
    if (k == 0) r -= c.point(c.t_min());
    return r;
}

// ∂^{a+b}/∂u^a ∂v^b of the terms of eq (27) with i, j ≥ first.
Eigen::VectorXd tensor_sum(const CornerDerivatives& c, const spline::HosakaBasis& basis, double u, double v, int a,
                           int b, int first) {
    Eigen::VectorXd s = Eigen::VectorXd::Zero(c.dimension());
    for (int i = first; i <= c.m(); ++i) {
        const double pu = basis.p(i, u, a), qu = basis.q(i, u, a);
        for (int j = first; j <= c.m(); ++j) {
            const double pv = basis.p(j, v, b), qv = basis.q(j, v, b);
            s += c.at(0, 0, i, j) * (pu * pv) + c.at(0, 1, i, j) * (pu * qv) + c.at(1, 0, i, j) * (qu * pv) +
                 c.at(1, 1, i, j) * (qu * qv);
        }
    }
    return s;
}

Eigen::VectorXd chord(const Curve& c) { return c.point(c.t_max()) - c.point(c.t_min()); }

void require_edges(const PatchEdges& e, const char* who) {
    const Curve* curves[] = {e.r1.get(), e.r2.get(), e.r3.get(), e.r4.get()};
    for (int k = 0; k < 4; ++k) {
        if (!curves[k]) fail_input(who, "edge R" + std::to_string(k + 1) + " is missing");
        if (curves[k]->dimension() != curves[0]->dimension())
            fail_input(who, "edges must have one dimension, R" + std::to_string(k + 1) + " has " +
                                std::to_string(curves[k]->dimension()));
    }
    const auto start = [](const Curve& c) { return c.point(c.t_min()); };
    const auto end = [](const Curve& c) { return c.point(c.t_max()); };
    double size = 1.0;
    for (const Curve* c : curves) size = std::max({size, start(*c).norm(), end(*c).norm()});
    const struct {
        Eigen::VectorXd a, b;
        const char* name;
    } corners[] = {{start(*e.r1), start(*e.r2), "S(0,0): R1(0) vs R2(0)"},
                   {end(*e.r1), start(*e.r4), "S(1,0): R1(1) vs R4(0)"},
                   {end(*e.r2), start(*e.r3), "S(0,1): R2(1) vs R3(0)"},
                   {end(*e.r3), end(*e.r4), "S(1,1): R3(1) vs R4(1)"}};
    for (const auto& c : corners)
        if ((c.a - c.b).norm() > 1e-9 * size)
            fail_input(who, std::string("edges do not meet at corner ") + c.name + ", distance " +
                                full_precision((c.a - c.b).norm()));
}

}  // namespace

CornerDerivatives::CornerDerivatives(int m, int dimension) : m_(m), dimension_(dimension) {
    if (m < 0) fail_input("cagd::surface::CornerDerivatives", "m must be >= 0, got " + std::to_string(m));
    if (dimension < 1)
        fail_input("cagd::surface::CornerDerivatives", "dimension must be >= 1, got " + std::to_string(dimension));
    data_.assign(4 * static_cast<std::size_t>((m + 1) * (m + 1)), Eigen::VectorXd::Zero(dimension));
}

std::size_t CornerDerivatives::index(int k, int l, int i, int j) const {
    if (k < 0 || k > 1 || l < 0 || l > 1 || i < 0 || i > m_ || j < 0 || j > m_)
        fail_input("cagd::surface::CornerDerivatives::at",
                   "need k, l in {0, 1} and i, j in [0, m], got k=" + std::to_string(k) + " l=" + std::to_string(l) +
                       " i=" + std::to_string(i) + " j=" + std::to_string(j));
    return static_cast<std::size_t>(((k * 2 + l) * (m_ + 1) + i) * (m_ + 1) + j);
}

Eigen::VectorXd& CornerDerivatives::at(int k, int l, int i, int j) { return data_[index(k, l, i, j)]; }
const Eigen::VectorXd& CornerDerivatives::at(int k, int l, int i, int j) const { return data_[index(k, l, i, j)]; }

HosakaPatch::HosakaPatch(CornerDerivatives corners) : corners_(std::move(corners)), basis_(corners_.m()) {
    for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l)
            for (int i = 0; i <= m(); ++i)
                for (int j = 0; j <= m(); ++j) {
                    const Eigen::VectorXd& s = corners_.at(k, l, i, j);
                    if (s.size() != corners_.dimension() || !s.allFinite())
                        fail_input("cagd::surface::HosakaPatch", "corner derivative S_" + std::to_string(k) +
                                                                     std::to_string(l) + "^(" + std::to_string(i) +
                                                                     "," + std::to_string(j) +
                                                                     ") must be a finite vector of dimension " +
                                                                     std::to_string(corners_.dimension()));
                }
}

Eigen::VectorXd HosakaPatch::derivative(double u, double v, int a, int b) const {
    require_unit("cagd::surface::HosakaPatch::derivative", u, v, a, b);
    return tensor_sum(corners_, basis_, u, v, a, b, 0);
}

spline::HosakaCurve HosakaPatch::edge(int which) const {
    if (which < 1 || which > 4)
        fail_input("cagd::surface::HosakaPatch::edge", "edge must be 1..4, got " + std::to_string(which));
    // R1: (0,0)→(1,0) along u; R2: (0,0)→(0,1) along v; R3: (0,1)→(1,1) along u; R4: (1,0)→(1,1) along v.
    const bool along_u = which == 1 || which == 3;
    const int fixed = (which == 3 || which == 4) ? 1 : 0;
    Eigen::MatrixXd start(m() + 1, corners_.dimension()), end(m() + 1, corners_.dimension());
    for (int i = 0; i <= m(); ++i) {
        start.row(i) = (along_u ? corners_.at(0, fixed, i, 0) : corners_.at(fixed, 0, 0, i)).transpose();
        end.row(i) = (along_u ? corners_.at(1, fixed, i, 0) : corners_.at(fixed, 1, 0, i)).transpose();
    }
    return spline::HosakaCurve(m(), start, end);
}

PatchEdges HosakaPatch::edges() const {
    return {std::make_shared<spline::HosakaCurve>(edge(1)), std::make_shared<spline::HosakaCurve>(edge(2)),
            std::make_shared<spline::HosakaCurve>(edge(3)), std::make_shared<spline::HosakaCurve>(edge(4))};
}

Eigen::MatrixXd unit_edge_jet(const Curve& edge, double s, int order) {
    const double span = edge.t_max() - edge.t_min();
    Eigen::MatrixXd j = edge.jet(std::min(edge.t_min() + s * span, edge.t_max()), order);
    for (int k = 1; k <= order; ++k) j.row(k) *= std::pow(span, k);
    return j;
}

EdgeFormPatch::EdgeFormPatch(int m, PatchEdges edges, CornerDerivatives twists)
    : basis_(m), edges_(std::move(edges)), twists_(std::move(twists)) {
    const char* who = "cagd::surface::EdgeFormPatch";
    require_edges(edges_, who);
    if (twists_.m() != m || twists_.dimension() != edges_.r1->dimension())
        fail_input(who, "twist data must have m = " + std::to_string(m) + " and the edges' dimension " +
                            std::to_string(edges_.r1->dimension()));
    corner_term_ = 0.5 * (chord(*edges_.r1) + chord(*edges_.r2) - chord(*edges_.r3) - chord(*edges_.r4));
}

EdgeFormPatch::EdgeFormPatch(int m, PatchEdges edges)
    : EdgeFormPatch(m, edges, CornerDerivatives(m, edges.r1 ? edges.r1->dimension() : 1)) {}

Eigen::VectorXd EdgeFormPatch::derivative(double u, double v, int a, int b) const {
    require_unit("cagd::surface::EdgeFormPatch::derivative", u, v, a, b);
    const auto f = [&](double t, int k) { return basis_.q(0, t, k); };
    const Curve &r1 = *edges_.r1, &r2 = *edges_.r2, &r3 = *edges_.r3, &r4 = *edges_.r4;
    Eigen::VectorXd s = Eigen::VectorXd::Zero(r1.dimension());
    if (a == 0 && b == 0) s += r1.point(r1.t_min());  // S(0,0)
    if (b == 0) s += relative_edge(r1, u, a);
    s += (relative_edge(r3, u, a) - relative_edge(r1, u, a)) * f(v, b);
    if (a == 0) s += relative_edge(r2, v, b);
    s += (relative_edge(r4, v, b) - relative_edge(r2, v, b)) * f(u, a);
    s += corner_term_ * (f(u, a) * f(v, b));
    if (m() >= 1) s += tensor_sum(twists_, basis_, u, v, a, b, 1);  // S0(u, v): the terms of eq (27) with i, j ≥ 1
    return s;
}

Eigen::VectorXd coons_boolean_sum(const PatchEdges& e, int m, double u, double v) {
    const char* who = "cagd::surface::coons_boolean_sum";
    require_edges(e, who);
    require_unit(who, u, v, 0, 0);
    const spline::HosakaBasis basis(m);
    const double fu = basis.q(0, u, 0), fv = basis.q(0, v, 0);
    const auto at = [](const Curve& c, double s) { return Eigen::VectorXd(unit_edge_jet(c, s, 0).row(0).transpose()); };
    const Eigen::VectorXd ruled_u = (1 - fv) * at(*e.r1, u) + fv * at(*e.r3, u);  // P_v: blend of the u-edges
    const Eigen::VectorXd ruled_v = (1 - fu) * at(*e.r2, v) + fu * at(*e.r4, v);  // P_u: blend of the v-edges
    const Eigen::VectorXd tensor = (1 - fu) * (1 - fv) * at(*e.r1, 0) + fu * (1 - fv) * at(*e.r1, 1) +
                                   (1 - fu) * fv * at(*e.r3, 0) + fu * fv * at(*e.r3, 1);
    return ruled_u + ruled_v - tensor;
}

CartesianSurface::CartesianSurface(int m, std::vector<double> x, std::vector<double> y,
                                   std::vector<Eigen::MatrixXd> node_derivatives)
    : basis_(m), x_(std::move(x)), y_(std::move(y)), nodes_(std::move(node_derivatives)) {
    const char* who = "cagd::surface::CartesianSurface";
    require_increasing(x_, 2, "x", who);
    require_increasing(y_, 2, "y", who);
    if (nodes_.size() != x_.size() * y_.size())
        fail_input(who, "needs one node matrix per grid node (" + std::to_string(x_.size() * y_.size()) + "), got " +
                            std::to_string(nodes_.size()));
    for (std::size_t n = 0; n < nodes_.size(); ++n)
        if (nodes_[n].rows() != m + 1 || nodes_[n].cols() != m + 1 || !nodes_[n].allFinite())
            fail_input(who, "node " + std::to_string(n) +
                                ": needs a finite (m+1) x (m+1) matrix of derivatives, m = " + std::to_string(m));
}

const Eigen::MatrixXd& CartesianSurface::node(int a, int b) const {
    if (a < 0 || b < 0 || a >= static_cast<int>(x_.size()) || b >= static_cast<int>(y_.size()))
        fail_input("cagd::surface::CartesianSurface::node",
                   "node (" + std::to_string(a) + ", " + std::to_string(b) + ") outside the grid");
    return nodes_[static_cast<std::size_t>(a) + x_.size() * static_cast<std::size_t>(b)];
}

double CartesianSurface::derivative_in(int cx, int cy, double u, double v, int a, int b) const {
    const char* who = "cagd::surface::CartesianSurface::derivative_in";
    if (cx < 0 || cy < 0 || cx + 1 >= static_cast<int>(x_.size()) || cy + 1 >= static_cast<int>(y_.size()))
        fail_input(who, "cell (" + std::to_string(cx) + ", " + std::to_string(cy) + ") outside the grid");
    require_unit(who, u, v, a, b);
    const double lx = x_[static_cast<std::size_t>(cx) + 1] - x_[static_cast<std::size_t>(cx)];
    const double ly = y_[static_cast<std::size_t>(cy) + 1] - y_[static_cast<std::size_t>(cy)];
    const Eigen::MatrixXd &z00 = node(cx, cy), &z01 = node(cx, cy + 1), &z10 = node(cx + 1, cy),
                          &z11 = node(cx + 1, cy + 1);
    double s = 0.0;
    for (int i = 0; i <= m(); ++i) {
        const double pu = basis_.p(i, u, a), qu = basis_.q(i, u, a);
        for (int j = 0; j <= m(); ++j) {
            const double pv = basis_.p(j, v, b), qv = basis_.q(j, v, b);
            s += std::pow(lx, i) * std::pow(ly, j) *
                 (z00(i, j) * pu * pv + z01(i, j) * pu * qv + z10(i, j) * qu * pv + z11(i, j) * qu * qv);
        }
    }
    return s / (std::pow(lx, a) * std::pow(ly, b));
}

double CartesianSurface::derivative(double x, double y, int a, int b) const {
    const char* who = "cagd::surface::CartesianSurface::derivative";
    if (!(x >= x_.front() && x <= x_.back()) || !(y >= y_.front() && y <= y_.back()))
        fail_input(who, "(x, y) = (" + full_precision(x) + ", " + full_precision(y) + ") outside the grid [" +
                            full_precision(x_.front()) + ", " + full_precision(x_.back()) + "] x [" +
                            full_precision(y_.front()) + ", " + full_precision(y_.back()) + "]");
    const auto cell = [](const std::vector<double>& g, double t) {
        const auto it = std::upper_bound(g.begin(), g.end(), t);
        return std::clamp(static_cast<int>(it - g.begin()) - 1, 0, static_cast<int>(g.size()) - 2);
    };
    const int cx = cell(x_, x), cy = cell(y_, y);
    const double u = (x - x_[static_cast<std::size_t>(cx)]) /
                     (x_[static_cast<std::size_t>(cx) + 1] - x_[static_cast<std::size_t>(cx)]);
    const double v = (y - y_[static_cast<std::size_t>(cy)]) /
                     (y_[static_cast<std::size_t>(cy) + 1] - y_[static_cast<std::size_t>(cy)]);
    return derivative_in(cx, cy, std::clamp(u, 0.0, 1.0), std::clamp(v, 0.0, 1.0), a, b);
}

CartesianSurface cartesian_spline_surface(const std::vector<double>& x, const std::vector<double>& y,
                                          const Eigen::MatrixXd& z) {
    const char* who = "cagd::surface::cartesian_spline_surface";
    if (z.rows() != static_cast<Eigen::Index>(x.size()) || z.cols() != static_cast<Eigen::Index>(y.size()))
        fail_input(who, "heights must be " + std::to_string(x.size()) + " x " + std::to_string(y.size()) +
                            " (x by y), got " + std::to_string(z.rows()) + " x " + std::to_string(z.cols()));
    // Columns of `values` are independent functions: splines along x for every y line, and so on.
    const Eigen::MatrixXd zx = spline::hosaka_explicit_spline(x, z).slopes;                // ζ^{(1,0)}, nx × ny
    const Eigen::MatrixXd zy = spline::hosaka_explicit_spline(y, z.transpose()).slopes;    // ζ^{(0,1)}, ny × nx
    const Eigen::MatrixXd zxy = spline::hosaka_explicit_spline(y, zx.transpose()).slopes;  // ζ^{(1,1)}, ny × nx
    std::vector<Eigen::MatrixXd> nodes;
    for (std::size_t b = 0; b < y.size(); ++b)
        for (std::size_t a = 0; a < x.size(); ++a) {
            const Eigen::Index ia = static_cast<Eigen::Index>(a), ib = static_cast<Eigen::Index>(b);
            Eigen::MatrixXd n(2, 2);
            n << z(ia, ib), zy(ib, ia), zx(ia, ib), zxy(ib, ia);
            nodes.push_back(n);
        }
    return CartesianSurface(1, x, y, std::move(nodes));
}

PatchEdges edges_through_points(const PointList& bottom, const PointList& left, const PointList& top,
                                const PointList& right) {
    const auto edge = [](const PointList& p) {
        return std::make_shared<spline::HosakaCurve>(spline::hosaka_c2_spline(p).curve);
    };
    return {edge(bottom), edge(left), edge(top), edge(right)};
}

GridHeights grid_from_points(const PointList& xyz) {
    const char* who = "cagd::surface::grid_from_points";
    if (xyz.cols() != 3) fail_input(who, "needs rows x, y, z, got " + std::to_string(xyz.cols()) + " columns");
    std::set<double> xs, ys;
    for (Eigen::Index r = 0; r < xyz.rows(); ++r) {
        if (!xyz.row(r).allFinite()) fail_input(who, "row " + std::to_string(r + 1) + " is not finite");
        xs.insert(xyz(r, 0));
        ys.insert(xyz(r, 1));
    }
    GridHeights g{std::vector<double>(xs.begin(), xs.end()), std::vector<double>(ys.begin(), ys.end()), {}};
    if (static_cast<std::size_t>(xyz.rows()) != g.x.size() * g.y.size())
        fail_input(who, "the points must cover a rectangular grid exactly once: " + std::to_string(g.x.size()) +
                            " distinct x and " + std::to_string(g.y.size()) + " distinct y need " +
                            std::to_string(g.x.size() * g.y.size()) + " rows, got " + std::to_string(xyz.rows()));
    std::map<std::pair<double, double>, double> height;
    for (Eigen::Index r = 0; r < xyz.rows(); ++r)
        if (!height.emplace(std::make_pair(xyz(r, 0), xyz(r, 1)), xyz(r, 2)).second)
            fail_input(who, "node (" + full_precision(xyz(r, 0)) + ", " + full_precision(xyz(r, 1)) +
                                ") given twice (row " + std::to_string(r + 1) + ")");
    g.z.resize(static_cast<Eigen::Index>(g.x.size()), static_cast<Eigen::Index>(g.y.size()));
    for (std::size_t a = 0; a < g.x.size(); ++a)
        for (std::size_t b = 0; b < g.y.size(); ++b)
            g.z(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = height.at({g.x[a], g.y[b]});
    return g;
}

CartesianSurface cartesian_spline_surface(const PointList& xyz) {
    const GridHeights g = grid_from_points(xyz);
    return cartesian_spline_surface(g.x, g.y, g.z);
}

}  // namespace cagd::surface
