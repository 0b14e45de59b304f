// The `cagd` command: the library on the user's own points.
//   cagd interpolate --method s-spline|b2-spline|cubic-bspline (--m M | --m-vector LIST)
//                    [--end natural|tangent|bessel] [--start-tangent X,Y] [--end-tangent X,Y]
//                    [--rule locality|I|IIa|fmill] [--closed] [--samples N] --in P.csv --out C.csv
//   cagd interpolate --method pseudo-spline [--optimize none|exact|approx] [--table T]
//                    | cubic-a | cubic-b | hermite-a | hermite-b  [--closed] --in P.csv --out C.csv
//   cagd interpolate --method hosaka [--m M] [--scale chord|unit] [--end natural|tangent] [--closed] (2-D, 3-D; any M >= 1)
//   cagd interpolate --method curvature-profile [--spans line,free,arc,...] [--knots LIST [--degree 2|3]] [--closed] (2-D)
//   cagd surface --kind tensor --in XYZ.csv | --kind coons --bottom B --left L --top T --right R
//                | --kind boundary --lower L0 --upper L1 [--m 1|2] [--lower-slope S] [--upper-slope S]
//                  [--lower-curvature C] [--upper-curvature C]     [--samples N] --out GRID.csv
//   cagd smooth (--lambda L | --lambda-file F) [--form yx|parametric] [--samples N] --in P.csv --out C.csv
//   cagd smooth-surface --method net|plate|plate-boundary|approx1|approx2 --lambda L [--energy 55|56|57|58]
//                       [--poisson NU] [--m M] [--samples N] --in XYZ.csv --out GRID.csv
//   cagd lac --alpha A --length L --degree N [--construction scale1|rotation] [--samples S] [--lcg]
//            [--fit-from T0 --fit-to T1] --out C.csv
//   cagd monotone --in CONTROL.csv [--knots endpoint|uniform]
//   cagd lac3d --alpha A --beta B --degree N [--length L] [--start S0] [--composition C] [--slopes] --out C.csv
//   cagd typical-surface --n N --alpha-u A --alpha-v B --angle-deg D [--length L] [--grid G] --out GRID.csv [--net-out NET.csv]
//   cagd analyze CURVE.csv
//   cagd compare --in P.csv [--closed] [--methods a,b,...] [--no-plot] --out DIR
//   cagd analyze --in P.csv --method M [--optimize O] [--table T] [--closed]
// Bad input: one line on stderr, exit code 2.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

#include "analysis/curve_measures.hpp"
#include "cli/aesthetic_commands.hpp"
#include "cli/compare_command.hpp"
#include "cli/curvature_profile_command.hpp"
#include "cli/curve_output.hpp"
#include "core/errors.hpp"
#include "core/point_csv.hpp"
#include "fairness/pseudo_energy_table.hpp"
#include "fairness/pseudo_spline.hpp"
#include "locality/locality_spline.hpp"
#include "smoothing/elastic_line.hpp"
#include "smoothing/surface_smoothing.hpp"
#include "spline/hosaka_spline.hpp"
#include "surface/boundary_surface.hpp"
#include "surface/hosaka_patch.hpp"
#include "repro/csv.hpp"

