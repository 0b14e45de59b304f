#include "cagd/fairness/pseudo_energy_table.hpp"

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <thread>

#include "cagd/core/file_lock.hpp"
#include "cagd/core/parallel.hpp"

namespace cagd::fairness {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}

namespace {

// Bumped whenever a minimiser or the file layout changes, so stale caches are rebuilt.
constexpr int kCacheFormat = 5;  // 5: the runner-up's r0, r1 (TableReading::runner_up_within)

using detail::next_node;

}  // namespace

const char* to_string(NodePlacement p) {
    switch (p) {
        case NodePlacement::periodic: return "periodic";
        case NodePlacement::endpoints: return "endpoints";
        default: return "midpoints";
    }
}

NodePlacement parse_node_placement(const std::string& text) {
    if (text == "periodic") return NodePlacement::periodic;
    if (text == "endpoints") return NodePlacement::endpoints;
    if (text == "midpoints") return NodePlacement::midpoints;
    fail_input("cagd::fairness::parse_node_placement", "placement must be periodic, endpoints or midpoints, got '" + text + "'");
}

const char* to_string(TableMethod m) {
    switch (m) {
        case TableMethod::fast: return "fast";
        case TableMethod::reference: return "reference";
        default: return "nlopt";
    }
}

std::vector<double> AngleGrid::nodes() const {
    if (n < 2) fail_input("cagd::fairness::AngleGrid", "n must be >= 2, got " + std::to_string(n));
    std::vector<double> out(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        double f = 0.0;  // fraction of the way from −π to π
        switch (placement) {
            case NodePlacement::periodic: f = 2.0 * k / n; break;
            case NodePlacement::endpoints: f = 2.0 * k / (n - 1); break;
            case NodePlacement::midpoints: f = (2.0 * k + 1.0) / n; break;
        }
        // π·(f − 1) is exactly 0 when f = 1 and exactly ∓π at the ends.
        out[static_cast<std::size_t>(k)] = std::numbers::pi * (f - 1.0);
    }
    return out;
}

PseudoEnergyTable PseudoEnergyTable::build(const AngleGrid& grid, TableMethod method, int threads, bool use_symmetry, const std::function<void(long, long)>& progress) {
    if (threads < 1) fail_input("cagd::fairness::PseudoEnergyTable::build", "threads must be >= 1, got " + std::to_string(threads));
    PseudoEnergyTable t;
    t.grid_ = grid;
    t.method_ = method;
    t.axis_ = detail::PeriodicAxis(grid.nodes());
    const int n = grid.n;
    t.values_.assign(static_cast<std::size_t>(n * n), PseudoEnergyMinimum{});
    // Index of the node at −θ (the placements are symmetric about 0; ±π map to themselves).
    std::vector<int> negate(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        const double target = -t.axis_.nodes[static_cast<std::size_t>(k)];
        int best = 0;
        for (int m = 0; m < n; ++m)
            if (std::abs(std::remainder(t.axis_.nodes[static_cast<std::size_t>(m)] - target, 2 * std::numbers::pi)) <
                std::abs(std::remainder(t.axis_.nodes[static_cast<std::size_t>(best)] - target, 2 * std::numbers::pi)))
                best = m;
        negate[static_cast<std::size_t>(k)] = best;
    }
    // The orbit representative of (i, j): the smallest linear index among its images.
    const auto representative = [&](int i, int j) {
        const int ni = negate[static_cast<std::size_t>(i)], nj = negate[static_cast<std::size_t>(j)];
        return std::min({i * n + j, j * n + i, ni * n + nj, nj * n + ni});
    };
    std::vector<long> todo;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            if (!use_symmetry || representative(i, j) == i * n + j) todo.push_back(i * n + j);
    parallel_for(
        static_cast<long>(todo.size()), threads,
        [&](long k) {
            const long idx = todo[static_cast<std::size_t>(k)];
            const double a = t.axis_.nodes[static_cast<std::size_t>(idx / n)], b = t.axis_.nodes[static_cast<std::size_t>(idx % n)];
            t.values_[static_cast<std::size_t>(idx)] = method == TableMethod::fast        ? minimize_pseudo_energy(a, b)
                                                       : method == TableMethod::reference ? minimize_pseudo_energy_reference(a, b)
                                                                                          : minimize_pseudo_energy_nlopt(a, b);
        },
        progress);
    if (use_symmetry) {
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const int rep = representative(i, j);
                if (rep == i * n + j) continue;
                const PseudoEnergyMinimum& src = t.values_[static_cast<std::size_t>(rep)];
                PseudoEnergyMinimum m = src;
                const int ri = rep / n, rj = rep % n;
                const int ni = negate[static_cast<std::size_t>(i)], nj = negate[static_cast<std::size_t>(j)];
                m.theta0 = t.axis_.nodes[static_cast<std::size_t>(i)];
                m.theta1 = t.axis_.nodes[static_cast<std::size_t>(j)];
                bool swapped = false, negated = false;
                if (ri == j && rj == i)
                    swapped = true;
                else if (ri == ni && rj == nj)
                    negated = true;
                else
                    swapped = negated = true;  // (−θ1, −θ0)
                if (swapped) {
                    std::swap(m.r0, m.r1);
                    std::swap(m.runner_up_r0, m.runner_up_r1);
                }
                if (swapped != negated) m.area = -m.area;
                t.values_[static_cast<std::size_t>(i * n + j)] = m;
            }
    }
    t.pack();
    return t;
}

