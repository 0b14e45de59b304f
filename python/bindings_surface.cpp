// surface/ and smoothing/'s surfaces: Hosaka's tensor patch (eq 27), the edge-curve form and
// Coons' patch (eq 28), the Cartesian patch over a grid (eq 30), and the surface smoothings of
// section 7 (elastic net, plate). Grids in and out as numpy arrays; evaluation broadcasts u and v.
#include "bindings.hpp"

#include "cagd/smoothing/boundary_plate_smoothing.hpp"
#include "cagd/smoothing/elastic_net.hpp"
#include "cagd/smoothing/plate_smoothing.hpp"
#include "cagd/smoothing/window_smoothing.hpp"
#include "cagd/surface/boundary_surface.hpp"
#include "cagd/surface/hosaka_patch.hpp"

namespace cagd_python {

namespace {

// The largest derivative order a patch is asked for from Python: the patches are polynomials of
// degree 2m + 1 ≤ 61 (m ≤ 30) in each variable, so higher orders are exact zeros there.
constexpr int kMaxSurfaceDerivative = 64;

void require_order(int a, int b) {
    if (a < 0 || b < 0 || a > kMaxSurfaceDerivative || b > kMaxSurfaceDerivative)
        throw cagd::InvalidInput("derivative orders (" + std::to_string(a) + ", " + std::to_string(b) +
                                 "); allowed 0.." + std::to_string(kMaxSurfaceDerivative));
}

// f(u, v) → a vector of `dim` values, over u and v broadcast against each other: shape
// broadcast(u, v).shape + (dim,) (dim = 0: a scalar per point, shape broadcast(u, v).shape).
template <class F>
py::array broadcast_surface(const py::object& u_in, const py::object& v_in, const char* u_name, const char* v_name,
                            int dim, F f) {
    const Array u = real_array(u_in, u_name), v = real_array(v_in, v_name);
    const py::module_ np = py::module_::import("numpy");
    const py::tuple both = np.attr("broadcast_arrays")(u, v);
    const Array ub = Array::ensure(both[0]), vb = Array::ensure(both[1]);
    std::vector<py::ssize_t> shape(ub.shape(), ub.shape() + ub.ndim());
    if (dim > 0) shape.push_back(dim);
    py::array_t<double> out(shape);
    double* w = out.mutable_data();
    const py::ssize_t count = ub.size();
    std::vector<double> uf(static_cast<std::size_t>(count)), vf(static_cast<std::size_t>(count));
    {
        // broadcast_arrays gives views with zero strides: read them element by element in C order.
        const py::array uc = np.attr("ascontiguousarray")(ub), vc = np.attr("ascontiguousarray")(vb);
        const double* up = static_cast<const double*>(uc.data());
        const double* vp = static_cast<const double*>(vc.data());
        std::copy(up, up + count, uf.begin());
        std::copy(vp, vp + count, vf.begin());
    }
    {
        py::gil_scoped_release release;
        for (py::ssize_t k = 0; k < count; ++k) {
            const Eigen::VectorXd r = f(uf[static_cast<std::size_t>(k)], vf[static_cast<std::size_t>(k)]);
            for (int d = 0; d < std::max(dim, 1); ++d) w[k * std::max(dim, 1) + d] = r[d];
        }
    }
    return out;
}

// ζ^(a,b)(x, y) of a scalar surface (Cartesian, boundary-conforming, joined) over broadcast x and y.
template <class Surface>
py::array evaluate_scalar(const Surface& s, const py::object& x, const py::object& y, int a, int b) {
    require_order(a, b);
    return broadcast_surface(
        x, y, "x", "y", 0, [&](double p, double q) { return Eigen::VectorXd::Constant(1, s.derivative(p, q, a, b)); });
}

// Corner derivatives from an array of shape (2, 2, m + 1, m + 1, dim): [k, l, i, j] = S_kl^(i,j).
cagd::surface::CornerDerivatives corners_from(const py::object& data) {
    const Array a = real_array(data, "corners");
    if (a.ndim() != 5 || a.shape(0) != 2 || a.shape(1) != 2 || a.shape(2) != a.shape(3) || a.shape(2) < 1 ||
        a.shape(4) < 1)
        throw cagd::InvalidInput(
            "corners: expected shape (2, 2, m + 1, m + 1, dim), got " +
            std::string(py::str(py::tuple(py::cast(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()))))));
    const int m = static_cast<int>(a.shape(2)) - 1, dim = static_cast<int>(a.shape(4));
    if (m > 30) throw cagd::InvalidInput("corners: m = " + std::to_string(m) + "; allowed 0..30 (as hosaka --m)");
    cagd::surface::CornerDerivatives c(m, dim);
    const auto r = a.unchecked<5>();
    for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l)
            for (int i = 0; i <= m; ++i)
                for (int j = 0; j <= m; ++j)
                    for (int d = 0; d < dim; ++d) c.at(k, l, i, j)[d] = r(k, l, i, j, d);
    return c;
}