namespace {

using namespace cagd;
using cagd::cli::write_curve;

Eigen::VectorXd parse_vector(const std::string& text, const std::string& option) {
    std::vector<double> v;
    std::stringstream ss(text);
    std::string f;
    while (std::getline(ss, f, ',')) {
        try {
            v.push_back(repro::parse_number(f));
        } catch (const InvalidInput&) {
            fail_input("cagd", option + " '" + text + "': '" + f + "' is not a number");
        }
    }
    Eigen::VectorXd out(static_cast<Eigen::Index>(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) out(static_cast<Eigen::Index>(i)) = v[i];
    return out;
}


int run_analyze(const std::string& path) {
    std::ifstream in(path);
    if (!in) fail_input("cagd analyze", "cannot open '" + path + "'");
    std::string line;
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;
    int line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.empty() || line[0] == '#') continue;
        const auto f = repro::split_csv_line(line);
        if (header.empty()) { header = f; continue; }
        std::vector<double> r;
        for (const auto& x : f) {
            try {
                r.push_back(repro::parse_number(x));
            } catch (const InvalidInput&) {
                fail_input("cagd analyze", path + ":" + std::to_string(line_no) + ": '" + x + "' is not a number");
            }
        }
        if (r.size() != header.size())
            fail_input("cagd analyze", path + ":" + std::to_string(line_no) + ": " + std::to_string(r.size()) +
                                           " fields, header has " + std::to_string(header.size()));
        rows.push_back(r);
    }
    const auto col = [&](const std::string& n) {
        for (std::size_t i = 0; i < header.size(); ++i) if (header[i] == n) return static_cast<int>(i);
        return -1;
    };
    const int x = col("x"), y = col("y"), dx = col("dx"), dy = col("dy"), ddx = col("ddx"), ddy = col("ddy");
    if (x < 0 || y < 0) fail_input("cagd analyze", path + ": needs columns x and y (as written by cagd interpolate)");
    if (rows.size() < 2) fail_input("cagd analyze", path + ": needs at least 2 samples");
    double length = 0.0, area = 0.0, energy = 0.0, kmin = INFINITY, kmax = -INFINITY;
    double u_kmin = 0, u_kmax = 0;
    const bool have_derivatives = dx >= 0 && dy >= 0 && ddx >= 0 && ddy >= 0;
    std::vector<double> kappa(rows.size(), 0.0);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const auto& r = rows[i];
        if (have_derivatives) {
            const double s2 = r[dx] * r[dx] + r[dy] * r[dy];
            if (s2 == 0.0) fail_input("cagd analyze", "zero speed at sample " + std::to_string(i));
            kappa[i] = (r[dx] * r[ddy] - r[dy] * r[ddx]) / (s2 * std::sqrt(s2));
            const double u = col("u") >= 0 ? r[col("u")] : double(i);
            if (kappa[i] < kmin) { kmin = kappa[i]; u_kmin = u; }
            if (kappa[i] > kmax) { kmax = kappa[i]; u_kmax = u; }
        }
        if (i == 0) continue;
        const auto& p = rows[i - 1];
        const double ds = std::hypot(r[x] - p[x], r[y] - p[y]);
        length += ds;
        area += 0.5 * (p[x] * r[y] - r[x] * p[y]);
        energy += 0.5 * (kappa[i] * kappa[i] + kappa[i - 1] * kappa[i - 1]) * ds;
    }
    const bool closed = std::hypot(rows.front()[x] - rows.back()[x], rows.front()[y] - rows.back()[y]) <= 1e-12 * (1 + length);
    std::cout << "quantity,value\n"
              << "samples," << rows.size() << "\n"
              << "polyline_length," << repro::format_number(length, 12) << "\n";
    if (closed) std::cout << "enclosed_area," << repro::format_number(area, 12) << "\n";
    if (have_derivatives)
        std::cout << "curvature_min," << repro::format_number(kmin, 12) << "\n"
                  << "curvature_min_at_u," << repro::format_number(u_kmin, 12) << "\n"
                  << "curvature_max," << repro::format_number(kmax, 12) << "\n"
                  << "curvature_max_at_u," << repro::format_number(u_kmax, 12) << "\n"
                  << "bending_energy," << repro::format_number(energy, 12) << "\n";
    std::cerr << "cagd analyze: sample-based (polyline length, trapezoid energy); accuracy grows with --samples\n";
    return 0;
}

bool is_section42_method(const std::string& m) {
    return m == "pseudo-spline" || m == "cubic-a" || m == "cubic-b" || m == "hermite-a" || m == "hermite-b";
}

// The pseudo-energy tables for the pseudo-spline: a file written by `cagd energy-table`, or the
// 36-node fast table built in memory (about 0.2 s on two threads), and J(θ), θ1(θ) derived from it.
fairness::PseudoSplineTables load_tables(const std::string& table_path) {
    return fairness::PseudoSplineTables::from(table_path.empty() ? fairness::PseudoEnergyTable::build({36, fairness::NodePlacement::periodic},
                                                                                                     fairness::TableMethod::fast)
                                                                 : fairness::PseudoEnergyTable::load(table_path));
}

void print_integrated(const spline::PiecewiseHermiteCurve& c);

// Length and area of a curve through the points: direct integration always (Romberg arc length
// to 1e-13, exact polynomial area), and from the L and S tables for the pseudo-spline (eq 16–21).
int run_analyze_method(const std::string& in_path, const std::string& method, const std::string& optimize, const std::string& table_path,
                       bool closed) {
    const PointList points = read_points_csv(in_path);
    const auto mode = fairness::parse_tangent_optimization(optimize);
    const auto m = fairness::parse_interpolation_method(method);
    if (m != fairness::InterpolationMethod::pseudo_spline) {
        const spline::PiecewiseHermiteCurve c = fairness::section42_interpolant(points, m, closed, fairness::ExactOracle{}, mode);
        print_integrated(c);
        return 0;
    }
    const fairness::PseudoSplineTables t = load_tables(table_path);
    const fairness::PseudoSpline ps = fairness::pseudo_spline(points, t.oracle(), mode, closed);
    print_integrated(ps.curve);
    std::cout << "length_from_tables," << repro::format_number(ps.length_from_tables(), 12) << "\n"
              << "area_from_tables," << repro::format_number(ps.area_from_tables(), 12) << "\n"
              << "pseudo_energy_from_tables," << repro::format_number(ps.pseudo_energy_from_tables(), 12) << "\n";
    std::cerr << "cagd analyze: areas are signed (counter-clockwise positive); an open curve is closed by the line from its last point to its first\n";
    return 0;
}

