// libFuzzer target: every reader of user input on arbitrary bytes. The first byte picks the reader
// (0xF0 planar and 0xF1 space table files, with their checksum line appended by this harness so
// that the value checks behind it are reached; 0xF2 a curve document, 0xF3 a surface document
// (export/curve_json.hpp); 0xF4 benchmark parts (compare/interpolant_benchmark.hpp: parts split at
// form feeds, the token PLAN replaced by a small plan's fingerprint and each closed by its checksum
// line, so that the records behind them are reached); bytes from 0xF5 up: a table file by their
// last bit; below 0xF0: modulo 7), the rest is its text:
//   0 points (core/point_csv)   1 values (λ files)   2 numeric tables (curve CSV of cagd analyze)
//   3 m-vectors (sb2_locality)  4 knot-difference lists (degree 2 or 3)   5 span-shape lists
//   6 method parameters: the registry's typed options of a method (second byte), "name=value" lines
// Contract checked: each returns (points: 1+ rows of 2 or 3 finite columns; values and tables:
// finite numbers, rows as long as the header; merged parts: as many runs as the units line, finite
// errors) or throws cagd::InvalidInput; nothing else escapes,
// and ASan/UBSan see no memory error or undefined behaviour. Seed corpus: tests/fuzz/corpus/readers.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include <unistd.h>

#include <fstream>

#include "cagd/compare/interpolant_benchmark.hpp"
#include "cagd/core/checksum.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/export/bspline_form.hpp"
#include "cagd/export/curve_json.hpp"
#include "cagd/fairness/pseudo_energy_table.hpp"
#include "cagd/fairness/space_pseudo_energy_table.hpp"
#include "cagd/intrinsic/curvature_profile_design.hpp"
#include "cagd/intrinsic/knot_difference_list.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "cagd/methods/method_registry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace cagd;
    if (size < 1) return 0;
    const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
    if (data[0] == 0xF2 || data[0] == 0xF3) {
        std::istringstream in(text);
        try {
            if (data[0] == 0xF2) {
                const exports::CurveDocument d = exports::read_curve_json(in, "fuzz");
                const exports::BezierPieces& p = d.form.pieces;
                if (p.pieces() < 1 || p.degree < 1 || p.degree > exports::kMaxDocumentDegree ||
                    p.control.rows() != static_cast<Eigen::Index>(p.pieces()) * (p.degree + 1) ||
                    !p.control.allFinite() || exports::first_unjoined_piece(p) != 0 || !d.provenance.points.allFinite())
                    std::abort();
            } else {
                const exports::SurfaceDocument d = exports::read_surface_json(in, "fuzz");
                const exports::BezierSurfacePieces& p = d.form.pieces;
                if (p.nets.size() != static_cast<std::size_t>(p.cells_u()) * static_cast<std::size_t>(p.cells_v()))
                    std::abort();
                for (const surface::ControlNet& net : p.nets)
                    for (const Eigen::MatrixXd& c : net)
                        if (c.rows() != p.degree_u + 1 || c.cols() != p.degree_v + 1 || !c.allFinite()) std::abort();
            }
        } catch (const InvalidInput&) {}
        return 0;
    }
    if (data[0] == 0xF4) {
        static const compare::BenchmarkPlan plan = [] {
            compare::BenchmarkPlan p;
            p.truth.sizes = {6, 12};
            p.truth.families = {"circle", "helix"};
            p.truth.methods = {"cubic-b", "spiro"};
            p.random.sizes = {8};
            p.random.sets = 3;
            p.random.methods = p.truth.methods;
            return p;
        }();
        static const std::string fingerprint = compare::benchmark_plan_fingerprint(plan);
        std::vector<std::pair<std::string, std::string>> parts;
        std::istringstream split(text);
        for (std::string part; std::getline(split, part, '\f');) {
            for (std::size_t at = part.find("PLAN"); at != std::string::npos; at = part.find("PLAN", at))
                part.replace(at, 4, fingerprint);
            parts.emplace_back("part " + std::to_string(parts.size() + 1), part + checksum_line(part));
        }
        try {
            const compare::BenchmarkResults r = compare::merge_benchmark_parts(plan, parts);
            for (const compare::TruthRun& run : r.truth)
                for (int e = 0; e < 5; ++e)
                    if (!std::isfinite(compare::truth_error(run.errors, e))) std::abort();
            for (const compare::RandomSetSummary& s : r.random)
                if (s.sets != plan.random.sets) std::abort();
        } catch (const InvalidInput&) {}
        return 0;
    }
    if (data[0] >= 0xF0) {  // a table file: loaded from a file of this process
        static const std::string path = "/tmp/cagd-fuzz-table-" + std::to_string(::getpid()) + ".txt";
        static const struct Remove {
            ~Remove() { ::unlink(path.c_str()); }
        } remove_at_exit;
        std::ofstream(path, std::ios::binary) << text << checksum_line(text);
        try {
            if (data[0] & 1) {
                const fairness::SpacePseudoEnergyTable t = fairness::SpacePseudoEnergyTable::load(path);
                if (t.grid().n_theta < 2) std::abort();
            } else {
                const fairness::PseudoEnergyTable t = fairness::PseudoEnergyTable::load(path);
                if (t.grid().n < 2 || t.grid().n > fairness::kMaxTableGrid) std::abort();
            }
        } catch (const InvalidInput&) {}
        return 0;
    }
    const int reader = data[0] % 7;
    std::istringstream in(text);
    try {
        switch (reader) {
            case 0: {
                const PointList p = read_points_csv(in, "fuzz");
                if (p.rows() < 1 || (p.cols() != 2 && p.cols() != 3) || !p.allFinite()) std::abort();
                break;
            }
            case 1:
                for (double v : read_values_csv(in, "fuzz"))
                    if (!std::isfinite(v)) std::abort();
                break;
            case 2: {
                const NumericTable t = read_numeric_table(in, "fuzz");
                for (const auto& row : t.rows) {
                    if (row.size() != t.header.size()) std::abort();
                    for (double v : row)
                        if (!std::isfinite(v)) std::abort();
                }
                break;
            }
            case 3: locality::parse_m_vector(text); break;
            case 4:
                intrinsic::parse_knot_difference_list(text.substr(text.empty() ? 0 : 1),
                                                      text.empty() || text[0] % 2 ? 2 : 3);
                break;
            case 5: intrinsic::parse_span_shapes(text); break;
            case 6: {
                if (text.empty()) break;
                const methods::Method& m =
                    methods::registry()[static_cast<unsigned char>(text[0]) % methods::registry().size()];
                methods::ParameterText given;
                std::istringstream lines(text.substr(1));
                std::string line;
                while (std::getline(lines, line)) {
                    const auto eq = line.find('=');
                    if (eq != std::string::npos) given[line.substr(0, eq)] = line.substr(eq + 1);
                }
                methods::parse_parameter_values(m.name, m.parameters, given);
                break;
            }
        }
    } catch (const InvalidInput&) {}
    return 0;
}
