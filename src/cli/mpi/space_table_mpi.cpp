// cagd_space_table_mpi: the space pseudo-energy table (fairness/space_pseudo_energy_table.hpp) on
// MPI, for grids that outgrow one machine (the 1° table: 180 × 180 × 360 nodes, hours of CPU).
//   mpirun -np R cagd_space_table_mpi --n-theta N --n-phi M [--method fast|reference] [--threads T] --out FILE
// Rank r computes the block [r·K/R, (r+1)·K/R) of the K symmetry orbits with T threads, rank 0
// gathers them, assembles the table and writes FILE (io/output_file.hpp: `-` is standard output,
// a device is written in place, a regular file replaced whole; the place is checked by rank 0 before
// the work). The result is the same, byte for byte, for any R and T (each node is computed on its
// own), and equals SpacePseudoEnergyTable::build.
// Exit 0 success, 2 bad arguments or output place (one line on stderr from rank 0), 1 a failure while
// writing (the old file kept).
#include <mpi.h>

#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/fairness/space_pseudo_energy_table.hpp"
#include "cagd/io/output_file.hpp"

using namespace cagd;
using namespace cagd::fairness;

namespace {

constexpr int kFields = 6;  // J, r0, r1, L, type, ok: what assemble() reads of a minimum

struct Args {
    SpaceAngleGrid grid{0, 0};
    TableMethod method = TableMethod::fast;
    int threads = 1;
    std::string out;
};

int parse_int(const std::string& option, const std::string& text, int lo, int hi) {
    std::size_t used = 0;
    int v = 0;
    try {
        v = std::stoi(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || v < lo || v > hi)
        fail_input("cagd_space_table_mpi", option + " '" + text + "': expected an integer in [" + std::to_string(lo) +
                                               ", " + std::to_string(hi) + "]");
    return v;
}

Args parse(int argc, char** argv) {
    Args a;
    for (int i = 1; i < argc; ++i) {
        const std::string o = argv[i];
        if (i + 1 >= argc)
            fail_input(
                "cagd_space_table_mpi",
                o + " needs a value (usage: --n-theta N --n-phi M [--method fast|reference] [--threads T] --out FILE)");
        const std::string v = argv[++i];
        if (o == "--n-theta")
            a.grid.n_theta = parse_int(o, v, 2, 2000);
        else if (o == "--n-phi")
            a.grid.n_phi = parse_int(o, v, 4, 4000);
        else if (o == "--threads")
            a.threads = parse_int(o, v, 1, 1024);
        else if (o == "--method") {
            if (v != "fast" && v != "reference")
                fail_input("cagd_space_table_mpi", "--method '" + v + "': expected fast or reference");
            a.method = v == "fast" ? TableMethod::fast : TableMethod::reference;
        } else if (o == "--out")
            a.out = v;
        else
            fail_input("cagd_space_table_mpi", "unknown option '" + o + "'");
    }
    if (a.grid.n_theta == 0 || a.grid.n_phi == 0 || a.out.empty())
        fail_input("cagd_space_table_mpi", "--n-theta, --n-phi and --out are required");
    SpacePseudoEnergyTable::orbit_nodes(a.grid);  // checks the grid
    return a;
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    Args a;
    std::unique_ptr<OutputFile> out;
    int bad = 0;
    try {
        a = parse(argc, argv);
        if (rank == 0) out = std::make_unique<OutputFile>(a.out, "--out");  // checked before the work
    } catch (const InvalidInput& e) {
        if (rank == 0) std::cerr << e.what() << "\n";
        bad = 1;
    }
    MPI_Bcast(&bad, 1, MPI_INT, 0, MPI_COMM_WORLD);  // every rank stops if rank 0 refused the output
    if (bad != 0) {
        MPI_Finalize();
        return 2;
    }
    const long orbits = static_cast<long>(SpacePseudoEnergyTable::orbit_nodes(a.grid).size());
    const auto block_start = [&](int r) { return orbits * r / size; };
    const long begin = block_start(rank), end = block_start(rank + 1);
    const std::vector<SpacePseudoEnergyMinimum> mine =
        SpacePseudoEnergyTable::compute_orbits(a.grid, a.method, begin, end, a.threads);
    std::vector<double> packed;
    packed.reserve(mine.size() * kFields);
    for (const SpacePseudoEnergyMinimum& m : mine)
        packed.insert(packed.end(), {m.pseudo_energy, m.r0, m.r1, m.length,
                                     static_cast<double>(static_cast<int>(m.type)), m.outcome.ok() ? 1.0 : 0.0});
    std::vector<int> counts(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
    for (int r = 0; r < size; ++r) {
        counts[static_cast<std::size_t>(r)] = static_cast<int>((block_start(r + 1) - block_start(r)) * kFields);
        offsets[static_cast<std::size_t>(r)] = static_cast<int>(block_start(r) * kFields);
    }
    std::vector<double> all(rank == 0 ? static_cast<std::size_t>(orbits * kFields) : 0);
    MPI_Gatherv(packed.data(), static_cast<int>(packed.size()), MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                MPI_DOUBLE, 0, MPI_COMM_WORLD);
    int status = 0;
    if (rank == 0) {
        std::vector<SpacePseudoEnergyMinimum> minima(static_cast<std::size_t>(orbits));
        for (std::size_t q = 0; q < minima.size(); ++q) {
            const double* f = all.data() + q * kFields;
            SpacePseudoEnergyMinimum& m = minima[q];
            m.pseudo_energy = f[0], m.r0 = f[1], m.r1 = f[2], m.length = f[3];
            m.type = static_cast<SegmentType>(static_cast<int>(f[4]));
            if (f[5] == 0.0) m.outcome = {Status::no_convergence, "not converged"};
        }
        try {
            SpacePseudoEnergyTable::assemble(a.grid, a.method, minima).save(out->stream());
            out->commit();
        } catch (const std::exception& e) {
            std::cerr << e.what() << "\n";
            status = 1;
        }
    }
    MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
    MPI_Finalize();
    return status;
}