void PseudoEnergyTable::pack() {
    packed_.resize(values_.size());
    for (std::size_t k = 0; k < values_.size(); ++k) {
        const PseudoEnergyMinimum& m = values_[k];
        const bool usable = m.type != SegmentType::x && m.outcome.ok();
        packed_[k] = {m.pseudo_energy, m.r0, m.r1, m.length, m.area, usable ? m.type : SegmentType::x};
    }
}

std::string PseudoEnergyTable::header_line() const {
    std::ostringstream s;
    s << "# cagd pseudo_energy table format " << kCacheFormat << " grid " << grid_.n << " placement " << to_string(grid_.placement) << " method " << to_string(method_);
    return s.str();
}

void PseudoEnergyTable::save(std::ostream& out) const {
    out << header_line() << "\n";
    out << "i,j,theta0,theta1,J,r0,r1,L,S,E,type,local_minima,runner_up,status,runner_up_r0,runner_up_r1\n";
    char buf[512];
    const int n = grid_.n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const PseudoEnergyMinimum& m = node(i, j);
            std::snprintf(buf, sizeof buf, "%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%s,%d,%.17g,%d,%.17g,%.17g\n", i, j, m.theta0, m.theta1, m.pseudo_energy, m.r0,
                          m.r1, m.length, m.area, m.strain_energy, to_string(m.type), m.local_minima, m.runner_up, static_cast<int>(m.outcome.status), m.runner_up_r0,
                          m.runner_up_r1);
            out << buf;
        }
}

void PseudoEnergyTable::save(const std::string& path) const {
    // A temporary name of this process, renamed at the end: concurrent builders never mix their lines.
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    {
        std::ofstream out(tmp);
        if (!out) fail_input("cagd::fairness::PseudoEnergyTable::save", "cannot write '" + tmp + "'");
        save(out);
    }
    std::rename(tmp.c_str(), path.c_str());
}

namespace {

// Reads the node rows after the header line; true when all n² rows were read.
bool read_node_rows(std::istream& in, int n, std::vector<PseudoEnergyMinimum>& values) {
    std::string line;
    if (!std::getline(in, line)) return false;  // column names
    values.assign(static_cast<std::size_t>(n * n), PseudoEnergyMinimum{});
    long read = 0;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string f[16];
        for (auto& x : f) std::getline(s, x, ',');
        try {
            const int i = std::stoi(f[0]), j = std::stoi(f[1]);
            if (i < 0 || j < 0 || i >= n || j >= n) return false;
            PseudoEnergyMinimum& m = values[static_cast<std::size_t>(i * n + j)];
            m.theta0 = std::stod(f[2]);
            m.theta1 = std::stod(f[3]);
            m.pseudo_energy = std::stod(f[4]);
            m.r0 = std::stod(f[5]);
            m.r1 = std::stod(f[6]);
            m.length = std::stod(f[7]);
            m.area = std::stod(f[8]);
            m.strain_energy = std::stod(f[9]);
            m.type = f[10] == "c" ? SegmentType::c : f[10] == "s" ? SegmentType::s : SegmentType::x;
            m.local_minima = std::stoi(f[11]);
            m.runner_up = std::stod(f[12]);
            m.outcome.status = static_cast<Status>(std::stoi(f[13]));
            m.runner_up_r0 = std::stod(f[14]);
            m.runner_up_r1 = std::stod(f[15]);
        } catch (const std::exception&) {
            return false;
        }
        ++read;
    }
    return read == static_cast<long>(n) * n;
}

}  // namespace