cagd::smoothing::PlateEnergy plate_energy_named(const std::string& name) {
    if (name == "poisson") return cagd::smoothing::PlateEnergy::poisson;
    if (name == "no_poisson") return cagd::smoothing::PlateEnergy::no_poisson;
    if (name == "no_twist") return cagd::smoothing::PlateEnergy::no_twist;
    if (name == "mean_curvature") return cagd::smoothing::PlateEnergy::mean_curvature;
    throw cagd::InvalidInput("energy = '" + name + "'; allowed poisson | no_poisson | no_twist | mean_curvature");
}

// A boundary line through points (n, 3) with constant cross-boundary derivatives (j = 1..m).
cagd::surface::BoundaryCurve boundary_from(const py::object& points, const py::object& cross, const char* name,
                                           const char* cross_name) {
    const Array c = real_array(cross, cross_name);
    std::vector<double> values;
    if (c.ndim() == 0)
        values.push_back(c.data()[0]);
    else
        values = to_vector(c, cross_name);
    return cagd::surface::boundary_through_points(to_matrix(real_array(points, name), name), values);
}

// The smoothings' data: grid lines x (nx,), y (ny,) and heights a (nx, ny).
struct GridData {
    std::vector<double> x, y;
    Eigen::MatrixXd a;
};
GridData grid_data(const py::object& x, const py::object& y, const py::object& a) {
    return {to_vector(real_array(x, "x"), "x"), to_vector(real_array(y, "y"), "y"), to_matrix(real_array(a, "a"), "a")};
}

// λ for the smoothings: one number, or one per node (nx, ny).
Eigen::MatrixXd lambda_grid(const py::object& lam) {
    const Array a = real_array(lam, "lam");
    if (a.ndim() == 0) return Eigen::MatrixXd::Constant(1, 1, a.data()[0]);
    return to_matrix(a, "lam");
}

}  // namespace

