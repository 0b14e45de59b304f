#include "cagd/export/surface_form.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "cagd/core/bernstein_polynomial.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/spline/bezier.hpp"

namespace cagd::exports {

namespace {

// The points inside a cell at which a form is measured: 7 per direction, none a Chebyshev point of
// low degree, a corner or a midpoint.
constexpr int kMeasuredPerDirection = 7;
double measured_local(int k) { return (k + 0.37) / kMeasuredPerDirection; }

constexpr double kExactRelative = 1e-12;

// S at local (s, t) ∈ [0, 1]² of one net, by the Bernstein basis values.
Eigen::Vector3d net_point(const surface::ControlNet& net, double s, double t) {
    const int p = static_cast<int>(net[0].rows()) - 1, q = static_cast<int>(net[0].cols()) - 1;
    const std::vector<double> bu = bernstein_basis_values(p, s), bv = bernstein_basis_values(q, t);
    const Eigen::Map<const Eigen::VectorXd> u(bu.data(), p + 1), v(bv.data(), q + 1);
    return {u.dot(net[0] * v), u.dot(net[1] * v), u.dot(net[2] * v)};
}

// Index of the cell holding x among breaks (the lower cell on a break, the last at the end).
int cell_of(const std::vector<double>& breaks, double x) {
    const auto it = std::upper_bound(breaks.begin(), breaks.end(), x);
    const int i = static_cast<int>(it - breaks.begin()) - 1;
    return std::clamp(i, 0, static_cast<int>(breaks.size()) - 2);
}

// The net of degree d × d from the jets ∂^{i+j} S/∂u^i ∂v^j, i, j ≤ ⌊d/2⌋ (d odd), at the corners
// (k, l) of a cell of sides hu × hv: jet(k, l, i, j) as a 3-vector. See the header.
surface::ControlNet net_from_corner_jets(int d, double hu, double hv,
                                         const std::function<Eigen::Vector3d(int k, int l, int i, int j)>& jet) {
    const int m = d / 2;
    // rows[l][j]: the Bézier points in u of ∂^j S/∂v^j (·, l).
    std::vector<Eigen::MatrixXd> rows[2];
    for (int l = 0; l < 2; ++l)
        for (int j = 0; j <= m; ++j) {
            Eigen::MatrixXd J0(m + 1, 3), J1(m + 1, 3);
            for (int i = 0; i <= m; ++i) {
                J0.row(i) = jet(0, l, i, j).transpose();
                J1.row(i) = jet(1, l, i, j).transpose();
            }
            rows[l].push_back(bezier_from_end_jets(d, hu, J0, J1));
        }
    surface::ControlNet net;
    for (auto& c : net) c.resize(d + 1, d + 1);
    for (int a = 0; a <= d; ++a) {
        Eigen::MatrixXd K0(m + 1, 3), K1(m + 1, 3);
        for (int j = 0; j <= m; ++j) {
            K0.row(j) = rows[0][static_cast<std::size_t>(j)].row(a);
            K1.row(j) = rows[1][static_cast<std::size_t>(j)].row(a);
        }
        const Eigen::MatrixXd column = bezier_from_end_jets(d, hv, K0, K1);
        for (int b = 0; b <= d; ++b)
            for (int c = 0; c < 3; ++c) net[static_cast<std::size_t>(c)](a, b) = column(b, c);
    }
    return net;
}

Eigen::Vector3d as_point3(const Eigen::VectorXd& v, const char* who) {
    if (v.size() == 3) return v;
    if (v.size() == 2) return {v(0), v(1), 0.0};
    fail_input(who, "a surface of " + std::to_string(v.size()) + " coordinates; 2 or 3 are written");
}

// Measures the pieces against `surface(a, b, s, t)` (cell (a, b), local (s, t)) and says whether
// the form is exact.
SurfaceForm measured(BezierSurfacePieces pieces,
                     const std::function<Eigen::Vector3d(int a, int b, double s, double t)>& surface) {
    SurfaceForm f;
    for (int b = 0; b < pieces.cells_v(); ++b)
        for (int a = 0; a < pieces.cells_u(); ++a)
            for (int i = 0; i < kMeasuredPerDirection; ++i)
                for (int j = 0; j < kMeasuredPerDirection; ++j) {
                    const double s = measured_local(i), t = measured_local(j);
                    f.conversion_error =
                        std::max(f.conversion_error, (net_point(pieces.net(a, b), s, t) - surface(a, b, s, t)).norm());
                }
    f.exact = f.conversion_error <= kExactRelative * std::max(net_diagonal(pieces), 1e-300);
    f.pieces = std::move(pieces);
    return f;
}

// The Chebyshev points of degree d on [0, 1] and the Bernstein collocation matrix N(k, i) = B_i^d(t_k).
Eigen::MatrixXd chebyshev_collocation(int d, std::vector<double>& nodes) {
    nodes.clear();
    Eigen::MatrixXd n(d + 1, d + 1);
    for (int k = 0; k <= d; ++k) {
        nodes.push_back(0.5 * (1.0 - std::cos(std::numbers::pi * (2 * k + 1) / (2.0 * (d + 1)))));
        const std::vector<double> b = bernstein_basis_values(d, nodes.back());
        for (int i = 0; i <= d; ++i) n(k, i) = b[static_cast<std::size_t>(i)];
    }
    return n;
}

// The breaks of an edge mapped onto [0, 1] (as EdgeFormPatch maps the edge), merged into `into`.
void merge_edge_breaks(const Curve& edge, std::vector<double>& into) {
    const double a = edge.t_min(), span = edge.t_max() - a;
    for (const double t : edge.breakpoints()) into.push_back(std::clamp((t - a) / span, 0.0, 1.0));
    std::sort(into.begin(), into.end());
    std::vector<double> merged;
    for (const double x : into)
        if (merged.empty() || x - merged.back() > 1e-12) merged.push_back(x);
    merged.front() = 0.0;
    merged.back() = 1.0;
    into = merged;
}

}  // namespace

Eigen::Vector3d BezierSurfacePieces::point(double u, double v) const {
    const int a = cell_of(u_breaks, u), b = cell_of(v_breaks, v);
    const double s = (u - u_breaks[static_cast<std::size_t>(a)]) /
                     (u_breaks[static_cast<std::size_t>(a) + 1] - u_breaks[static_cast<std::size_t>(a)]);
    const double t = (v - v_breaks[static_cast<std::size_t>(b)]) /
                     (v_breaks[static_cast<std::size_t>(b) + 1] - v_breaks[static_cast<std::size_t>(b)]);
    return net_point(net(a, b), s, t);
}

double net_diagonal(const BezierSurfacePieces& pieces) {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
    for (const surface::ControlNet& net : pieces.nets)
        for (int c = 0; c < 3; ++c) {
            lo(c) = std::min(lo(c), net[static_cast<std::size_t>(c)].minCoeff());
            hi(c) = std::max(hi(c), net[static_cast<std::size_t>(c)].maxCoeff());
        }
    return pieces.nets.empty() ? 0.0 : (hi - lo).norm();
}

namespace {
// Refuses patches of more than kMaxSurfaceControlPoints control points, before any is built.
void require_size(const char* who, std::size_t u_breaks, std::size_t v_breaks, int du, int dv) {
    const double points = static_cast<double>(u_breaks - 1) * static_cast<double>(v_breaks - 1) * (du + 1) * (dv + 1);
    if (points > static_cast<double>(kMaxSurfaceControlPoints))
        fail_input(who, "the surface's " + std::to_string(u_breaks - 1) + " x " + std::to_string(v_breaks - 1) +
                            " patches of degree " + std::to_string(du) + " x " + std::to_string(dv) + " would hold " +
                            full_precision(points) + " control points, more than " +
                            std::to_string(kMaxSurfaceControlPoints) + ": give fewer points");
}

}  // namespace

SurfaceForm to_bezier(const surface::BezierPatch& patch) {
    BezierSurfacePieces p;
    p.degree_u = patch.degree_u();
    p.degree_v = patch.degree_v();
    p.u_breaks = {0.0, 1.0};
    p.v_breaks = {0.0, 1.0};
    p.nets = {patch.net()};
    // The patch's own net, copied: no conversion, nothing to measure (measuring compared two de
    // Casteljau evaluations of this very net, O(n³) each: minutes at n = 1000).
    SurfaceForm f;
    f.pieces = std::move(p);
    f.exact = true;
    return f;
}

SurfaceForm to_bezier(const surface::HosakaPatch& patch) {
    const char* who = "cagd::exports::to_bezier(HosakaPatch)";
    const surface::CornerDerivatives& c = patch.corners();
    as_point3(c.at(0, 0, 0, 0), who);
    const int d = 2 * patch.m() + 1;
    BezierSurfacePieces p;
    p.degree_u = p.degree_v = d;
    p.u_breaks = p.v_breaks = {0.0, 1.0};
    p.nets = {net_from_corner_jets(d, 1.0, 1.0,
                                   [&](int k, int l, int i, int j) { return as_point3(c.at(k, l, i, j), who); })};
    return measured(std::move(p), [&](int, int, double s, double t) { return as_point3(patch.point(s, t), who); });
}

SurfaceForm to_bezier(const surface::CartesianSurface& surface) {
    const int d = 2 * surface.m() + 1;
    const std::vector<double>&x = surface.x(), &y = surface.y();
    require_size("cagd::exports::to_bezier", x.size(), y.size(), d, d);
    BezierSurfacePieces p;
    p.degree_u = p.degree_v = d;
    p.u_breaks = x;
    p.v_breaks = y;
    for (std::size_t b = 0; b + 1 < y.size(); ++b)
        for (std::size_t a = 0; a + 1 < x.size(); ++a) {
            const double lx = x[a + 1] - x[a], ly = y[b + 1] - y[b];
            surface::ControlNet net = net_from_corner_jets(d, lx, ly, [&](int k, int l, int i, int j) {
                const double z = surface.node(static_cast<int>(a) + k, static_cast<int>(b) + l)(i, j);
                // x and y as polynomials of the cell: x = x_a + lx ū has jets (x_a + k lx, lx, 0, …).
                const double xv = i == 0 && j == 0 ? x[a] + k * lx : (i == 1 && j == 0 ? 1.0 : 0.0);
                const double yv = i == 0 && j == 0 ? y[b] + l * ly : (i == 0 && j == 1 ? 1.0 : 0.0);
                return Eigen::Vector3d(xv, yv, z);
            });
            p.nets.push_back(std::move(net));
        }
    return measured(std::move(p), [&](int a, int b, double s, double t) {
        const double xv =
            x[static_cast<std::size_t>(a)] + s * (x[static_cast<std::size_t>(a) + 1] - x[static_cast<std::size_t>(a)]);
        const double yv =
            y[static_cast<std::size_t>(b)] + t * (y[static_cast<std::size_t>(b) + 1] - y[static_cast<std::size_t>(b)]);
        return Eigen::Vector3d(xv, yv, surface.derivative_in(a, b, s, t, 0, 0));
    });
}

SurfaceForm to_bezier(const surface::EdgeFormPatch& patch) {
    const char* who = "cagd::exports::to_bezier(EdgeFormPatch)";
    const surface::PatchEdges& e = patch.edges();
    const std::pair<const Curve*, const char*> named[] = {
        {e.r1.get(), "R1 (v = 0)"}, {e.r2.get(), "R2 (u = 0)"}, {e.r3.get(), "R3 (v = 1)"}, {e.r4.get(), "R4 (u = 1)"}};
    int du = 2 * patch.m() + 1, dv = du;
    for (int k = 0; k < 4; ++k) {
        const int deg = named[k].first->polynomial_degree();
        if (deg < 0)
            fail_input(who, std::string("edge ") + named[k].second +
                                " is not a polynomial curve: the patch has no exact Bezier form");
        (k % 2 == 0 ? du : dv) = std::max(k % 2 == 0 ? du : dv, deg);
    }
    BezierSurfacePieces p;
    p.degree_u = du;
    p.degree_v = dv;
    merge_edge_breaks(*e.r1, p.u_breaks);
    merge_edge_breaks(*e.r3, p.u_breaks);
    merge_edge_breaks(*e.r2, p.v_breaks);
    merge_edge_breaks(*e.r4, p.v_breaks);
    require_size("cagd::exports::to_bezier", p.u_breaks.size(), p.v_breaks.size(), du, dv);
    std::vector<double> su, sv;
    const Eigen::PartialPivLU<Eigen::MatrixXd> nu(chebyshev_collocation(du, su)), nv(chebyshev_collocation(dv, sv));
    // The breaks by value: `p` moves into measured() before this is called there.
    const auto global = [&patch, who, ub = p.u_breaks, vb = p.v_breaks](int a, int b, double s, double t) {
        const double u = ub[static_cast<std::size_t>(a)] +
                         s * (ub[static_cast<std::size_t>(a) + 1] - ub[static_cast<std::size_t>(a)]);
        const double v = vb[static_cast<std::size_t>(b)] +
                         t * (vb[static_cast<std::size_t>(b) + 1] - vb[static_cast<std::size_t>(b)]);
        return as_point3(patch.point(u, v), who);
    };
    for (int b = 0; b < p.cells_v(); ++b)
        for (int a = 0; a < p.cells_u(); ++a) {
            surface::ControlNet values;
            for (auto& c : values) c.resize(du + 1, dv + 1);
            for (int i = 0; i <= du; ++i)
                for (int j = 0; j <= dv; ++j) {
                    const Eigen::Vector3d s =
                        global(a, b, su[static_cast<std::size_t>(i)], sv[static_cast<std::size_t>(j)]);
                    for (int c = 0; c < 3; ++c) values[static_cast<std::size_t>(c)](i, j) = s(c);
                }
            surface::ControlNet net;
            // N_u P N_vᵀ = V: P = N_u⁻¹ V N_v⁻ᵀ.
            for (int c = 0; c < 3; ++c) {
                const Eigen::MatrixXd left = nu.solve(values[static_cast<std::size_t>(c)]);
                net[static_cast<std::size_t>(c)] = nv.solve(left.transpose()).transpose();
            }
            p.nets.push_back(std::move(net));
        }
    return measured(std::move(p), global);
}

BSplineSurface bspline_surface(const BezierSurfacePieces& pieces, double* mismatch) {
    const char* who = "cagd::exports::bspline_surface";
    if (pieces.cells_u() < 1 || pieces.cells_v() < 1 ||
        pieces.nets.size() != static_cast<std::size_t>(pieces.cells_u() * pieces.cells_v()))
        fail_input(who, "the pieces need at least one cell and one net per cell");
    const int p = pieces.degree_u, q = pieces.degree_v, K = pieces.cells_u(), L = pieces.cells_v();
    BSplineSurface s;
    s.degree_u = p;
    s.degree_v = q;
    const auto clamped = [](const std::vector<double>& breaks, int degree) {
        std::vector<double> k(static_cast<std::size_t>(degree) + 1, breaks.front());
        for (std::size_t i = 1; i + 1 < breaks.size(); ++i)
            k.insert(k.end(), static_cast<std::size_t>(degree), breaks[i]);
        k.insert(k.end(), static_cast<std::size_t>(degree) + 1, breaks.back());
        return k;
    };
    s.knots_u = clamped(pieces.u_breaks, p);
    s.knots_v = clamped(pieces.v_breaks, q);
    for (auto& c : s.control) c.resize(K * p + 1, L * q + 1);
    double worst = 0.0;
    for (int b = 0; b < L; ++b)
        for (int a = 0; a < K; ++a) {
            const surface::ControlNet& net = pieces.net(a, b);
            for (int i = 0; i <= p; ++i)
                for (int j = 0; j <= q; ++j) {
                    const int r = a * p + i, c = b * q + j;
                    const bool shared = (i == 0 && a > 0) || (j == 0 && b > 0);
                    Eigen::Vector3d here(net[0](i, j), net[1](i, j), net[2](i, j));
                    if (shared) {
                        const Eigen::Vector3d there(s.control[0](r, c), s.control[1](r, c), s.control[2](r, c));
                        worst = std::max(worst, (here - there).norm());
                        continue;
                    }
                    for (int k = 0; k < 3; ++k) s.control[static_cast<std::size_t>(k)](r, c) = here(k);
                }
        }
    if (mismatch) *mismatch = worst;
    return s;
}

}  // namespace cagd::exports