PseudoEnergyTable PseudoEnergyTable::load_or_build(const std::string& path, const AngleGrid& grid, TableMethod method, int threads) {
    const auto try_load = [&]() -> std::optional<PseudoEnergyTable> {
        PseudoEnergyTable t;
        t.grid_ = grid;
        t.method_ = method;
        t.axis_ = detail::PeriodicAxis(grid.nodes());
        std::ifstream in(path);
        std::string line;
        if (!(in && std::getline(in, line) && line == t.header_line() && read_node_rows(in, grid.n, t.values_))) return std::nullopt;
        t.pack();
        return t;
    };
    return load_or_build_locked(path, try_load, [&] {
        PseudoEnergyTable built = build(grid, method, threads, method == TableMethod::fast);
        built.save(path);
        return built;
    });
}

PseudoEnergyTable PseudoEnergyTable::load(const std::string& path) {
    const char* who = "cagd::fairness::PseudoEnergyTable::load";
    std::ifstream in(path);
    if (!in) fail_input(who, "cannot open '" + path + "'");
    std::string line;
    std::getline(in, line);
    std::istringstream h(line);
    std::string hash, cagd, paper, table, format, grid_word, placement_word, placement, method_word, method;
    int version = 0, n = 0;
    h >> hash >> cagd >> paper >> table >> format >> version >> grid_word >> n >> placement_word >> placement >> method_word >> method;
    if (hash != "#" || grid_word != "grid" || placement_word != "placement" || method_word != "method")
        fail_input(who, "'" + path + "' is not a table written by cagd energy-table (first line: '" + line + "')");
    if (version != kCacheFormat)
        fail_input(who, "'" + path + "' has table format " + std::to_string(version) + ", this build reads format " + std::to_string(kCacheFormat) +
                            "; rebuild it with cagd energy-table");
    if (n < 2) fail_input(who, "'" + path + "': grid must be >= 2, got " + std::to_string(n));
    PseudoEnergyTable t;
    t.grid_ = AngleGrid{n, parse_node_placement(placement)};
    t.method_ = method == "reference" ? TableMethod::reference : method == "nlopt" ? TableMethod::nlopt : TableMethod::fast;
    t.axis_ = detail::PeriodicAxis(t.grid_.nodes());
    if (!read_node_rows(in, n, t.values_)) fail_input(who, "'" + path + "': expected " + std::to_string(n * n) + " well-formed node rows");
    t.pack();
    return t;
}

PseudoEnergyTable::CellPosition PseudoEnergyTable::locate_cell(double theta0, double theta1) const {
    const char* who = "cagd::fairness::PseudoEnergyTable::lookup";
    require_tangent_angle(who, theta0, "theta0");
    require_tangent_angle(who, theta1, "theta1");
    if (is_undefined_node(theta0, theta1))
        fail_input(who,
                   "(" + full_precision(theta0) + ", " + full_precision(theta1) + ") is an undefined node (theta0, theta1 in {0, +-pi}): r0, r1 do not exist there (paper §4.1)");
    CellPosition c;
    axis_.locate(theta0, c.i, c.u);
    axis_.locate(theta1, c.j, c.v);
    return c;
}