void print_integrated(const spline::PiecewiseHermiteCurve& c) {
    // Area enclosed by the curve, closed by the straight line from the last point to the first.
    const Eigen::MatrixXd& nodes = c.nodes();
    const Eigen::Index last = nodes.rows() - 1;
    const double closing = 0.5 * (nodes(last, 0) * nodes(0, 1) - nodes(last, 1) * nodes(0, 0));
    std::cout << "quantity,value\n"
              << "spans," << c.spans() << "\n"
              << "length_integrated," << repro::format_number(analysis::romberg_arc_length(c).value, 12) << "\n"
              << "area_integrated," << repro::format_number(analysis::enclosed_area(c) + closing, 12) << "\n";
}

struct SurfaceArgs {
    std::string kind, in, bottom, left, top, right, lower, upper, out;
    int m = 1, samples = 20;
    double lower_slope = 0, upper_slope = 0, lower_curvature = 0, upper_curvature = 0;
};

// hosaka section 4: the surfaces that take simple inputs, sampled on a (samples+1)² grid.
int run_surface(const SurfaceArgs& a) {
    const char* who = "cagd surface";
    const int n = a.samples;
    const auto require = [&](const std::string& value, const char* option) {
        if (value.empty()) fail_input(who, "--kind " + a.kind + " needs " + option);
    };
    if (a.kind == "tensor") {   // eq (30), m = 1, node derivatives from splines along the grid lines
        require(a.in, "--in");
        const surface::CartesianSurface s = surface::cartesian_spline_surface(read_points_csv(a.in));
        repro::CsvWriter w(a.out, {"x", "y", "z", "zx", "zy"});
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                const double x = s.x().front() + (s.x().back() - s.x().front()) * i / n, y = s.y().front() + (s.y().back() - s.y().front()) * j / n;
                w.row({x, y, s.value(x, y), s.derivative(x, y, 1, 0), s.derivative(x, y, 0, 1)}, 15);
            }
        return 0;
    }
    if (a.kind == "coons") {   // eq (28) with S0 = 0
        for (const auto& [v, o] : {std::pair{a.bottom, "--bottom"}, {a.left, "--left"}, {a.top, "--top"}, {a.right, "--right"}}) require(v, o);
        const surface::EdgeFormPatch s(1, surface::edges_through_points(read_points_csv(a.bottom), read_points_csv(a.left), read_points_csv(a.top),
                                                                         read_points_csv(a.right)));
        const Eigen::VectorXd probe = s.point(0, 0);
        std::vector<std::string> header{"u", "v", "x", "y"};
        if (probe.size() == 3) header.push_back("z");
        repro::CsvWriter w(a.out, header);
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                const Eigen::VectorXd p = s.point(double(i) / n, double(j) / n);
                std::vector<double> row{double(i) / n, double(j) / n};
                for (Eigen::Index k = 0; k < p.size(); ++k) row.push_back(p(k));
                w.row(row, 15);
            }
        return 0;
    }
    if (a.kind == "boundary") {   // eq (31) between two boundary curves
        require(a.lower, "--lower");
        require(a.upper, "--upper");
        if (a.m != 1 && a.m != 2) fail_input(who, "--kind boundary takes --m 1 or 2, got " + std::to_string(a.m));
        std::vector<double> lower_d{a.lower_slope}, upper_d{a.upper_slope};
        if (a.m == 2) {
            lower_d.push_back(a.lower_curvature);
            upper_d.push_back(a.upper_curvature);
        }
        const surface::BoundaryConformingSurface s(a.m, surface::boundary_through_points(read_points_csv(a.lower), lower_d),
                                                   surface::boundary_through_points(read_points_csv(a.upper), upper_d));
        repro::CsvWriter w(a.out, {"x", "y", "z"});
        for (int i = 0; i <= n; ++i) {
            const double x = std::min(s.x_min() + (s.x_max() - s.x_min()) * i / n, s.x_max());
            for (int j = 0; j <= n; ++j) {
                const double y = s.y_lower(x) + (s.y_upper(x) - s.y_lower(x)) * j / n;
                w.row({x, y, s.value(x, y)}, 15);
            }
        }
        return 0;
    }
    fail_input(who, "unknown --kind " + a.kind);
}

struct SmoothArgs {
    std::string in, out, lambda_file, form = "yx";
    double lambda = 0.0;
    int samples = 20;
};

