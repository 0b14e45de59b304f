// The `cagd` command: the library on the user's own points. Each subcommand lives in its own
// cli/<name>_command.cpp (cli/commands.hpp); this file only wires them. The contract:
//   exit 0  success;
//   exit 1  a numerical outcome for valid input: no solution, no convergence, or a result that is
//           not representable (any non-finite value: it is never written out);
//   exit 2  bad input or usage.
// Every message is one line on stderr naming the file:line or the option and its value; every
// exception is caught here. Output appears only after success (io/output_file.hpp: `-` and open
// descriptors written through, regular files replaced atomically, devices and pipes written
// directly; a failed write is exit 1 and keeps the old file). INT, TERM, HUP and PIPE remove the
// temporary files before the process ends by the signal. Sizes are checked
// against their limits (in --help) before anything is allocated. Progress goes to stderr for long
// work, only when stderr is a terminal and --quiet is not given. CMake defines CAGD_VERSION and
// CAGD_REVISION (the git revision at configure time). Tables that take seconds to build come from
// the user's cache (io/user_cache.hpp); building one prints one line (unless --quiet), and
// --no-cache (or CAGD_NO_CACHE=1) builds them in memory instead.
#include <CLI/CLI.hpp>
#include <iostream>
#include <new>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"
#include "cli/process_setup.hpp"

int main(int argc, char** argv) {
    using namespace cagd::cli;
    prepare_command_process();
    CLI::App app{"cagd — interpolating curves and surfaces from five Japanese CAGD papers (cagd-repro)"};
    app.require_subcommand(1);
    app.fallthrough();  // --quiet may follow the subcommand
    app.option_defaults()->always_capture_default();
    app.set_version_flag("--version", std::string("cagd ") + CAGD_VERSION + " (git " + CAGD_REVISION + ")");
    bool quiet = false;
    app.add_flag("--quiet", quiet, "no progress on stderr (it is shown only when stderr is a terminal anyway)");
    bool no_cache = false;
    app.add_flag("--no-cache", no_cache,
                 "build the pseudo-energy tables in memory, not in the user's cache ($XDG_CACHE_HOME/cagd or "
                 "~/.cache/cagd; also CAGD_NO_CACHE=1)");
    const std::vector<Command> commands = {
        add_interpolate_command(app), add_analyze_command(app),      add_compare_command(app),
        add_surface_command(app),     add_smooth_command(app),       add_smooth_surface_command(app),
        add_energy_command(app),      add_energy_table_command(app), add_lac_command(app),
        add_monotone_command(app),    add_lac3d_command(app),        add_typical_surface_command(app),
        add_benchmark_command(app),   add_peers_command(app),        add_scorecard_command(app),
    };
    try {
        app.parse(argc, argv);
        set_quiet(quiet);
        set_up_table_cache(no_cache);
        for (const Command& c : commands)
            if (c.app->parsed()) return c.run();
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);
        std::cerr << "cagd: error: " << e.what() << "\n";
        return 2;
    } catch (const cagd::InvalidInput& e) {
        std::cerr << "cagd: error: " << user_message(e.what()) << "\n";
        return 2;
    } catch (const cagd::OutputError& e) {
        std::cerr << "cagd: cannot write: " << user_message(e.what()) << "\n";
        return 1;
    } catch (const NoResult& e) {
        std::cerr << "cagd: no result: " << user_message(e.what()) << "\n";
        return 1;
    } catch (const std::bad_alloc&) {
        std::cerr << "cagd: no result: out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "cagd: no result: " << user_message(e.what()) << "\n";
        return 1;
    }
    return 2;
}
