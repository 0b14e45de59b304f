// `cagd surface --kind tensor|coons|boundary … --out GRID.csv`: the hosaka section 4 surfaces that
// take simple inputs, sampled on a (samples+1)² grid; tensor and coons also leave exactly as Bezier
// patches (--out S.json) or one B-spline surface (--out S.step), export/surface_form.hpp.
#include <memory>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/export/curve_formats.hpp"
#include "cagd/export/surface_form.hpp"
#include "cagd/surface/boundary_surface.hpp"
#include "cagd/surface/hosaka_patch.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

enum class SurfaceKind { tensor, coons, boundary };

struct SurfaceArgs {
    SurfaceKind kind = SurfaceKind::tensor;
    std::string in, bottom, left, top, right, lower, upper, out, format;
    int m = 1, samples = 20;
    double lower_slope = 0, upper_slope = 0, lower_curvature = 0, upper_curvature = 0;
};

void require(const std::string& value, const char* kind, const char* option) {
    if (value.empty()) fail_input("cagd surface", std::string("--kind ") + kind + " needs " + option);
}

// The exact patches of a polynomial surface in json or step (exports::write_surface refuses a form
// that is not exact: a numerical outcome, nothing written).
void write_patches(const exports::SurfaceForm& form, exports::CurveFormat format,
                   const exports::SurfaceProvenance& provenance, OutputFile& out) {
    if (const Outcome written = exports::write_surface(out.stream(), format, form, provenance); !written.ok())
        throw NoResult(written.message);
}

// eq (30), m = 1, node derivatives from splines along the grid lines.
void write_tensor(const SurfaceArgs& a, exports::CurveFormat format, OutputFile& out) {
    require(a.in, "tensor", "--in");
    const int n = a.samples;
    const surface::CartesianSurface s = surface::cartesian_spline_surface(read_data_points(a.in));
    if (format != exports::CurveFormat::csv)
        return write_patches(exports::to_bezier(s), format, {"hosaka-cartesian", {{"m", "1"}, {"in", a.in}}}, out);
    CsvOutput w(out, {"x", "y", "z", "zx", "zy"});
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            // The last line exactly on the grid's edge (rounding may carry front + span past it).
            const double x = i == n ? s.x().back() : s.x().front() + (s.x().back() - s.x().front()) * i / n;
            const double y = j == n ? s.y().back() : s.y().front() + (s.y().back() - s.y().front()) * j / n;
            w.row({x, y, s.value(x, y), s.derivative(x, y, 1, 0), s.derivative(x, y, 0, 1)}, 15);
        }
}

// eq (28) with S0 = 0.
void write_coons(const SurfaceArgs& a, exports::CurveFormat format, OutputFile& out) {
    for (const auto& [v, o] :
         {std::pair{a.bottom, "--bottom"}, {a.left, "--left"}, {a.top, "--top"}, {a.right, "--right"}})
        require(v, "coons", o);
    const int n = a.samples;
    const surface::EdgeFormPatch s(
        1, surface::edges_through_points(read_data_points(a.bottom), read_data_points(a.left), read_data_points(a.top),
                                         read_data_points(a.right)));
    if (format != exports::CurveFormat::csv)
        return write_patches(
            exports::to_bezier(s), format,
            {"hosaka-coons", {{"m", "1"}, {"bottom", a.bottom}, {"left", a.left}, {"top", a.top}, {"right", a.right}}},
            out);
    const Eigen::VectorXd probe = s.point(0, 0);
    std::vector<std::string> header{"u", "v", "x", "y"};
    if (probe.size() == 3) header.push_back("z");
    CsvOutput w(out, header);
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const Eigen::VectorXd p = s.point(double(i) / n, double(j) / n);
            std::vector<double> row{double(i) / n, double(j) / n};
            for (Eigen::Index k = 0; k < p.size(); ++k) row.push_back(p(k));
            w.row(row, 15);
        }
}