// hosaka section 6: the elastic line (eq 50-52) on y(x) data or on a parametric point list.
int run_smooth(const SmoothArgs& a, bool lambda_given) {
    const char* who = "cagd smooth";
    if (lambda_given == !a.lambda_file.empty()) fail_input(who, "give exactly one of --lambda and --lambda-file");
    const PointList points = read_points_csv(a.in);
    std::vector<double> lambda{a.lambda};
    if (!a.lambda_file.empty()) lambda = read_values_csv(a.lambda_file);
    const char* names = "xyz";
    if (a.form == "yx") {   // rows x, y[, z]: y(x) (and z(x)) smoothed
        if (points.cols() < 2) fail_input(who, "--form yx needs rows x,y or x,y,z");
        const std::vector<double> x(points.col(0).data(), points.col(0).data() + points.rows());
        const smoothing::ElasticLine line = smoothing::elastic_line(x, points.rightCols(points.cols() - 1), lambda);
        std::vector<std::string> header{"x"};
        for (const char* prefix : {"", "d", "dd"})
            for (Eigen::Index k = 1; k < points.cols(); ++k) header.push_back(std::string(prefix) + names[k]);
        repro::CsvWriter w(a.out, header);
        for (std::size_t i = 0; i + 1 < x.size(); ++i)
            for (int k = 0; k < a.samples || (i + 2 == x.size() && k == a.samples); ++k) {
                const double u = double(k) / a.samples;
                std::vector<double> row{x[i] + u * (x[i + 1] - x[i])};
                for (int order = 0; order <= 2; ++order) {
                    const Eigen::RowVectorXd v = line.curve.evaluate_in(static_cast<int>(i), u, order);
                    row.insert(row.end(), v.data(), v.data() + v.size());
                }
                w.row(row, 15);
            }
        return 0;
    }
    // parametric: x(t), y(t)[, z(t)] over the chord-length parameter
    const smoothing::ElasticLine line = smoothing::elastic_line_parametric(points, lambda);
    std::vector<std::string> header{"t"};
    for (Eigen::Index k = 0; k < points.cols(); ++k) header.push_back(std::string(1, names[k]));
    repro::CsvWriter w(a.out, header);
    for (std::size_t i = 0; i + 1 < line.x().size(); ++i)
        for (int k = 0; k < a.samples || (i + 2 == line.x().size() && k == a.samples); ++k) {
            const double u = double(k) / a.samples;
            std::vector<double> row{line.x()[i] + u * (line.x()[i + 1] - line.x()[i])};
            const Eigen::RowVectorXd v = line.curve.evaluate_in(static_cast<int>(i), u);
            row.insert(row.end(), v.data(), v.data() + v.size());
            w.row(row, 15);
        }
    return 0;
}

struct SmoothSurfaceArgs {
    std::string method, in, out;
    double lambda = 0.0, poisson = 0.3;
    int energy = 57, m = 2, samples = 0;
};

// hosaka sections 6-7: the net, the plates and the two approximations on a grid of heights.
int run_smooth_surface(const SmoothSurfaceArgs& a) {
    const surface::GridHeights g = surface::grid_from_points(read_points_csv(a.in));
    const Eigen::MatrixXd lambda = Eigen::MatrixXd::Constant(1, 1, a.lambda);
    const smoothing::PlateEnergy energy = a.energy == 55   ? smoothing::PlateEnergy::poisson
                                          : a.energy == 56 ? smoothing::PlateEnergy::no_poisson
                                          : a.energy == 57 ? smoothing::PlateEnergy::no_twist
                                                           : smoothing::PlateEnergy::mean_curvature;
    if (a.method == "net") {   // the net's own unknowns at the nodes
        if (a.samples > 0) fail_input("cagd smooth-surface", "--method net gives node values only; use approx2 for a surface to sample");
        const smoothing::ElasticNet net = smoothing::elastic_net(g.x, g.y, g.z, lambda);
        repro::CsvWriter w(a.out, {"x", "y", "z", "zxx", "zyy"});
        for (std::size_t i = 0; i < g.x.size(); ++i)
            for (std::size_t j = 0; j < g.y.size(); ++j) {
                const Eigen::Index r = static_cast<Eigen::Index>(i), c = static_cast<Eigen::Index>(j);
                w.row({g.x[i], g.y[j], net.values(r, c), net.xx(r, c), net.yy(r, c)}, 15);
            }
        return 0;
    }
    std::function<double(double, double, int, int)> s;
    if (a.method == "plate-boundary") {
        const auto b = smoothing::boundary_plate_smoothing(g.x, g.y, g.z, lambda, energy, a.m, a.poisson).surface;
        s = [b](double x, double y, int i, int j) { return b.derivative(x, y, i, j); };
    } else {
        const surface::CartesianSurface c = a.method == "plate"     ? smoothing::plate_smoothing(g.x, g.y, g.z, lambda, energy, a.poisson).surface
                                            : a.method == "approx1" ? smoothing::local_orthogonal_smoothing(g.x, g.y, g.z, a.lambda, energy, a.poisson)
                                                                    : smoothing::net_spline_smoothing(g.x, g.y, g.z, lambda);
        s = [c](double x, double y, int i, int j) { return c.derivative(x, y, i, j); };
    }
    repro::CsvWriter w(a.out, {"x", "y", "z", "zx", "zy", "zxy"});
    const auto emit = [&](double x, double y) { w.row({x, y, s(x, y, 0, 0), s(x, y, 1, 0), s(x, y, 0, 1), s(x, y, 1, 1)}, 15); };
    if (a.samples == 0) {
        for (double x : g.x)
            for (double y : g.y) emit(x, y);
        return 0;
    }
    for (int i = 0; i <= a.samples; ++i)
        for (int j = 0; j <= a.samples; ++j)
            emit(std::min(g.x.front() + (g.x.back() - g.x.front()) * i / a.samples, g.x.back()), std::min(g.y.front() + (g.y.back() - g.y.front()) * j / a.samples, g.y.back()));
    return 0;
}

