// The text file of a PseudoEnergyTable (save, load, load_or_build): the format of `cagd
// energy-table` and of the build's table cache. Line 1: "# cagd pseudo_energy table format F grid N
// placement P method M"; line 2 the column names; then one row per node (i, j), j fastest: theta0,
// theta1, J, r0, r1, L, S, E, type, local minima, runner-up J, status and the runner-up's r0, r1,
// numbers at %.17g (a load equals a build bit for bit), inf for the format's marks (undefined nodes,
// no second minimum); last the checksum line of core/checksum.hpp. F is bumped whenever a minimiser
// or the layout changes, so a stale cache is rebuilt and a foreign file refused.
//
// A load checks, before it trusts a value: the checksum; 2 ≤ N ≤ kMaxTableGrid; exactly N² rows,
// each node (i, j) once, its angles those of the grid; every field a number, NaN nowhere; a node of
// status ok has type c or s, finite J ≥ 0, E ≥ 0 and S, magnitudes r0, r1 > 0 and length L ≥ 1 (the
// unit chord), a runner-up J not below J to rounding (or inf); an undefined node (status not ok)
// has type x.
// Memory grows with the rows read, never with what the header declares.
#include "cagd/fairness/pseudo_energy_table.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>

#include "cagd/core/checksum.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/io/file_lock.hpp"
#include "cagd/io/output_file.hpp"
#include "cagd/io/user_cache.hpp"

namespace cagd::fairness {

namespace {

// 5: the runner-up's r0, r1 (TableReading::runner_up_within); 6: the checksum line; 7: the reference
// tables' local_minima and runner-up from the census (ReferenceMinimizerOptions::census).
constexpr int kTableFileFormat = 7;

}  // namespace

std::string PseudoEnergyTable::header_line() const {
    std::ostringstream s;
    s << "# cagd pseudo_energy table format " << kTableFileFormat << " grid " << grid_.n << " placement "
      << to_string(grid_.placement) << " method " << to_string(method_);
    return s.str();
}

void PseudoEnergyTable::save(std::ostream& out) const {
    std::string text = header_line() + "\n";
    text += "i,j,theta0,theta1,J,r0,r1,L,S,E,type,local_minima,runner_up,status,runner_up_r0,runner_up_r1\n";
    char buf[512];
    const int n = grid_.n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const PseudoEnergyMinimum& m = node(i, j);
            std::snprintf(buf, sizeof buf,
                          "%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%s,%d,%.17g,%d,%.17g,%.17g\n", i, j,
                          m.theta0, m.theta1, m.pseudo_energy, m.r0, m.r1, m.length, m.area, m.strain_energy,
                          to_string(m.type), m.local_minima, m.runner_up, static_cast<int>(m.outcome.status),
                          m.runner_up_r0, m.runner_up_r1);
            text += buf;
        }
    out << text << checksum_line(text);
}

void PseudoEnergyTable::save(const std::string& path) const {
    // io/output_file.hpp: a temporary file beside it, renamed at the end (concurrent builders never
    // mix their lines; a failed write keeps the old file and throws OutputError); a device or an open
    // descriptor is written in place.
    OutputFile out(path, "table");
    save(out.stream());
    out.commit();
}

