// The text file of a PseudoEnergyTable (save, load, load_or_build): the format of `cagd
// energy-table` and of the build's table cache. Line 1: "# cagd pseudo_energy table format F grid N
// placement P method M"; then one row per node (i, j), j fastest: theta0, theta1, J, r0, r1, L, S,
// type and the runner-up minimum, numbers at %.17g (a load equals a build bit for bit), inf for
// the format's marks (undefined nodes, no second minimum). F is bumped whenever a minimiser or the
// layout changes, so a stale cache is rebuilt and a foreign file refused.
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
#include "cagd/core/output_file.hpp"

namespace cagd::fairness {

namespace {

constexpr int kCacheFormat = 5;  // 5: the runner-up's r0, r1 (TableReading::runner_up_within)

}  // namespace

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
    // core/output_file.hpp: a temporary file beside it, renamed at the end (concurrent builders never
    // mix their lines; a failed write keeps the old file and throws OutputError); a device or an open
    // descriptor is written in place.
    OutputFile out(path, "table");
    save(out.stream());
    out.commit();
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

}  // namespace cagd::fairness
