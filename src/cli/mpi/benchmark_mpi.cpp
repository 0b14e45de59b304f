// cagd_benchmark_mpi: the interpolant benchmark (`cagd benchmark`) on MPI ranks, for plans that
// outgrow one machine (every family × many sizes × every method × many random sets).
//   mpirun -np R cagd_benchmark_mpi --out DIR [the plan's options of cagd benchmark] [--timing-out FILE]
// Rank r computes share r of R of the work (compare/work_share.hpp) with --threads threads, sends
// its part (compare/interpolant_benchmark.hpp) to rank 0, which merges the parts and writes DIR as
// `cagd benchmark` does (io/output_file.hpp: whole or not at all; checked by rank 0 before the
// work). DIR is the same, byte for byte, for any R and thread count, and equals what
// `cagd benchmark` writes with the same options.
// Exit 0 success, 2 bad arguments or output place (one line on stderr from rank 0), 1 a failure while
// writing (the old directory kept).
#include <mpi.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cagd/compare/interpolant_benchmark.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/io/output_file.hpp"
#include "cli/benchmark_options.hpp"

using namespace cagd;

namespace {

// Rank 0's verdict, sent to every rank so that all stop together: 0 go on, else the exit code.
int agree(int code) {
    MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return code;
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    CLI::App app{
        "The interpolant benchmark of cagd on MPI ranks: each rank a share, rank 0 writes --out as cagd benchmark does",
        "cagd_benchmark_mpi"};
    cli::BenchmarkPlanArgs args;
    std::string out_path, timing_path;
    app.add_option("--out", out_path, "directory for the benchmark's files (as cagd benchmark --out)")->required();
    app.add_option("--timing-out", timing_path, "CSV file for the random sets' run times; absent: not written");
    cli::add_benchmark_plan_options(&app, args);
    compare::BenchmarkPlan plan;
    std::unique_ptr<OutputDirectory> out;
    std::optional<OutputFile> timing;
    int code = 0;
    try {
        app.parse(argc, argv);
        plan = cli::benchmark_plan(args);
        if (rank == 0) {
            out = std::make_unique<OutputDirectory>(out_path);  // checked before the work
            if (!timing_path.empty()) timing.emplace(timing_path, "--timing-out");
        }
    } catch (const CLI::Success&) {
        if (rank == 0) std::cout << app.help();
        code = -1;
    } catch (const CLI::Error& e) {
        if (rank == 0) std::cerr << "cagd_benchmark_mpi: " << e.what() << "\n";
        code = 2;
    } catch (const InvalidInput& e) {
        if (rank == 0) std::cerr << e.what() << "\n";
        code = 2;
    }
    if (rank == 0 && code != 0) out.reset(), timing.reset();
    if ((code = agree(code)) != 0) {  // every rank stops if rank 0 refused the arguments or the output
        MPI_Finalize();
        return code < 0 ? 0 : code;
    }
    const compare::WorkShare share{rank, size};
    const std::string part =
        compare::benchmark_part_text(plan, share, compare::run_benchmark(plan, share, args.threads));
    int length = static_cast<int>(part.size());
    std::vector<int> lengths(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<char> all;
    if (rank == 0) {
        long total = 0;
        for (int r = 0; r < size; ++r)
            offsets[static_cast<std::size_t>(r)] = static_cast<int>(total),
            total += lengths[static_cast<std::size_t>(r)];
        if (total > 2147483647L) {  // MPI counts are int: a plan this large is split into --part runs instead
            std::cerr << "cagd_benchmark_mpi: the parts hold " << total
                      << " bytes together, more than one gather carries; use cagd benchmark --part and --merge\n";
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
        all.resize(static_cast<std::size_t>(total));
    }
    MPI_Gatherv(part.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
    int status = 0;
    if (rank == 0) {
        try {
            std::vector<std::pair<std::string, std::string>> parts;
            for (int r = 0; r < size; ++r)
                parts.emplace_back("rank " + std::to_string(r),
                                   std::string(all.data() + offsets[static_cast<std::size_t>(r)],
                                               static_cast<std::size_t>(lengths[static_cast<std::size_t>(r)])));
            const compare::BenchmarkResults results = compare::merge_benchmark_parts(plan, parts);
            cli::stage_benchmark_files(*out, compare::benchmark_files(plan, results));
            out->commit();
            if (timing) {
                timing->stream() << compare::benchmark_timing_csv(results);
                timing->commit();
            }
        } catch (const std::exception& e) {
            std::cerr << "cagd_benchmark_mpi: " << e.what() << "\n";
            status = 1;
        }
    }
    MPI_Finalize();
    return status;
}