// eq (31) between two boundary curves.
void write_boundary(const SurfaceArgs& a, exports::CurveFormat format, OutputFile& out) {
    if (format != exports::CurveFormat::csv)
        fail_input("cagd surface",
                   "--kind boundary: the surface between two boundary curves is not polynomial (eq 31 over y between "
                   "y_0(x) and y_1(x)); it leaves as a csv grid only");
    require(a.lower, "boundary", "--lower");
    require(a.upper, "boundary", "--upper");
    const int n = a.samples;
    std::vector<double> lower_d{a.lower_slope}, upper_d{a.upper_slope};
    if (a.m == 2) {
        lower_d.push_back(a.lower_curvature);
        upper_d.push_back(a.upper_curvature);
    }
    const surface::BoundaryConformingSurface s(a.m,
                                               surface::boundary_through_points(read_data_points(a.lower), lower_d),
                                               surface::boundary_through_points(read_data_points(a.upper), upper_d));
    CsvOutput w(out, {"x", "y", "z"});
    for (int i = 0; i <= n; ++i) {
        const double x = std::min(s.x_min() + (s.x_max() - s.x_min()) * i / n, s.x_max());
        for (int j = 0; j <= n; ++j) {
            const double y = s.y_lower(x) + (s.y_upper(x) - s.y_lower(x)) * j / n;
            w.row({x, y, s.value(x, y)}, 15);
        }
    }
}

}  // namespace

Command add_surface_command(CLI::App& app) {
    auto a = std::make_shared<SurfaceArgs>();
    CLI::App* c = app.add_subcommand(
        "surface",
        "Hosaka surfaces (section 4): tensor (eq 30 over a grid of heights), coons (eq 28, S0 = 0), boundary (eq 31)");
    add_enum_option(
        c, "--kind", a->kind,
        {{"tensor", SurfaceKind::tensor}, {"coons", SurfaceKind::coons}, {"boundary", SurfaceKind::boundary}},
        "surface kind")
        ->required();
    c->add_option("--in", a->in, "tensor: heights CSV, x,y,z per line covering a rectangular grid");
    c->add_option("--bottom", a->bottom, "coons: points of the edge v = 0 (R1), from S(0,0) to S(1,0)");
    c->add_option("--left", a->left, "coons: points of the edge u = 0 (R2), from S(0,0) to S(0,1)");
    c->add_option("--top", a->top, "coons: points of the edge v = 1 (R3), from S(0,1) to S(1,1)");
    c->add_option("--right", a->right, "coons: points of the edge u = 1 (R4), from S(1,0) to S(1,1)");
    c->add_option("--lower", a->lower, "boundary: lower curve L0, x,y,z per line, x increasing");
    c->add_option("--upper", a->upper, "boundary: upper curve L1, same first and last x as L0");
    c->add_option("--m", a->m, "boundary: order m of the sections (eq 31)")->check(CLI::Range(1, 2));
    c->add_option("--lower-slope", a->lower_slope, "boundary: cross slope dz/dy along L0 (constant)");
    c->add_option("--upper-slope", a->upper_slope, "boundary: cross slope dz/dy along L1 (constant)");
    c->add_option("--lower-curvature", a->lower_curvature, "boundary, m = 2: d2z/dy2 along L0 (constant)");
    c->add_option("--upper-curvature", a->upper_curvature, "boundary, m = 2: d2z/dy2 along L1 (constant)");
    c->add_option("--samples", a->samples, "samples per direction ((N+1)^2 rows)")->check(CLI::Range(1, 3000));
    c->add_option("--out", a->out,
                  "by extension: .csv grid of samples, .json exact Bezier patches (tensor, coons), .step/.stp one "
                  "B-spline surface (tensor, coons); - for stdout (csv unless --format)")
        ->required();
    c->add_option("--format", a->format, "output format, whatever the extension")
        ->check(CLI::IsMember(surface_format_names()));
    return {c, [a] {
                const exports::CurveFormat format = surface_output_format(a->format, a->out, "cagd surface");
                OutputFile out(a->out);
                switch (a->kind) {
                    case SurfaceKind::tensor: write_tensor(*a, format, out); break;
                    case SurfaceKind::coons: write_coons(*a, format, out); break;
                    case SurfaceKind::boundary: write_boundary(*a, format, out); break;
                }
                out.commit();
                return 0;
            }};
}

}  // namespace cagd::cli