int run_energy(double theta0, double theta1, bool degrees) {
    const double k = degrees ? M_PI / 180.0 : 1.0;
    const double t0 = theta0 * k, t1 = theta1 * k;
    fairness::require_tangent_angle(degrees ? "cagd energy (--deg converted to radians)" : "cagd energy", t0, "--theta0");
    fairness::require_tangent_angle(degrees ? "cagd energy (--deg converted to radians)" : "cagd energy", t1, "--theta1");
    const fairness::PseudoEnergyMinimum m = fairness::minimize_pseudo_energy(t0, t1);
    if (fairness::is_undefined_node(t0, t1)) fail_input("cagd energy", m.outcome.message);
    if (!m.outcome.ok()) {
        std::cerr << "cagd: no result: " << m.outcome.message << "\n";
        return 1;
    }
    std::printf("theta0,theta1,J,r0,r1,L,S,type\n%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%s\n", theta0, theta1, m.pseudo_energy, m.r0,
                m.r1, m.length, m.area, fairness::to_string(m.type));
    return 0;
}

int run_energy_table(int n, const std::string& placement, const std::string& method, int threads, const std::string& out) {
    if (n < 2) fail_input("cagd energy-table", "--grid must be >= 2, got " + std::to_string(n));
    const fairness::AngleGrid grid{n, fairness::parse_node_placement(placement)};
    const auto m = method == "reference" ? fairness::TableMethod::reference : fairness::TableMethod::fast;
    const auto progress = [](long done, long total) {
        std::fprintf(stderr, "\rcagd energy-table: %ld / %ld nodes", done, total);
        if (done == total) std::fprintf(stderr, "\n");
    };
    const fairness::PseudoEnergyTable t = fairness::PseudoEnergyTable::build(grid, m, threads, m == fairness::TableMethod::fast, progress);
    t.save(out);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"cagd — interpolating curves from five Japanese CAGD papers (cagd-repro)"};
    app.require_subcommand(1);

    auto* interp = app.add_subcommand("interpolate", "Interpolate points with an S-/B2-spline (sb2_locality) or the cubic B-spline of eq (10)");
    std::string method = "s-spline", m_vector, end = "natural", rule = "locality", in_path, out_path;
    std::string start_tangent, end_tangent;
    int m = -1, samples = 16;
    bool closed = false;
    std::string optimize = "exact", table_path;
    interp->add_option("--method", method, "s-spline | b2-spline | cubic-bspline (sb2_locality); pseudo-spline | cubic-a | cubic-b | hermite-a | hermite-b (pseudo_energy section 4.2); hosaka; curvature-profile")
        ->check(CLI::IsMember({"s-spline", "b2-spline", "cubic-bspline", "pseudo-spline", "cubic-a", "cubic-b", "hermite-a", "hermite-b", "hosaka", "curvature-profile"}));
    cli::CurvatureProfileArgs cp;
    interp->add_option("--spans", cp.spans, "curvature-profile: one shape per span, free | line | arc | clothoid, e.g. line,free,arc (default: all free)");
    interp->add_option("--knots", cp.knots, "curvature-profile: knot-difference list of ψ, e.g. \"{0, S0, 0, {S1, S2}, S3, 0}\" (default: from --spans, degree 2)");
    auto* cp_degree = interp->add_option("--degree", cp.degree, "curvature-profile: degree of ψ for --knots, 2 (clothoid) or 3 (the paper's cubic)")->check(CLI::Range(2, 3));
    std::string scale = "chord";
    interp->add_option("--scale", scale, "hosaka: chord (k_i = |A_i|/|A_i+1|, eq 19) | unit (k_i = 1)")->check(CLI::IsMember({"chord", "unit"}));
    interp->add_option("--optimize", optimize, "pseudo-spline tangent optimisation: none | exact | approx (Table 4)")->check(CLI::IsMember({"none", "exact", "approx"}));
    interp->add_option("--table", table_path, "pseudo-energy table written by cagd energy-table (default: the 36-node fast table, built in memory)");
    auto* m_opt = interp->add_option("--m", m, "s-/b2-spline: locality m >= 0 for every segment (eq 12); hosaka: segment order m >= 1 (continuous to order 2m)");
    auto* mv_opt = interp->add_option("--m-vector", m_vector, "one m per segment, pairs as l:r, e.g. 1,2,1:3");
    m_opt->excludes(mv_opt);
    interp->add_option("--end", end, "natural | tangent | bessel (section 3.3)")->check(CLI::IsMember({"natural", "tangent", "bessel"}));
    interp->add_option("--start-tangent", start_tangent, "tangent at the first point, e.g. 1,0 (with --end tangent)");
    interp->add_option("--end-tangent", end_tangent, "tangent at the last point (with --end tangent)");
    interp->add_option("--rule", rule, "extra control point: locality (eq 12) | I (eq 15) | IIa (eq 16) | fmill (eq 17)")->check(CLI::IsMember({"locality", "I", "IIa", "fmill"}));
    interp->add_flag("--closed", closed, "closed curve");
    interp->add_option("--samples", samples, "samples per span in the output")->check(CLI::Range(1, 100000));
    interp->add_option("--in", in_path, "points CSV: x,y[,z] per line, optional header")->required();
    interp->add_option("--out", out_path, "curve CSV: u, position, 1st and 2nd derivative")->required();

    auto* analyze = app.add_subcommand("analyze", "Length, enclosed area, curvature extrema and bending energy of a curve CSV");
    std::string curve_path;
    std::string an_in, an_method, an_optimize = "exact", an_table;
    bool an_closed = false;
    auto* an_curve = analyze->add_option("curve", curve_path, "curve CSV as written by cagd interpolate (sample-based measures)");
    auto* an_in_opt = analyze->add_option("--in", an_in, "points CSV: build the curve with --method and integrate it exactly");
    analyze->add_option("--method", an_method, "with --in: pseudo-spline | cubic-a | cubic-b | hermite-a | hermite-b")
        ->check(CLI::IsMember({"pseudo-spline", "cubic-a", "cubic-b", "hermite-a", "hermite-b"}));
    analyze->add_option("--optimize", an_optimize, "pseudo-spline tangent optimisation: none | exact | approx")->check(CLI::IsMember({"none", "exact", "approx"}));
    analyze->add_option("--table", an_table, "pseudo-energy table written by cagd energy-table (default: 36-node fast table)");
    analyze->add_flag("--closed", an_closed, "closed curve (with --in)");
    an_curve->excludes(an_in_opt);

    auto* surf = app.add_subcommand("surface", "Hosaka surfaces (section 4): tensor (eq 30 over a grid of heights), coons (eq 28, S0 = 0), boundary (eq 31)");
    SurfaceArgs sa;
    surf->add_option("--kind", sa.kind, "tensor | coons | boundary")->required()->check(CLI::IsMember({"tensor", "coons", "boundary"}));
    surf->add_option("--in", sa.in, "tensor: heights CSV, x,y,z per line covering a rectangular grid");
    surf->add_option("--bottom", sa.bottom, "coons: points of the edge v = 0 (R1), from S(0,0) to S(1,0)");
    surf->add_option("--left", sa.left, "coons: points of the edge u = 0 (R2), from S(0,0) to S(0,1)");
    surf->add_option("--top", sa.top, "coons: points of the edge v = 1 (R3), from S(0,1) to S(1,1)");
    surf->add_option("--right", sa.right, "coons: points of the edge u = 1 (R4), from S(1,0) to S(1,1)");
    surf->add_option("--lower", sa.lower, "boundary: lower curve L0, x,y,z per line, x increasing");
    surf->add_option("--upper", sa.upper, "boundary: upper curve L1, same first and last x as L0");
    surf->add_option("--m", sa.m, "boundary: order m (1 or 2) of the sections (eq 31)");
    surf->add_option("--lower-slope", sa.lower_slope, "boundary: cross slope dz/dy along L0 (constant)");
    surf->add_option("--upper-slope", sa.upper_slope, "boundary: cross slope dz/dy along L1 (constant)");
    surf->add_option("--lower-curvature", sa.lower_curvature, "boundary, m = 2: d2z/dy2 along L0 (constant)");
    surf->add_option("--upper-curvature", sa.upper_curvature, "boundary, m = 2: d2z/dy2 along L1 (constant)");
    surf->add_option("--samples", sa.samples, "samples per direction")->check(CLI::Range(1, 10000));
    surf->add_option("--out", sa.out, "grid CSV")->required();

    auto* smooth = app.add_subcommand("smooth", "Elastic-line smoothing (hosaka section 6, eq 50-52): y(x) data or a parametric point list");
    SmoothArgs sm;
    auto* sm_lambda = smooth->add_option("--lambda", sm.lambda, "lambda = EI/k for every point (>= 0; 0 interpolates; units length^3)");
    smooth->add_option("--lambda-file", sm.lambda_file, "one lambda per data point, one per line");
    smooth->add_option("--form", sm.form, "yx: rows x,y[,z], x strictly increasing | parametric: 2-D/3-D points, chord parameter")
        ->check(CLI::IsMember({"yx", "parametric"}));
    smooth->add_option("--samples", sm.samples, "samples per interval")->check(CLI::Range(1, 100000));
    smooth->add_option("--in", sm.in, "data CSV")->required();
    smooth->add_option("--out", sm.out, "smoothed curve CSV (yx: x, values, first and second derivatives)")->required();

    auto* ssurf = app.add_subcommand("smooth-surface", "Smooth a grid of heights (hosaka sections 6-7): elastic net, plates, approximations 1 and 2");
    SmoothSurfaceArgs ss;
    ssurf->add_option("--method", ss.method, "net | plate (method i) | plate-boundary (method ii) | approx1 (eq 60) | approx2 (net + splines)")
        ->required()
        ->check(CLI::IsMember({"net", "plate", "plate-boundary", "approx1", "approx2"}));
    ssurf->add_option("--lambda", ss.lambda, "lambda = EI/k (net) or D/k (plates), >= 0 (> 0 for plates)")->required();
    ssurf->add_option("--energy", ss.energy, "plate energy: 55 (with --poisson), 56, 57 (default), 58")->check(CLI::IsMember({55, 56, 57, 58}));
    ssurf->add_option("--poisson", ss.poisson, "Poisson's ratio for --energy 55, in [0, 0.5)");
    ssurf->add_option("--m", ss.m, "plate-boundary: order m of eq (31), 1..4");
    ssurf->add_option("--samples", ss.samples, "sample the surface on an (N+1)^2 grid instead of the data nodes")->check(CLI::Range(0, 10000));
    ssurf->add_option("--in", ss.in, "heights CSV, x,y,z per line covering a rectangular grid")->required();
    ssurf->add_option("--out", ss.out, "CSV: x, y, z and derivatives at the nodes (or samples)")->required();

    auto* energy = app.add_subcommand("energy", "Minimum pseudo-energy J(theta0, theta1) of a unit-chord cubic Hermite segment (pseudo_energy eq 8), exact computation");
    double theta0 = 0, theta1 = 0;
    bool degrees = false;
    energy->add_option("--theta0", theta0, "start tangent angle, in [-pi, pi] (or [-180, 180] with --deg)")->required();
    energy->add_option("--theta1", theta1, "end tangent angle, in [-pi, pi] (or [-180, 180] with --deg)")->required();
    energy->add_flag("--deg", degrees, "angles in degrees");

    auto* table = app.add_subcommand("energy-table", "Build a lookup table of J, r0, r1, L, S and the segment type (pseudo_energy section 4.1)");
    int grid_n = 36, threads = 2;
    std::string placement = "periodic", table_out, table_method = "fast";
    table->add_option("--grid", grid_n, "nodes per axis (>= 2)")->required();
    table->add_option("--placement", placement, "periodic | endpoints | midpoints")->check(CLI::IsMember({"periodic", "endpoints", "midpoints"}));
    table->add_option("--method", table_method, "fast | reference")->check(CLI::IsMember({"fast", "reference"}));
    table->add_option("--threads", threads, "worker threads")->check(CLI::Range(1, 64));
    table->add_option("--out", table_out, "table file (text, first line records grid, placement and method)")->required();

    auto* cmp = app.add_subcommand("compare", "Every interpolation method on the same points: fairness table (CSV, Markdown) and figures");
    cli::CompareArgs cmp_args;
    cmp->add_option("--in", cmp_args.in, "points CSV: x,y per line, optional header")->required();
    cmp->add_option("--out", cmp_args.out, "output directory (created)")->required();
    cmp->add_flag("--closed", cmp_args.closed, "closed curves (methods that draw open curves only are listed as not applicable)");
    cmp->add_option("--methods", cmp_args.methods, "comma-separated subset, e.g. pseudo-spline-exact,cubic-b,curvature-profile (default: all)");
    bool no_plot = false;
    cmp->add_flag("--no-plot", no_plot, "write the figure data and script but do not run gnuplot");

    cli::LacArgs lac_args;
    cli::MonotoneArgs mono_args;
    auto* lac = cli::add_lac_command(app, lac_args);
    auto* mono = cli::add_monotone_command(app, mono_args);
    cli::Lac3dArgs lac3d_args;
    cli::TypicalSurfaceArgs tsurf_args;
    auto* lac3d = cli::add_lac3d_command(app, lac3d_args);
    auto* tsurf = cli::add_typical_surface_command(app, tsurf_args);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);
        std::cerr << "cagd: error: " << e.what() << "\n";
        return 2;
    }
    try {
        if (*analyze) {
            if (!an_in.empty()) {
                if (an_method.empty()) fail_input("cagd analyze", "--in needs --method");
                return run_analyze_method(an_in, an_method, an_optimize, an_table, an_closed);
            }
            if (curve_path.empty()) fail_input("cagd analyze", "give a curve CSV or --in POINTS --method M");
            return run_analyze(curve_path);
        }
        if (*cmp) {
            cmp_args.plot = !no_plot;
            return cli::run_compare(cmp_args);
        }
        if (*energy) return run_energy(theta0, theta1, degrees);
        if (*lac) return cli::run_lac(lac_args);
        if (*mono) return cli::run_monotone(mono_args);
        if (*lac3d) return cli::run_lac3d(lac3d_args);
        if (*tsurf) return cli::run_typical_surface(tsurf_args);
        if (*surf) return run_surface(sa);
        if (*smooth) return run_smooth(sm, sm_lambda->count() > 0);
        if (*ssurf) return run_smooth_surface(ss);
        if (*table) return run_energy_table(grid_n, placement, table_method, threads, table_out);
        const PointList points = read_points_csv(in_path);
        if (method == "curvature-profile") {   // curvature_profile sections 2–4
            cp.degree_given = cp_degree->count() > 0;
            cp.closed = closed;
            cp.samples = samples;
            cp.out = out_path;
            return cli::run_curvature_profile(points, cp);
        }
        if (method == "hosaka" && *mv_opt) fail_input("cagd interpolate", "--m-vector is for s-spline and b2-spline; hosaka takes --m");
        if (method == "hosaka") {   // hosaka eq (20) (m = 1), or order-m segments continuous to order 2m (section 3)
            if (*m_opt && m < 1) fail_input("cagd interpolate", "--method hosaka needs --m >= 1, got " + std::to_string(m));
            spline::HosakaSplineOptions ho;
            ho.scale = scale == "unit" ? spline::HosakaScale::unit : spline::HosakaScale::chord;
            ho.closed = closed;
            if (end == "bessel") fail_input("cagd interpolate", "--method hosaka takes --end natural or tangent, not bessel");
            if (end == "tangent") {
                if (start_tangent.empty() || end_tangent.empty())
                    fail_input("cagd interpolate", "--end tangent needs --start-tangent and --end-tangent");
                ho.end = spline::HosakaEnd::tangent;
                ho.start_tangent = parse_vector(start_tangent, "--start-tangent");
                ho.end_tangent = parse_vector(end_tangent, "--end-tangent");
            }
            if (*m_opt && m != 1) write_curve(spline::hosaka_spline(points, m, ho), samples, out_path);
            else write_curve(spline::hosaka_c2_spline(points, ho).curve, samples, out_path);
            return 0;
        }
        if (method == "pseudo-spline") {
            const fairness::PseudoSplineTables t = load_tables(table_path);
            write_curve(fairness::pseudo_spline(points, t.oracle(), fairness::parse_tangent_optimization(optimize), closed).curve, samples, out_path);
            return 0;
        }
        if (is_section42_method(method)) {   // the four comparison curves need no table
            write_curve(fairness::section42_interpolant(points, fairness::parse_interpolation_method(method), closed, fairness::ExactOracle{},
                                                        fairness::TangentOptimization::none),
                        samples, out_path);
            return 0;
        }
        if (method == "cubic-bspline") {
            write_curve(locality::cubic_bspline_interpolant(points, closed), samples, out_path);
            return 0;
        }
        locality::Options o;
        o.form = method == "b2-spline" ? locality::SplineForm::b2_spline : locality::SplineForm::s_spline;
        if (*mv_opt) o.m = locality::parse_m_vector(m_vector);
        else if (*m_opt) {
            if (m < 0) fail_input("cagd interpolate", "--m must be >= 0, got " + std::to_string(m));
            o.m = {{m, m}};
        }
        o.closed = closed;
        o.rule = rule == "I" ? locality::ExtraPointRule::method_I
                 : rule == "IIa" ? locality::ExtraPointRule::method_IIa
                 : rule == "fmill" ? locality::ExtraPointRule::fmill
                                   : locality::ExtraPointRule::locality;
        const auto kind = end == "tangent" ? locality::EndKind::tangent
                          : end == "bessel" ? locality::EndKind::bessel
                                            : locality::EndKind::natural;
        o.start.kind = o.end.kind = kind;
        if (kind == locality::EndKind::tangent) {
            if (start_tangent.empty() || end_tangent.empty())
                fail_input("cagd interpolate", "--end tangent needs --start-tangent and --end-tangent");
            o.start.tangent = parse_vector(start_tangent, "--start-tangent");
            o.end.tangent = parse_vector(end_tangent, "--end-tangent");
        }
        const auto spline = locality::interpolate(points, o);
        write_curve(spline.curve, samples, out_path);
        return 0;
    } catch (const InvalidInput& e) {
        std::cerr << "cagd: error: " << e.what() << "\n";
        return 2;
    }
}
