#include "cagd/fairness/space_pseudo_energy_table.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>

#include "cagd/core/checksum.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/io/file_lock.hpp"
#include "cagd/io/output_file.hpp"
#include "cagd/io/user_cache.hpp"

namespace cagd::fairness {

namespace {

constexpr int kSpaceTableFormat = 2;  // 2: the checksum line
const char* const kWho = "cagd::fairness::SpacePseudoEnergyTable";

void require_grid(const SpaceAngleGrid& g) {
    if (g.n_theta < 2) fail_input(kWho, "n_theta must be >= 2, got " + std::to_string(g.n_theta));
    if (g.n_phi < 4 || g.n_phi % 2 != 0)
        fail_input(kWho, "n_phi must be even and >= 4, got " + std::to_string(g.n_phi));
    if (g.size() > 200'000'000L) fail_input(kWho, "grid of " + std::to_string(g.size()) + " nodes is larger than 2e8");
}

// The orbit representative of node (i, j, k): i ≤ j (reversal), k ≤ M/2 (reflection).
struct Orbit {
    int i, j, k;
    bool swapped;  // the node is the reversal of its representative: r0 ↔ r1
};
Orbit orbit_of(int i, int j, int k, int m) { return {std::min(i, j), std::max(i, j), std::min(k, (m - k) % m), i > j}; }

}  // namespace

std::vector<double> SpaceAngleGrid::theta_nodes() const {
    std::vector<double> t(static_cast<std::size_t>(n_theta));
    for (int k = 0; k < n_theta; ++k) t[static_cast<std::size_t>(k)] = (k + 0.5) * std::numbers::pi / n_theta;
    return t;
}

std::vector<double> SpaceAngleGrid::phi_nodes() const {
    std::vector<double> p(static_cast<std::size_t>(n_phi));
    for (int k = 0; k < n_phi; ++k) p[static_cast<std::size_t>(k)] = 2 * std::numbers::pi * k / n_phi;
    return p;
}

std::vector<long> SpacePseudoEnergyTable::orbit_nodes(const SpaceAngleGrid& grid) {
    require_grid(grid);
    std::vector<long> out;
    for (int i = 0; i < grid.n_theta; ++i)
        for (int j = i; j < grid.n_theta; ++j)
            for (int k = 0; k <= grid.n_phi / 2; ++k)
                out.push_back((static_cast<long>(i) * grid.n_theta + j) * grid.n_phi + k);
    return out;
}

std::vector<SpacePseudoEnergyMinimum> SpacePseudoEnergyTable::compute_orbits(
    const SpaceAngleGrid& grid, TableMethod method, long begin, long end, int threads,
    const std::function<void(long, long)>& progress) {
    if (method == TableMethod::nlopt)
        fail_input(kWho,
                   "the space table is built by the fast or the reference minimiser (method nlopt is planar only)");
    const std::vector<long> orbits = orbit_nodes(grid);
    if (begin < 0 || end > static_cast<long>(orbits.size()) || begin > end)
        fail_input(kWho, "orbit range [" + std::to_string(begin) + ", " + std::to_string(end) + ") outside [0, " +
                             std::to_string(orbits.size()) + "]");
    const std::vector<double> theta = grid.theta_nodes(), phi = grid.phi_nodes();
    std::vector<SpacePseudoEnergyMinimum> out(static_cast<std::size_t>(end - begin));
    parallel_for(
        end - begin, std::max(1, threads),
        [&](long q) {
            const long node = orbits[static_cast<std::size_t>(begin + q)];
            const auto k = static_cast<std::size_t>(node % grid.n_phi),
                       j = static_cast<std::size_t>((node / grid.n_phi) % grid.n_theta),
                       i = static_cast<std::size_t>(node / grid.n_phi / grid.n_theta);
            out[static_cast<std::size_t>(q)] = method == TableMethod::reference
                                                   ? minimize_space_pseudo_energy_reference(theta[i], theta[j], phi[k])
                                                   : minimize_space_pseudo_energy(theta[i], theta[j], phi[k]);
        },
        progress);
    return out;
}

SpacePseudoEnergyTable SpacePseudoEnergyTable::assemble(const SpaceAngleGrid& grid, TableMethod method,
                                                        const std::vector<SpacePseudoEnergyMinimum>& orbits) {
    const std::vector<long> nodes = orbit_nodes(grid);
    if (orbits.size() != nodes.size())
        fail_input(kWho, "assemble needs " + std::to_string(nodes.size()) + " orbit minima, got " +
                             std::to_string(orbits.size()));
    SpacePseudoEnergyTable t;
    t.grid_ = grid;
    t.method_ = method;
    t.theta_ = grid.theta_nodes();
    t.phi_ = grid.phi_nodes();
    // Position of each representative in the orbit list.
    std::vector<long> where(static_cast<std::size_t>(grid.size()), -1);
    for (std::size_t q = 0; q < nodes.size(); ++q) where[static_cast<std::size_t>(nodes[q])] = static_cast<long>(q);
    t.values_.resize(static_cast<std::size_t>(grid.size()));
    for (int i = 0; i < grid.n_theta; ++i)
        for (int j = 0; j < grid.n_theta; ++j)
            for (int k = 0; k < grid.n_phi; ++k) {
                const Orbit o = orbit_of(i, j, k, grid.n_phi);
                const SpacePseudoEnergyMinimum& m =
                    orbits[static_cast<std::size_t>(where[static_cast<std::size_t>(t.index(o.i, o.j, o.k))])];
                SpaceTableValue v{m.pseudo_energy, o.swapped ? m.r1 : m.r0, o.swapped ? m.r0 : m.r1, m.length,
                                  m.outcome.ok() ? m.type : SegmentType::x};
                t.values_[static_cast<std::size_t>(t.index(i, j, k))] = v;
            }
    return t;
}

SpacePseudoEnergyTable SpacePseudoEnergyTable::build(const SpaceAngleGrid& grid, TableMethod method, int threads,
                                                     const std::function<void(long, long)>& progress) {
    const long orbits = static_cast<long>(orbit_nodes(grid).size());
    return assemble(grid, method, compute_orbits(grid, method, 0, orbits, threads, progress));
}

std::string SpacePseudoEnergyTable::header_line() const {
    std::ostringstream s;
    s << "# cagd space pseudo-energy table format " << kSpaceTableFormat << " grid " << grid_.n_theta << " "
      << grid_.n_phi << " method " << to_string(method_);
    return s.str();
}

void SpacePseudoEnergyTable::save(std::ostream& out) const {
    std::string text = header_line() + "\ni,j,k,J,r0,r1,L,type\n";
    char buf[256];
    for (int i = 0; i < grid_.n_theta; ++i)
        for (int j = 0; j < grid_.n_theta; ++j)
            for (int k = 0; k < grid_.n_phi; ++k) {
                const SpaceTableValue& v = node(i, j, k);
                std::snprintf(buf, sizeof buf, "%d,%d,%d,%.17g,%.17g,%.17g,%.17g,%s\n", i, j, k, v.pseudo_energy, v.r0,
                              v.r1, v.length, to_string(v.type));
                text += buf;
            }
    out << text << checksum_line(text);
}

void SpacePseudoEnergyTable::save(const std::string& path) const {
    OutputFile out(path, "table");  // io/output_file.hpp: written whole or not at all
    save(out.stream());
    out.commit();
}

// A load checks, before it trusts a value: the checksum (core/checksum.hpp); the grid (require_grid);
// exactly n_θ² n_φ rows, each node once; every field a number, NaN nowhere; type c, s or x; a node
// of type c or s has finite J ≥ 0, magnitudes r0, r1 > 0 and length L ≥ 1 (the unit chord); a node
// of type x, J ≥ 0 or inf. The text is bounded by what the header declares (read_table_text).
SpacePseudoEnergyTable SpacePseudoEnergyTable::load(const std::string& path) {
    // Lines after the header: the column names, n_θ² n_φ rows, the checksum line (−1: no grid).
    const auto lines_after = [](const std::string& header) -> long {
        std::istringstream h(header);
        std::string word;
        while (h >> word && word != "grid") {}
        long n = 0, m = 0;
        if (!(h >> n >> m) || n < 2 || m < 4 || n * n * m > 200'000'000L) return -1;
        return n * n * m + 2;
    };
    const std::string text = read_table_text(path, kWho, lines_after);
    std::istringstream in{std::string(checked_content(text, path))};
    std::string line;
    std::getline(in, line);
    std::istringstream h(line);
    std::string hash, cagd, space, pe, table, format, grid_word, method_word, method;
    int version = 0, n = 0, m = 0;
    h >> hash >> cagd >> space >> pe >> table >> format >> version >> grid_word >> n >> m >> method_word >> method;
    if (hash != "#" || space != "space" || grid_word != "grid" || method_word != "method" ||
        version != kSpaceTableFormat)
        fail_input(kWho, "'" + path + "' is not a space pseudo-energy table of format " +
                             std::to_string(kSpaceTableFormat) + " (first line: '" + excerpt(line) + "')");
    if (method != "fast" && method != "reference")
        fail_input(kWho, "'" + path + "': unknown method '" + excerpt(method) + "'");
    SpacePseudoEnergyTable t;
    t.grid_ = {n, m};
    require_grid(t.grid_);
    t.method_ = method == "reference" ? TableMethod::reference : TableMethod::fast;
    std::getline(in, line);  // column names
    struct Row {
        long index;
        SpaceTableValue value;
    };
    std::vector<Row> rows;
    int line_no = 2;
    while (std::getline(in, line)) {
        ++line_no;
        const std::string where = "'" + path + "':" + std::to_string(line_no) + ": ";
        const std::vector<std::string> f = split_fields(line);
        if (f.size() != 8) fail_input(kWho, where + std::to_string(f.size()) + " fields, a node row has 8");
        double v[7] = {};
        for (int c = 0; c < 7; ++c)
            if (!parse_decimal(f[static_cast<std::size_t>(c)], v[c]) || std::isnan(v[c]))
                fail_input(kWho, where + "field " + std::to_string(c + 1) + " '" +
                                     excerpt(f[static_cast<std::size_t>(c)]) + "' is not a number");
        const int limits[3] = {n, n, m};
        for (int c = 0; c < 3; ++c)
            if (!(v[c] >= 0 && v[c] < limits[c] && v[c] == std::floor(v[c])))
                fail_input(kWho, where + "node index " + f[static_cast<std::size_t>(c)] + " is outside the grid");
        const std::string& type = f[7];
        if (type != "c" && type != "s" && type != "x")
            fail_input(kWho, where + "type '" + excerpt(type) + "': c, s or x is expected");
        const SpaceTableValue value{v[3], v[4], v[5], v[6],
                                    type == "c"   ? SegmentType::c
                                    : type == "s" ? SegmentType::s
                                                  : SegmentType::x};
        if (value.type != SegmentType::x) {
            if (!(std::isfinite(value.pseudo_energy) && value.pseudo_energy >= 0))
                fail_input(kWho, where + "J = " + f[3] + ": J of a defined node is finite and >= 0");
            if (!(std::isfinite(value.r0) && value.r0 > 0 && std::isfinite(value.r1) && value.r1 > 0))
                fail_input(kWho, where + "r0, r1 = " + f[4] + ", " + f[5] + ": finite and > 0");
            if (!(std::isfinite(value.length) && value.length >= 1.0 - 1e-9))
                fail_input(kWho, where + "L = " + f[6] + ": the length of a unit-chord segment is finite and >= 1");
        } else if (!(value.pseudo_energy >= 0)) {
            fail_input(kWho, where + "J = " + f[3] + ": >= 0 or inf");
        }
        rows.push_back({(static_cast<long>(v[0]) * n + static_cast<long>(v[1])) * m + static_cast<long>(v[2]), value});
    }
    if (static_cast<long>(rows.size()) != t.grid_.size())
        fail_input(kWho, "'" + path + "': " + std::to_string(rows.size()) + " node rows, the grid has " +
                             std::to_string(t.grid_.size()));
    t.theta_ = t.grid_.theta_nodes();
    t.phi_ = t.grid_.phi_nodes();
    t.values_.assign(static_cast<std::size_t>(t.grid_.size()), {});
    std::vector<char> seen(t.values_.size(), 0);
    for (const Row& r : rows) {
        if (seen[static_cast<std::size_t>(r.index)])
            fail_input(kWho, "'" + path + "': node " + std::to_string(r.index) + " (in i, j, k order) is given twice");
        seen[static_cast<std::size_t>(r.index)] = 1;
        t.values_[static_cast<std::size_t>(r.index)] = r.value;
    }
    return t;
}

SpacePseudoEnergyTable SpacePseudoEnergyTable::load_or_build(const std::string& path, const SpaceAngleGrid& grid,
                                                             TableMethod method, int threads) {
    return load_or_build(path, grid, method, threads, false);
}

SpacePseudoEnergyTable SpacePseudoEnergyTable::user_cached(const SpaceAngleGrid& grid, TableMethod method,
                                                           int threads) {
    const std::optional<std::string> dir = user_cache_directory();
    if (!dir) return build(grid, method, threads);
    const std::string name = std::string("space-pseudo-energy-table-") + std::to_string(grid.n_theta) + "x" +
                             std::to_string(grid.n_theta) + "x" + std::to_string(grid.n_phi) + "-" + to_string(method) +
                             ".txt";
    return load_or_build(*dir + "/" + name, grid, method, threads, true);
}

SpacePseudoEnergyTable SpacePseudoEnergyTable::load_or_build(const std::string& path, const SpaceAngleGrid& grid,
                                                             TableMethod method, int threads, bool user_cache) {
    const auto try_load = [&](std::string& why) -> std::optional<SpacePseudoEnergyTable> {
        if (!cache_file_exists(path)) return std::nullopt;
        try {
            SpacePseudoEnergyTable t = load(path);
            if (t.grid_.n_theta == grid.n_theta && t.grid_.n_phi == grid.n_phi && t.method_ == method) return t;
            why = "another table (grid " + std::to_string(t.grid_.n_theta) + " x " + std::to_string(t.grid_.n_phi) +
                  " or another method)";
        } catch (const InvalidInput& e) {  // damaged or foreign: rebuilt
            why = e.what();
        }
        return std::nullopt;
    };
    return load_or_build_locked(path, try_load, [&] {
        if (!user_cache) {
            SpacePseudoEnergyTable t = build(grid, method, threads);
            t.save(path);
            return t;
        }
        announce_cache_build(path, "the " + std::to_string(grid.n_theta) + " x " + std::to_string(grid.n_theta) +
                                       " x " + std::to_string(grid.n_phi) + " space pseudo-energy table (" +
                                       to_string(method) + " minimiser)");
        SpacePseudoEnergyTable t = build(grid, method, threads, cache_build_progress());
        try {
            t.save(path);
        } catch (const OutputError&) {   // a failed write: the table stays in memory, the cache as it was
        } catch (const InvalidInput&) {  // a place no file can be made (a directory there): likewise
        }
        return t;
    });
}

SpaceTableValue SpacePseudoEnergyTable::lookup(double theta0, double theta1, double phi) const {
    const char* who = "cagd::fairness::SpacePseudoEnergyTable::lookup";
    for (const auto& [v, name] : {std::pair{theta0, "theta0"}, {theta1, "theta1"}})
        if (!(v >= -1e-12 && v <= std::numbers::pi + 1e-12))
            fail_input(who, std::string(name) + " must be a finite angle in [0, pi], got " + full_precision(v));
    if (!std::isfinite(phi)) fail_input(who, "phi must be finite, got " + full_precision(phi));
    const int n = grid_.n_theta, m = grid_.n_phi;
    // θ: cell between midpoint nodes, clamped at the ends; φ: periodic.
    const auto locate_theta = [&](double th, int& i, double& f) {
        const double u = th / (std::numbers::pi / n) - 0.5;
        i = std::clamp(static_cast<int>(std::floor(u)), 0, n - 2);
        f = std::clamp(u - i, 0.0, 1.0);
    };
    int i = 0, j = 0;
    double fu = 0, fv = 0;
    locate_theta(theta0, i, fu);
    locate_theta(theta1, j, fv);
    const double turns = phi / (2 * std::numbers::pi);
    const double w = (turns - std::floor(turns)) * m;
    const int k = std::min(static_cast<int>(w), m - 1);
    const double fw = w - k;
    const int k1 = (k + 1) % m;
    const SegmentType want = node(fu < 0.5 ? i : i + 1, fv < 0.5 ? j : j + 1, fw < 0.5 ? k : k1).type;
    SpaceTableValue out;
    double wsum = 0;
    for (int c = 0; c < 8; ++c) {
        const int a = i + (c & 1), b = j + ((c >> 1) & 1), p = (c & 4) ? k1 : k;
        const SpaceTableValue& v = node(a, b, p);
        if (v.type == SegmentType::x || (want != SegmentType::x && v.type != want)) continue;
        const double wt = ((c & 1) ? fu : 1 - fu) * (((c >> 1) & 1) ? fv : 1 - fv) * ((c & 4) ? fw : 1 - fw);
        wsum += wt;
        out.pseudo_energy += wt * v.pseudo_energy;
        out.r0 += wt * v.r0;
        out.r1 += wt * v.r1;
        out.length += wt * v.length;
    }
    if (!(wsum > 0.0))
        fail_input(who, "no defined table node of the nearest node's type around (" + full_precision(theta0) + ", " +
                            full_precision(theta1) + ", " + full_precision(phi) + ")");
    out.pseudo_energy /= wsum;
    out.r0 /= wsum;
    out.r1 /= wsum;
    out.length /= wsum;
    out.type = want;
    return out;
}

}  // namespace cagd::fairness