namespace {

// The text of the table file `path`, bounded by the grid its header declares (grid n: the column
// names, n² rows, the checksum line); a header without a grid is left to parse_table to name.
std::string table_text(const std::string& path, const char* who) {
    return read_table_text(path, who, [&](const std::string& header) -> long {
        std::istringstream h(header);
        std::string word;
        while (h >> word && word != "grid") {}
        long n = 0;
        if (!(h >> n)) return -1;
        if (n < 2 || n > kMaxTableGrid)
            fail_input(who, "'" + path + "': grid " + std::to_string(n) + "; it must be in [2, " +
                                std::to_string(kMaxTableGrid) + "]");
        return n * n + 2;
    });
}

// The table in `text` (the file `source`), every value checked as the header comment says.
struct ParsedTable {
    AngleGrid grid;
    TableMethod method = TableMethod::fast;
    std::vector<PseudoEnergyMinimum> values;
};

ParsedTable parse_table(const std::string& text, const std::string& source) {
    const char* who = "cagd::fairness::PseudoEnergyTable::load";
    const std::string_view content = checked_content(text, source);
    std::istringstream in{std::string(content)};
    std::string line;
    std::getline(in, line);
    std::istringstream h(line);
    std::string hash, cagd, paper, table, format, grid_word, placement_word, placement, method_word, method;
    int version = 0, n = 0;
    h >> hash >> cagd >> paper >> table >> format >> version >> grid_word >> n >> placement_word >> placement >>
        method_word >> method;
    if (hash != "#" || grid_word != "grid" || placement_word != "placement" || method_word != "method")
        fail_input(
            who, "'" + source + "' is not a table written by cagd energy-table (first line: '" + excerpt(line) + "')");
    if (version != kTableFileFormat)
        fail_input(who, "'" + source + "' has table format " + std::to_string(version) + ", this build reads format " +
                            std::to_string(kTableFileFormat) + "; rebuild it with cagd energy-table");
    if (n < 2 || n > kMaxTableGrid)
        fail_input(who, "'" + source + "': grid " + std::to_string(n) + "; it must be in [2, " +
                            std::to_string(kMaxTableGrid) + "]");
    ParsedTable t;
    t.grid = AngleGrid{n, parse_node_placement(placement)};
    if (method != "fast" && method != "reference" && method != "nlopt")
        fail_input(who, "'" + source + "': unknown method '" + excerpt(method) + "'");
    t.method = method == "reference" ? TableMethod::reference
               : method == "nlopt"   ? TableMethod::nlopt
                                     : TableMethod::fast;
    const std::vector<double> nodes = t.grid.nodes();
    std::getline(in, line);  // column names
    std::vector<char> seen(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0);
    std::vector<std::pair<std::size_t, PseudoEnergyMinimum>> rows;
    int line_no = 2;
    static const char* const kColumns[16] = {
        "i", "j", "theta0", "theta1",       "J",         "r0",     "r1",           "L",
        "S", "E", "type",   "local_minima", "runner_up", "status", "runner_up_r0", "runner_up_r1"};
    while (std::getline(in, line)) {
        ++line_no;
        const std::string where = "'" + source + "':" + std::to_string(line_no) + ": ";
        const std::vector<std::string> f = split_fields(line);
        if (f.size() != 16) fail_input(who, where + std::to_string(f.size()) + " fields, a node row has 16");
        double v[16] = {};
        for (int k = 0; k < 16; ++k) {
            if (k == 10) continue;  // the type
            if (!parse_decimal(f[static_cast<std::size_t>(k)], v[k]) || std::isnan(v[k]))
                fail_input(who,
                           where + kColumns[k] + " '" + excerpt(f[static_cast<std::size_t>(k)]) + "' is not a number");
        }
        const auto bad = [&](int k, const std::string& rule) {
            fail_input(who, where + kColumns[k] + " = " + f[static_cast<std::size_t>(k)] + ": " + rule);
        };
        const auto integer = [&](int k, double lo, double hi) {
            if (!(v[k] >= lo && v[k] <= hi && v[k] == std::floor(v[k])))
                bad(k, "an integer in [" + format_number(lo) + ", " + format_number(hi) + "] is expected");
            return static_cast<int>(v[k]);
        };
        const int i = integer(0, 0, n - 1), j = integer(1, 0, n - 1);
        const std::size_t index =
            static_cast<std::size_t>(i) * static_cast<std::size_t>(n) + static_cast<std::size_t>(j);
        if (seen[index])
            fail_input(who, where + "node (" + std::to_string(i) + ", " + std::to_string(j) + ") is given twice");
        seen[index] = 1;
        if (std::abs(v[2] - nodes[static_cast<std::size_t>(i)]) > 1e-12)
            bad(2, "the grid's angle of node i is " + full_precision(nodes[static_cast<std::size_t>(i)]));
        if (std::abs(v[3] - nodes[static_cast<std::size_t>(j)]) > 1e-12)
            bad(3, "the grid's angle of node j is " + full_precision(nodes[static_cast<std::size_t>(j)]));
        PseudoEnergyMinimum m;
        m.theta0 = v[2], m.theta1 = v[3], m.pseudo_energy = v[4], m.r0 = v[5], m.r1 = v[6], m.length = v[7],
        m.area = v[8], m.strain_energy = v[9];
        const std::string& type = f[10];
        if (type != "c" && type != "s" && type != "x") bad(10, "c, s or x is expected");
        m.type = type == "c" ? SegmentType::c : type == "s" ? SegmentType::s : SegmentType::x;
        m.local_minima = integer(11, 0, 1e6);
        m.runner_up = v[12];
        m.outcome.status = static_cast<Status>(integer(13, 0, static_cast<int>(Status::not_representable)));
        m.runner_up_r0 = v[14], m.runner_up_r1 = v[15];
        if (m.outcome.ok()) {
            if (m.type == SegmentType::x) bad(10, "a node of status ok has type c or s");
            if (!(std::isfinite(m.pseudo_energy) && m.pseudo_energy >= 0))
                bad(4, "J of a defined node is finite and >= 0");
            for (int k : {5, 6})
                if (!(std::isfinite(v[k]) && v[k] > 0)) bad(k, "a tangent magnitude is finite and > 0");
            if (!(std::isfinite(m.length) && m.length >= 1.0 - 1e-9))
                bad(7, "the length of a unit-chord segment is finite and >= 1");
            if (!std::isfinite(m.area)) bad(8, "S is finite");
            if (!(std::isfinite(m.strain_energy) && m.strain_energy >= 0)) bad(9, "E is finite and >= 0");
            if (!(m.runner_up >= m.pseudo_energy - 1e-12 * (1 + m.pseudo_energy)))
                bad(12, "the runner-up minimum is not below J, to rounding (inf: none)");
            for (int k : {14, 15})
                if (!(std::isfinite(v[k]) && v[k] >= 0)) bad(k, "a runner-up magnitude is finite and >= 0");
        } else {
            if (m.type != SegmentType::x) bad(10, "an undefined node (status not ok) has type x");
            if (!(m.pseudo_energy >= 0)) bad(4, "J is >= 0 or inf");
        }
        rows.emplace_back(index, m);
    }
    if (rows.size() != seen.size())
        fail_input(who, "'" + source + "': " + std::to_string(rows.size()) + " node rows, the grid " +
                            std::to_string(n) + " has " + std::to_string(seen.size()));
    t.values.assign(seen.size(), PseudoEnergyMinimum{});
    for (auto& [index, m] : rows) t.values[index] = std::move(m);
    return t;
}

}  // namespace

