#include "cagd/fairness/angle_minimum_table.hpp"

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

#include "cagd/core/checksum.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/io/file_lock.hpp"
#include "cagd/io/output_file.hpp"

namespace cagd::fairness {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

using detail::next_node;

AngleMinimumTable AngleMinimumTable::build(const AngleGrid& grid, int threads) { return build(grid, nullptr, threads); }

AngleMinimumTable AngleMinimumTable::build(const AngleGrid& grid, const PseudoEnergyTable& scan_source, int threads) {
    return build(grid, &scan_source, threads);
}

AngleMinimumTable AngleMinimumTable::build(const AngleGrid& grid, const PseudoEnergyTable* scan_source, int threads) {
    int stride = 0;
    if (scan_source) {
        const AngleGrid& g = scan_source->grid();
        if (scan_source->method() != TableMethod::fast || g.placement != NodePlacement::endpoints ||
            (g.n - 1) % kEndAngleScanSteps != 0)
            fail_input("cagd::fairness::AngleMinimumTable::build",
                       "the scan source must be a fast table on an endpoints grid of 180·k + 1 nodes (its nodes then "
                       "hold the 2° scan), got grid " +
                           std::to_string(g.n) + " " + to_string(g.placement) + " " + to_string(scan_source->method()));
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
                     const auto row = source_nodes ? std::find(source_nodes->begin(), source_nodes->end(), theta)
                                                   : std::vector<double>::const_iterator{};
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
                     out = refine_end_angle_scan(theta, ts, vs,
                                                 [theta](double theta1) { return end_angle_energy(theta, theta1); });
                 },
                 {});
    return t;
}

AngleMinimumTable AngleMinimumTable::load_or_build(const std::string& path, const AngleGrid& grid, int threads) {
    return load_or_build(path, grid, nullptr, threads);
}

AngleMinimumTable AngleMinimumTable::load_or_build(const std::string& path, const AngleGrid& grid,
                                                   const PseudoEnergyTable& scan_source, int threads) {
    return load_or_build(path, grid, &scan_source, threads);
}

AngleMinimumTable AngleMinimumTable::load_or_build(const std::string& path, const AngleGrid& grid,
                                                   const PseudoEnergyTable* scan_source, int threads) {
    // The cache file: a header line, the column names, one row per node, the checksum line
    // (core/checksum.hpp). A damaged, foreign or stale file, or one whose values leave their domain
    // (a node angle off the grid, θ1 outside [−π, π], J not finite and ≥ 0 where the status is ok),
    // is rebuilt.
    std::ostringstream header;
    header << "# cagd pseudo_energy angle-minimum table format 2 grid " << grid.n << " placement "
           << to_string(grid.placement);
    const auto try_load = [&](std::string& why) -> std::optional<AngleMinimumTable> {
        if (!std::ifstream(path)) return std::nullopt;
        // Lines after the header: the column names, a row per node, the checksum line.
        const auto lines_after = [](const std::string& h) -> long {
            const std::size_t at = h.find(" grid ");
            const long n = at == std::string::npos ? 0 : std::atol(h.c_str() + at + 6);
            return n >= 2 && n <= 10'000'000 ? n + 2 : -1;  // a row per node, far beyond any grid in use
        };
        std::istringstream in;
        try {
            in.str(std::string(
                checked_content(read_table_text(path, "cagd::fairness::AngleMinimumTable", lines_after), path)));
        } catch (const InvalidInput& e) {
            why = e.what();
            return std::nullopt;
        }
        std::string line;
        if (!(std::getline(in, line) && line == header.str() && std::getline(in, line))) return std::nullopt;
        AngleMinimumTable t;
        t.grid_ = grid;
        t.axis_ = detail::PeriodicAxis(grid.nodes());
        while (t.values_.size() < t.axis_.nodes.size() && std::getline(in, line)) {
            // theta,theta1,J,status,message (the message last: it may hold commas)
            std::istringstream row(line);
            std::string f[4];
            for (std::string& x : f)
                if (!std::getline(row, x, ',')) return std::nullopt;
            AngleMinimum m;
            double status = 0;
            if (!parse_decimal(f[0], m.theta) || !parse_decimal(f[1], m.theta1) ||
                !parse_decimal(f[2], m.pseudo_energy) || !parse_decimal(f[3], status))
                return std::nullopt;
            if (!(status >= 0 && status <= static_cast<int>(Status::not_representable) && status == std::floor(status)))
                return std::nullopt;
            m.outcome.status = static_cast<Status>(static_cast<int>(status));
            std::getline(row, m.outcome.message);
            if (m.theta != t.axis_.nodes[t.values_.size()]) return std::nullopt;  // another grid
            if (m.outcome.ok() && !(std::isfinite(m.pseudo_energy) && m.pseudo_energy >= 0 &&
                                    m.theta1 >= -std::numbers::pi - 1e-12 && m.theta1 <= std::numbers::pi + 1e-12))
                return std::nullopt;
            t.values_.push_back(m);
        }
        if (t.values_.size() != t.axis_.nodes.size() || std::getline(in, line)) return std::nullopt;
        return t;
    };
    return load_or_build_locked(path, try_load, [&] {
        const AngleMinimumTable t = build(grid, scan_source, threads);
        std::string text = header.str() + "\ntheta,theta1,J,status,message\n";
        char buf[128];
        for (const AngleMinimum& m : t.values_) {
            std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g,%d,", m.theta, m.theta1, m.pseudo_energy,
                          static_cast<int>(m.outcome.status));
            text += buf + one_line(m.outcome.message) + "\n";
        }
        OutputFile out(path, "table");  // io/output_file.hpp: written whole or not at all
        out.stream() << text << checksum_line(text);
        out.commit();
        return t;
    });
}

AngleMinimumTable AngleMinimumTable::from_energy_table(const PseudoEnergyTable& table) {
    return from_energy_table(table, TableReading{});
}

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
    const std::size_t a = static_cast<std::size_t>(i),
                      b = static_cast<std::size_t>(next_node(i, static_cast<int>(axis_.nodes.size())));
    const double j = (1 - u) * values_[a].pseudo_energy + u * values_[b].pseudo_energy;
    // θ1 is an angle: interpolate the wrapped difference.
    const double d = wrap_angle(values_[b].theta1 - values_[a].theta1);
    return {j, wrap_angle(values_[a].theta1 + u * d)};
}

}  // namespace cagd::fairness
