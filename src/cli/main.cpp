// The `cagd` command: the library on the user's own points. Each subcommand lives in its own
// cli/<name>_command.cpp (cli/commands.hpp); this file only wires them and maps outcomes to exit
// codes: 0 success, 1 a numerical outcome for valid input, 2 bad input or usage (one line on
// stderr). `cagd --help`, `cagd SUBCOMMAND --help` (defaults and limits), `cagd --version`.
#include <CLI/CLI.hpp>
#include <iostream>
#include <new>
#include <vector>

#include "cli/commands.hpp"
#include "core/errors.hpp"

#ifndef CAGD_VERSION
#define CAGD_VERSION "unknown"
#endif

int main(int argc, char** argv) {
    using namespace cagd::cli;
    CLI::App app{"cagd — interpolating curves and surfaces from five Japanese CAGD papers (cagd-repro)"};
    app.require_subcommand(1);
    app.option_defaults()->always_capture_default();
    app.set_version_flag("--version", std::string("cagd ") + CAGD_VERSION);
    const std::vector<Command> commands = {
        add_interpolate_command(app), add_analyze_command(app),      add_compare_command(app), add_surface_command(app),  add_smooth_command(app), add_smooth_surface_command(app),
        add_energy_command(app),      add_energy_table_command(app), add_lac_command(app),     add_monotone_command(app), add_lac3d_command(app),  add_typical_surface_command(app),
    };
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);
        std::cerr << "cagd: error: " << e.what() << "\n";
        return 2;
    }
    try {
        for (const Command& c : commands)
            if (c.app->parsed()) return c.run();
    } catch (const cagd::InvalidInput& e) {
        std::cerr << "cagd: error: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "cagd: no result: out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "cagd: no result: " << e.what() << "\n";
        return 1;
    }
    return 2;
}