namespace {

// Bilinear blend of the cell (i, j) at local (u, v) over its defined corners of type `want`
// (x: every defined corner), the weights renormalised; `at(a, b)` gives a node's value.
template <class NodeValue>
TableValue blend_cell(int n, int i, int j, double u, double v, SegmentType want, const NodeValue& at, double theta0, double theta1) {
    const int i1 = next_node(i, n), j1 = next_node(j, n);
    const int ci[4] = {i, i1, i, i1}, cj[4] = {j, j, j1, j1};
    const double w[4] = {(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v};
    TableValue out;
    double wsum = 0.0;
    for (int k = 0; k < 4; ++k) {
        const TableValue& m = at(ci[k], cj[k]);
        if (m.type == SegmentType::x) continue;  // undefined or failed node
        if (want != SegmentType::x && m.type != want) continue;
        wsum += w[k];
        out.pseudo_energy += w[k] * m.pseudo_energy;
        out.r0 += w[k] * m.r0;
        out.r1 += w[k] * m.r1;
        out.length += w[k] * m.length;
        out.area += w[k] * m.area;
    }
    if (!(wsum > 0.0)) {
        // Only possible when every corner of the cell is undefined or of the other type with
        // zero weight: fall back to the nearest defined corner of the wanted type.
        for (int k = 0; k < 4; ++k) {
            const TableValue& m = at(ci[k], cj[k]);
            if (m.type != SegmentType::x && (want == SegmentType::x || m.type == want)) return m;
        }
        fail_input("cagd::fairness::PseudoEnergyTable::lookup", "no defined table node near (" + full_precision(theta0) + ", " + full_precision(theta1) + ")");
    }
    out.pseudo_energy /= wsum;
    out.r0 /= wsum;
    out.r1 /= wsum;
    out.length /= wsum;
    out.area /= wsum;
    out.type = want;
    return out;
}

}  // namespace

TableValue PseudoEnergyTable::lookup(double theta0, double theta1, bool same_type_only) const {
    const CellPosition cell = locate_cell(theta0, theta1);  // (not a structured binding: the lambdas below capture i, j)
    const int i = cell.i, j = cell.j;
    const double u = cell.u, v = cell.v;
    const int n = grid_.n;
    const auto at = [&](int a, int b) -> const TableValue& { return packed_[static_cast<std::size_t>(a * n + b)]; };
    const SegmentType want = same_type_only ? at(u < 0.5 ? i : next_node(i, n), v < 0.5 ? j : next_node(j, n)).type : SegmentType::x;
    return blend_cell(n, i, j, u, v, want, at, theta0, theta1);
}

const char* to_string(CellRule c) {
    switch (c) {
        case CellRule::same_type: return "same_type";
        case CellRule::all_corners: return "all_corners";
        case CellRule::nearest_node_down: return "nearest_node_down";
        case CellRule::nearest_node_up: return "nearest_node_up";
    }
    return "?";
}

TableValue PseudoEnergyTable::node_value(int i, int j, double runner_up_within) const {
    const auto k = static_cast<std::size_t>(i * grid_.n + j);
    const TableValue& v = packed_[k];
    const PseudoEnergyMinimum& m = values_[k];
    if (!(runner_up_within > 0.0) || v.type == SegmentType::x || !std::isfinite(m.runner_up) || m.runner_up - m.pseudo_energy > runner_up_within) return v;
    if (!(m.runner_up_r0 > 0.0 && m.runner_up_r1 > 0.0))
        fail_input("cagd::fairness::PseudoEnergyTable::lookup", "node (" + full_precision(m.theta0) + ", " + full_precision(m.theta1) + ") has no runner-up r0, r1 stored");
    const PseudoEnergyMinimum r = measure_segment(m.theta0, m.theta1, m.runner_up_r0, m.runner_up_r1);
    return {r.pseudo_energy, r.r0, r.r1, r.length, r.area, r.type};
}

int PseudoEnergyTable::runner_up_nodes(double within) const {
    int count = 0;
    for (std::size_t k = 0; k < values_.size(); ++k)
        count += packed_[k].type != SegmentType::x && std::isfinite(values_[k].runner_up) && values_[k].runner_up - values_[k].pseudo_energy <= within;
    return count;
}

TableValue PseudoEnergyTable::lookup(double theta0, double theta1, const TableReading& reading) const {
    if (reading.is_default()) return lookup(theta0, theta1, true);
    const CellPosition cell = locate_cell(theta0, theta1);  // (not a structured binding: the lambdas below capture i, j)
    const int i = cell.i, j = cell.j;
    const double u = cell.u, v = cell.v;
    const int n = grid_.n;
    const auto at = [&](int a, int b) { return node_value(a, b, reading.runner_up_within); };
    TableValue out;
    bool done = false;
    if (reading.cell == CellRule::nearest_node_down || reading.cell == CellRule::nearest_node_up) {
        const bool up = reading.cell == CellRule::nearest_node_up;
        const auto pick = [&](int lower, double t) { return (std::abs(t - 0.5) <= 1e-9 ? up : t > 0.5) ? next_node(lower, n) : lower; };
        out = at(pick(i, u), pick(j, v));
        done = out.type != SegmentType::x;
    }
    if (!done) {
        const SegmentType want = reading.cell == CellRule::same_type ? at(u < 0.5 ? i : next_node(i, n), v < 0.5 ? j : next_node(j, n)).type : SegmentType::x;
        out = blend_cell(n, i, j, u, v, want, at, theta0, theta1);
    }
    if (reading.radii) {
        const PseudoEnergyMinimum m = measure_segment(theta0, theta1, out.r0, out.r1);
        out.pseudo_energy = m.pseudo_energy;
        out.length = m.length;
        out.area = m.area;
    }
    return out;
}

AngleMinimumTable AngleMinimumTable::build(const AngleGrid& grid, int threads) { return build(grid, nullptr, threads); }

AngleMinimumTable AngleMinimumTable::build(const AngleGrid& grid, const PseudoEnergyTable& scan_source, int threads) { return build(grid, &scan_source, threads); }

AngleMinimumTable AngleMinimumTable::build(const AngleGrid& grid, const PseudoEnergyTable* scan_source, int threads) {
    int stride = 0;
    if (scan_source) {
        const AngleGrid& g = scan_source->grid();
        if (scan_source->method() != TableMethod::fast || g.placement != NodePlacement::endpoints || (g.n - 1) % kEndAngleScanSteps != 0)
            fail_input("cagd::fairness::AngleMinimumTable::build",
                       "the scan source must be a fast table on an endpoints grid of 180·k + 1 nodes (its nodes then hold the 2° scan), got grid " + std::to_string(g.n) + " " +
                           to_string(g.placement) + " " + to_string(scan_source->method()));
        stride = (g.n - 1) / kEndAngleScanSteps;
    }
    AngleMinimumTable t;
    t.grid_ = grid;
    t.axis_ = detail::PeriodicAxis(grid.nodes());
    t.values_.assign(t.axis_.nodes.size(), AngleMinimum{});
    parallel_for(static_cast<long>(t.axis_.nodes.size()), threads,
                 [&](long k) {
                     const double theta = t.axis_.nodes[static_cast<std::size_t>(k)];
                     AngleMinimum& out = t.values_[static_cast<std::size_t>(k)];
                     const std::vector<double>* source_nodes = scan_source ? &scan_source->nodes() : nullptr;
                     const auto row = source_nodes ? std::find(source_nodes->begin(), source_nodes->end(), theta) : std::vector<double>::const_iterator{};
                     if (!source_nodes || row == source_nodes->end()) {
                         out = minimize_over_end_angle(theta);
                         return;
                     }
                     // θ is a node of the source: its scan is the source's row (θ, every stride-th θ1).
                     const int i = static_cast<int>(row - source_nodes->begin());
                     std::vector<double> ts, vs;
                     for (int j = 0; j < scan_source->grid().n; j += stride) {
                         ts.push_back((*source_nodes)[static_cast<std::size_t>(j)]);
                         vs.push_back(end_angle_energy(scan_source->node(i, j)));
                     }
                     out = refine_end_angle_scan(theta, ts, vs, [theta](double theta1) { return end_angle_energy(theta, theta1); });
                 },
                 {});
    return t;
}

AngleMinimumTable AngleMinimumTable::load_or_build(const std::string& path, const AngleGrid& grid, int threads) { return load_or_build(path, grid, nullptr, threads); }

AngleMinimumTable AngleMinimumTable::load_or_build(const std::string& path, const AngleGrid& grid, const PseudoEnergyTable& scan_source, int threads) {
    return load_or_build(path, grid, &scan_source, threads);
}

AngleMinimumTable AngleMinimumTable::load_or_build(const std::string& path, const AngleGrid& grid, const PseudoEnergyTable* scan_source, int threads) {
    std::ostringstream header;
    header << "# cagd pseudo_energy angle-minimum table format 1 grid " << grid.n << " placement " << to_string(grid.placement);
    const auto try_load = [&]() -> std::optional<AngleMinimumTable> {
        std::ifstream in(path);
        std::string line;
        if (!(in && std::getline(in, line) && line == header.str() && std::getline(in, line))) return std::nullopt;
        AngleMinimumTable t;
        t.grid_ = grid;
        t.axis_ = detail::PeriodicAxis(grid.nodes());
        while (t.values_.size() < t.axis_.nodes.size() && std::getline(in, line)) {
            // theta,theta1,J,status,message (the message last: it may hold commas)
            std::istringstream row(line);
            std::string f[4];
            for (std::string& x : f)
                if (!std::getline(row, x, ',')) break;
            AngleMinimum m;
            char* end = nullptr;
            m.theta = std::strtod(f[0].c_str(), &end);
            m.theta1 = std::strtod(f[1].c_str(), &end);
            m.pseudo_energy = std::strtod(f[2].c_str(), &end);
            m.outcome.status = static_cast<Status>(std::atoi(f[3].c_str()));
            std::getline(row, m.outcome.message);
            if (m.theta != t.axis_.nodes[t.values_.size()]) break;  // another grid: rebuild
            t.values_.push_back(m);
        }
        if (t.values_.size() != t.axis_.nodes.size()) return std::nullopt;
        return t;
    };
    return load_or_build_locked(path, try_load, [&] {
        const AngleMinimumTable t = build(grid, scan_source, threads);
        const std::string tmp = path + ".tmp." + std::to_string(::getpid());
        {
            std::ofstream out(tmp);
            if (!out) fail_input("cagd::fairness::AngleMinimumTable::load_or_build", "cannot write '" + tmp + "'");
            out << header.str() << "\ntheta,theta1,J,status,message\n";
            char buf[128];
            for (const AngleMinimum& m : t.values_) {
                std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g,%d,", m.theta, m.theta1, m.pseudo_energy, static_cast<int>(m.outcome.status));
                out << buf << m.outcome.message << "\n";
            }
        }
        std::rename(tmp.c_str(), path.c_str());
        return t;
    });
}

AngleMinimumTable AngleMinimumTable::from_energy_table(const PseudoEnergyTable& table) { return from_energy_table(table, TableReading{}); }

AngleMinimumTable AngleMinimumTable::from_energy_table(const PseudoEnergyTable& table, const TableReading& reading_in) {
    TableReading reading = reading_in;
    reading.radii = false;  // J(θ) minimises the interpolated J
    AngleMinimumTable t;
    t.grid_ = table.grid();
    t.axis_ = detail::PeriodicAxis(table.nodes());
    for (double theta : t.axis_.nodes) {
        const auto j_of = [&](double theta1) {
            if (is_undefined_node(theta, theta1)) return std::abs(theta) + std::abs(theta1) == 0.0 ? 0.0 : kInfinity;
            return table.lookup(theta, theta1, reading).pseudo_energy;
        };
        t.values_.push_back(minimize_over_end_angle(theta, j_of, std::numbers::pi / 720));
    }
    return t;
}

std::pair<double, double> AngleMinimumTable::lookup(double theta) const {
    require_tangent_angle("cagd::fairness::AngleMinimumTable::lookup", theta, "theta");
    int i = 0;
    double u = 0.0;
    axis_.locate(theta, i, u);
    const std::size_t a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(next_node(i, static_cast<int>(axis_.nodes.size())));
    const double j = (1 - u) * values_[a].pseudo_energy + u * values_[b].pseudo_energy;
    // θ1 is an angle: interpolate the wrapped difference.
    const double d = wrap_angle(values_[b].theta1 - values_[a].theta1);
    return {j, wrap_angle(values_[a].theta1 + u * d)};
}

}  // namespace cagd::fairness