void bind_surface(py::module_& m) {
    py::class_<cagd::surface::HosakaPatch>(m, "TensorPatch",
                                           "Hosaka's tensor patch (hosaka eq 27) over (u, v) ∈ [0, 1]²: it "
                                           "interpolates every corner derivative S_kl^(i,j), i, j ≤ m. "
                                           "Made by tensor_patch (its example).")
        .def_property_readonly("m", &cagd::surface::HosakaPatch::m,
                               "the order m: corner derivatives up to (m, m), degree 2m + 1")
        .def(
            "evaluate",
            [](const cagd::surface::HosakaPatch& p, const py::object& u, const py::object& v, int a, int b) {
                require_order(a, b);
                return broadcast_surface(u, v, "u", "v", p.corners().dimension(),
                                         [&](double x, double y) { return p.derivative(x, y, a, b); });
            },
            py::arg("u"), py::arg("v"), py::arg("a") = 0, py::arg("b") = 0,
            "S^(a,b)(u, v) = ∂^(a+b) S / ∂u^a ∂v^b; u and v broadcast (numpy rules), result shape broadcast.shape + "
            "(dim,). ValueError outside [0, 1]².");
    m.def(
        "tensor_patch", [](const py::object& corners) { return cagd::surface::HosakaPatch(corners_from(corners)); },
        py::arg("corners"),
        "Hosaka's tensor patch of order m (hosaka eq 27) from its corner derivatives: corners[k, l, i, j] = S_kl^(i,j) "
        "= ∂^(i+j) S / ∂u^i ∂v^j at (u, v) "
        "= (k, l), an array of shape (2, 2, m + 1, m + 1, dim), 0 ≤ m ≤ 30.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> c = np.zeros((2, 2, 2, 2, 3))\n"
        ">>> for k in (0, 1):\n"
        "...     for l in (0, 1):\n"
        "...         c[k, l, 0, 0] = [k, l, k * l]\n"
        ">>> p = cagd.tensor_patch(c)\n"
        ">>> p.evaluate(1.0, 1.0)\n"
        "array([1., 1., 1.])\n"
        ">>> p.evaluate(np.linspace(0, 1, 3), 0.5).shape\n"
        "(3, 3)\n");

    py::class_<cagd::surface::EdgeFormPatch>(m, "EdgePatch",
                                             "A patch through four edge curves (hosaka eq 28): Coons' surface when it "
                                             "has no corner correction S0. Made by coons_patch (its example).")
        .def_property_readonly("m", &cagd::surface::EdgeFormPatch::m, "the order m of the blending f = q_0(m, ·)")
        .def(
            "evaluate",
            [](const cagd::surface::EdgeFormPatch& p, const py::object& u, const py::object& v, int a, int b) {
                require_order(a, b);
                const int dim = static_cast<int>(p.point(0.0, 0.0).size());
                return broadcast_surface(u, v, "u", "v", dim,
                                         [&](double x, double y) { return p.derivative(x, y, a, b); });
            },
            py::arg("u"), py::arg("v"), py::arg("a") = 0, py::arg("b") = 0,
            "S^(a,b)(u, v); u and v broadcast, result shape broadcast.shape + (dim,).");
    m.def(
        "coons_patch",
        [](const py::object& bottom, const py::object& left, const py::object& top, const py::object& right,
           int order) {
            const cagd::surface::PatchEdges edges = cagd::surface::edges_through_points(
                to_matrix(real_array(bottom, "bottom"), "bottom"), to_matrix(real_array(left, "left"), "left"),
                to_matrix(real_array(top, "top"), "top"), to_matrix(real_array(right, "right"), "right"));
            if (order < 1 || order > 30) throw cagd::InvalidInput("m = " + std::to_string(order) + "; allowed 1..30");
            return cagd::surface::EdgeFormPatch(order, edges);
        },
        py::arg("bottom"), py::arg("left"), py::arg("top"), py::arg("right"), py::arg("m") = 1,
        "Coons' patch (hosaka eq 28 with S0 = 0) through four edges, each the C2 spline of eq (20) through its points "
        "(n_i, 2) or (n_i, 3): "
        "bottom = S(u, 0), left = S(0, v), top = S(u, 1), right = S(1, v); the corners must coincide. Blending 1 − f, "
        "f with f = q_0(m, ·).\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> s = np.linspace(0, 1, 4)\n"
        ">>> p = cagd.coons_patch(np.column_stack([s, 0 * s, 0 * s]), np.column_stack([0 * s, s, s * s]),\n"
        "...                      np.column_stack([s, 1 + 0 * s, 1 + 0 * s]), np.column_stack([1 + 0 * s, s, s * s]))\n"
        ">>> bool(np.allclose(p.evaluate(s, 1.0), np.column_stack([s, 1 + 0 * s, 1 + 0 * s])))\n"
        "True\n");

    py::class_<cagd::surface::BoundaryConformingSurface>(
        m, "BoundaryConformingSurface",
        "ζ(x, y) between a lower and an upper boundary line (hosaka eq 31–38): every section x = const is a Hermite "
        "curve meeting both boundaries "
        "with the prescribed cross-boundary derivatives. Made by boundary_surface (its example).")
        .def_property_readonly("m", &cagd::surface::BoundaryConformingSurface::m,
                               "the order m of the sections' Hermite curves")
        .def_property_readonly(
            "x_range",
            [](const cagd::surface::BoundaryConformingSurface& s) { return py::make_tuple(s.x_min(), s.x_max()); },
            "(x_min, x_max) of the boundaries")
        .def(
            "y_range",
            [](const cagd::surface::BoundaryConformingSurface& s, double x) {
                return py::make_tuple(s.y_lower(x), s.y_upper(x));
            },
            py::arg("x"), "(y_0(x), y_1(x)): the lower and upper boundary at x")
        .def("evaluate", &evaluate_scalar<cagd::surface::BoundaryConformingSurface>, py::arg("x"), py::arg("y"),
             py::arg("a") = 0, py::arg("b") = 0,
             "ζ^(a,b)(x, y) (eq 38); x and y broadcast. ValueError for a point outside the strip between the "
             "boundaries.")
        .def(
            "join",
            [](const cagd::surface::BoundaryConformingSurface& s, double x0, const py::object& far,
               const py::object& cross) {
                return cagd::surface::SectionJoinedSurface(s, x0, boundary_from(far, cross, "far", "cross"));
            },
            py::arg("x0"), py::arg("far"), py::arg("cross") = 0.0,
            "The surface joined across the section x = x0 (hosaka eq 41–43) out to a far boundary x = x3(y), z = "
            "z3(y): far holds rows (y, x3, z3) over "
            "the section's y range, cross the x-derivatives ζ^(i,0) along it (i = 1..m, constants). It shares ζ^(i,n), "
            "i ≤ m, with this surface on x = x0.");
    py::class_<cagd::surface::SectionJoinedSurface>(
        m, "JoinedSurface",
        "The surface beyond a section (hosaka eq 41–43). Made by BoundaryConformingSurface.join (its example).")
        .def_property_readonly("x0", &cagd::surface::SectionJoinedSurface::x0, "the section's x")
        .def_property_readonly(
            "y_range",
            [](const cagd::surface::SectionJoinedSurface& s) { return py::make_tuple(s.y_min(), s.y_max()); },
            "(y_min, y_max) of the section")
        .def("evaluate", &evaluate_scalar<cagd::surface::SectionJoinedSurface>, py::arg("x"), py::arg("y"),
             py::arg("a") = 0, py::arg("b") = 0,
             "ζ^(a,b)(x, y) between the section and the far boundary; x and y broadcast.");
    m.def(
        "boundary_surface",
        [](const py::object& lower, const py::object& upper, const py::object& lower_cross,
           const py::object& upper_cross, int order) {
            if (order < 0 || order > 30) throw cagd::InvalidInput("m = " + std::to_string(order) + "; allowed 0..30");
            cagd::surface::BoundaryCurve lo = boundary_from(lower, lower_cross, "lower", "lower_cross"),
                                         up = boundary_from(upper, upper_cross, "upper", "upper_cross");
            return cagd::surface::BoundaryConformingSurface(order, std::move(lo), std::move(up));
        },
        py::arg("lower"), py::arg("upper"), py::arg("lower_cross") = 0.0, py::arg("upper_cross") = 0.0,
        py::arg("m") = 1,
        "Hosaka's boundary-conforming surface (hosaka eq 31–38) between two boundary lines through points (n, 3), x "
        "strictly increasing over the same "
        "x range: y_k(x), z_k(x) the explicit splines of eq (21)–(23), the cross-boundary derivatives ζ^(0,j), j = "
        "1..m, constants (one number or m).\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> x = np.linspace(0.0, 2.0, 5)\n"
        ">>> s = cagd.boundary_surface(np.column_stack([x, 0 * x, 0 * x]), np.column_stack([x, 1 + x, 0 * x + 1]))\n"
        ">>> float(s.evaluate(1.0, 2.0)), s.y_range(1.0)  # on the upper boundary\n"
        "(1.0, (0.0, 2.0))\n"
        ">>> j = s.join(2.0, np.column_stack([np.linspace(0.0, 3.0, 4), 3.0 + 0 * np.linspace(0.0, 3.0, 4), "
        "np.linspace(0.0, 1.0, 4)]))\n"
        ">>> round(float(j.evaluate(2.0, 1.5)), 12) == round(float(s.evaluate(2.0, 1.5)), 12)  # they meet on the "
        "section\n"
        "True\n");

    py::class_<cagd::surface::CartesianSurface>(
        m, "CartesianSurface",
        "ζ(x, y) over a rectangular grid (hosaka eq 30): Hosaka's patch of order m on every cell, C^m across grid "
        "lines. "
        "Made by cartesian_surface, elastic_net_surface and plate_smoothing (their examples).")
        .def_property_readonly("m", &cagd::surface::CartesianSurface::m, "the order m of every cell's patch")
        .def_property_readonly(
            "x", [](const cagd::surface::CartesianSurface& s) { return from_vector(s.x()); }, "the grid's x lines")
        .def_property_readonly(
            "y", [](const cagd::surface::CartesianSurface& s) { return from_vector(s.y()); }, "the grid's y lines")
        .def("evaluate", &evaluate_scalar<cagd::surface::CartesianSurface>, py::arg("x"), py::arg("y"),
             py::arg("a") = 0, py::arg("b") = 0,
             "ζ^(a,b)(x, y) = ∂^(a+b) ζ / ∂x^a ∂y^b; x and y broadcast, result of their broadcast shape (a float "
             "array). ValueError outside the grid.")
        .def(
            "node", [](const cagd::surface::CartesianSurface& s, int a, int b) { return from_matrix(s.node(a, b)); },
            py::arg("a"), py::arg("b"), "The node derivatives at (x_a, y_b): entry (i, j) = ζ^(i,j).");
    m.def(
        "cartesian_surface",
        [](const py::object& x, const py::object& y, const py::object& z) {
            return cagd::surface::cartesian_spline_surface(to_vector(real_array(x, "x"), "x"),
                                                           to_vector(real_array(y, "y"), "y"),
                                                           to_matrix(real_array(z, "z"), "z"));
        },
        py::arg("x"), py::arg("y"), py::arg("z"),
        "The m = 1 Cartesian surface through heights z[a, b] = ζ(x[a], y[b]) (hosaka eq 30, section 7 (iv)): node "
        "slopes and twists from natural splines "
        "(eq 23) along the grid lines, i.e. de Boor's bicubic spline. x (nx,), y (ny,) strictly increasing; z (nx, "
        "ny).\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> x, y = np.arange(4.0), np.arange(3.0)\n"
        ">>> s = cagd.cartesian_surface(x, y, np.add.outer(x, 2 * y))\n"
        ">>> float(s.evaluate(1.5, 0.25)), float(s.evaluate(1.5, 0.25, a=1))\n"
        "(2.0, 1.0)\n");
    m.def(
        "elastic_net_surface",
        [](const py::object& x, const py::object& y, const py::object& a, const py::object& lam) {
            const GridData g = grid_data(x, y, a);
            const Eigen::MatrixXd lambda = lambda_grid(lam);
            py::gil_scoped_release release;
            return cagd::smoothing::net_spline_smoothing(g.x, g.y, g.a, lambda);
        },
        py::arg("x"), py::arg("y"), py::arg("a"), py::arg("lam"),
        "Hosaka's elastic net (hosaka eq 53–54, approximation 2 of section 7 (iv)): heights a (nx, ny) on the grid x "
        "(nx,), y (ny,) smoothed with "
        "λ ≥ 0 (one number or (nx, ny); 0 interpolates), then the Cartesian surface through the net. Returns a "
        "CartesianSurface.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> x = y = np.arange(5.0)\n"
        ">>> s = cagd.elastic_net_surface(x, y, np.add.outer(x, y), 0.0)\n"
        ">>> round(float(s.evaluate(2.0, 3.0)), 12)\n"
        "5.0\n");
    py::class_<cagd::smoothing::BoundaryPlateSurface>(
        m, "BoundaryPlateSurface",
        "Hosaka's plate smoothing, method (ii): one surface of eq (31) between the grid's first and last y lines. "
        "Made by boundary_plate_smoothing (its example).")
        .def_property_readonly("m", &cagd::smoothing::BoundaryPlateSurface::m, "the order m of the cross-boundary data")
        .def("evaluate", &evaluate_scalar<cagd::smoothing::BoundaryPlateSurface>, py::arg("x"), py::arg("y"),
             py::arg("a") = 0, py::arg("b") = 0,
             "ζ^(a,b)(x, y), a ≤ 2 (its data are cubic splines in x); x and y broadcast.");
    m.def(
        "boundary_plate_smoothing",
        [](const py::object& x, const py::object& y, const py::object& a, const py::object& lam,
           const std::string& energy, int order, double poisson_ratio) {
            const GridData g = grid_data(x, y, a);
            const Eigen::MatrixXd lambda = lambda_grid(lam);
            const cagd::smoothing::PlateEnergy e = plate_energy_named(energy);
            if (order < 1 || order > 30) throw cagd::InvalidInput("m = " + std::to_string(order) + "; allowed 1..30");
            py::gil_scoped_release release;
            return cagd::smoothing::boundary_plate_smoothing(g.x, g.y, g.a, lambda, e, order, poisson_ratio).surface;
        },
        py::arg("x"), py::arg("y"), py::arg("a"), py::arg("lam"), py::arg("energy") = "poisson", py::arg("m") = 2,
        py::arg("poisson_ratio") = 0.3,
        "Hosaka's plate smoothing, method (ii) (section 7 (ii), eq 31 with 55–59): the surface of eq (31) between the "
        "first and last y lines whose "
        "cross-boundary derivatives (natural splines in x) minimise the plate energy plus Σ (ζ − a)² / λ. a (nx, ny), "
        "λ > 0 one number or (nx, ny).\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> x = y = np.arange(5.0)\n"
        ">>> s = cagd.boundary_plate_smoothing(x, y, np.add.outer(x, y), 1.0)  # a plane has no plate energy\n"
        ">>> round(float(s.evaluate(1.5, 2.5)), 9)\n"
        "4.0\n");
    m.def(
        "window_smoothing",
        [](const py::object& x, const py::object& y, const py::object& a, double lam, const std::string& energy,
           double poisson_ratio) {
            const GridData g = grid_data(x, y, a);
            const cagd::smoothing::PlateEnergy e = plate_energy_named(energy);
            py::gil_scoped_release release;
            return cagd::smoothing::local_orthogonal_smoothing(g.x, g.y, g.a, lam, e, poisson_ratio);
        },
        py::arg("x"), py::arg("y"), py::arg("a"), py::arg("lam"), py::arg("energy") = "poisson",
        py::arg("poisson_ratio") = 0.3,
        "Hosaka's approximation 1 (section 7 (iv), eq 60): a 5 × 5 window fit by discrete orthonormal polynomials at "
        "every node, its derivatives "
        "into the Cartesian surface of eq (30). Equally spaced x (nx,) and y (ny,) with at least 5 lines each; a (nx, "
        "ny); one λ ≥ 0.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> x = y = np.arange(6.0)\n"
        ">>> s = cagd.window_smoothing(x, y, np.add.outer(x, y), 0.5)  # a plane is kept\n"
        ">>> round(float(s.evaluate(2.5, 1.5)), 9)\n"
        "4.0\n");
    m.def(
        "plate_smoothing",
        [](const py::object& x, const py::object& y, const py::object& a, const py::object& lam,
           const std::string& energy, double poisson_ratio) {
            const GridData g = grid_data(x, y, a);
            const Eigen::MatrixXd lambda = lambda_grid(lam);
            const cagd::smoothing::PlateEnergy e = plate_energy_named(energy);
            py::gil_scoped_release release;
            return cagd::smoothing::plate_smoothing(g.x, g.y, g.a, lambda, e, poisson_ratio).surface;
        },
        py::arg("x"), py::arg("y"), py::arg("a"), py::arg("lam"), py::arg("energy") = "poisson",
        py::arg("poisson_ratio") = 0.3,
        "Hosaka's plate smoothing, method (i) of section 7 (eq 55–58): the bicubic Cartesian surface over the grid "
        "minimising the plate energy "
        "(poisson, no_poisson, no_twist or mean_curvature) plus Σ (ζ − a)² / λ. a (nx, ny), λ > 0 one number or (nx, "
        "ny). Returns a CartesianSurface.\n\n"
        ">>> import numpy as np, cagd\n"
        ">>> x = y = np.arange(4.0)\n"
        ">>> s = cagd.plate_smoothing(x, y, np.add.outer(x, y), 1.0)  # a plane has no plate energy\n"
        ">>> round(float(s.evaluate(1.5, 2.5)), 9)\n"
        "4.0\n");
}

}  // namespace cagd_python