PseudoEnergyTable PseudoEnergyTable::load_or_build(const std::string& path, const AngleGrid& grid, TableMethod method,
                                                   int threads) {
    return load_or_build(path, grid, method, threads, false);
}

PseudoEnergyTable PseudoEnergyTable::user_cached(const AngleGrid& grid, TableMethod method, int threads) {
    const std::optional<std::string> dir = user_cache_directory();
    if (!dir) return build(grid, method, threads, method == TableMethod::fast);
    const std::string name = std::string("pseudo-energy-table-") + std::to_string(grid.n) + "-" +
                             to_string(grid.placement) + "-" + to_string(method) + ".txt";
    return load_or_build(*dir + "/" + name, grid, method, threads, true);
}

PseudoEnergyTable PseudoEnergyTable::load_or_build(const std::string& path, const AngleGrid& grid, TableMethod method,
                                                   int threads, bool user_cache) {
    const auto try_load = [&](std::string& why) -> std::optional<PseudoEnergyTable> {
        std::ifstream probe(path);
        if (!probe) return std::nullopt;
        try {
            ParsedTable p = parse_table(table_text(path, "cagd::fairness::PseudoEnergyTable::load_or_build"), path);
            if (p.grid.n != grid.n || p.grid.placement != grid.placement ||
                p.method != method) {  // another table: rebuilt
                why = "another table (grid " + std::to_string(p.grid.n) + ", another placement or method)";
                return std::nullopt;
            }
            PseudoEnergyTable t;
            t.grid_ = grid;
            t.method_ = method;
            t.axis_ = detail::PeriodicAxis(grid.nodes());
            t.values_ = std::move(p.values);
            t.pack();
            return t;
        } catch (const InvalidInput& e) {  // damaged, or of another format: rebuilt
            why = e.what();
            return std::nullopt;
        }
    };
    return load_or_build_locked(path, try_load, [&] {
        if (!user_cache) {
            PseudoEnergyTable built = build(grid, method, threads, method == TableMethod::fast);
            built.save(path);
            return built;
        }
        announce_cache_build(path, "the " + std::to_string(grid.n) + " x " + std::to_string(grid.n) +
                                       " pseudo-energy table (" + to_string(method) + " minimiser)");
        PseudoEnergyTable built = build(grid, method, threads, method == TableMethod::fast, cache_build_progress());
        try {
            built.save(path);
        } catch (const OutputError&) {   // a failed write: the table stays in memory, the cache as it was
        } catch (const InvalidInput&) {  // a place no file can be made (a directory there): likewise
        }
        return built;
    });
}

PseudoEnergyTable PseudoEnergyTable::load(const std::string& path) {
    ParsedTable p = parse_table(table_text(path, "cagd::fairness::PseudoEnergyTable::load"), path);
    PseudoEnergyTable t;
    t.grid_ = p.grid;
    t.method_ = p.method;
    t.axis_ = detail::PeriodicAxis(t.grid_.nodes());
    t.values_ = std::move(p.values);
    t.pack();
    return t;
}

}  // namespace cagd::fairness
