#pragma once
// The subcommands of `cagd`, one file each (cli/<name>_command.cpp); main.cpp only wires them.
// add_X_command registers the subcommand and its options on `app` and returns how to run it once
// parsed. A run returns the exit code: 0 success, 1 a numerical outcome for valid input (no
// solution, no convergence), reported on stderr; bad input throws cagd::InvalidInput (exit 2).
#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <string>

namespace cagd::cli {

struct Command {
    CLI::App* app = nullptr;
    std::function<int()> run;
};

Command add_interpolate_command(CLI::App& app);
Command add_analyze_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_surface_command(CLI::App& app);
Command add_smooth_command(CLI::App& app);
Command add_smooth_surface_command(CLI::App& app);
Command add_energy_command(CLI::App& app);
Command add_energy_table_command(CLI::App& app);
Command add_lac_command(CLI::App& app);
Command add_lac3d_command(CLI::App& app);
Command add_monotone_command(CLI::App& app);
Command add_typical_surface_command(CLI::App& app);
Command add_benchmark_command(CLI::App& app);
Command add_peers_command(CLI::App& app);
Command add_scorecard_command(CLI::App& app);

// An option whose text names one value of an enumeration (CLI11's checked transform): the help
// lists the names and shows the current value of `value` as the default.
template <class Enum>
CLI::Option* add_enum_option(CLI::App* app, const std::string& name, Enum& value,
                             const std::map<std::string, Enum>& names, const std::string& help) {
    std::string listed;
    for (const auto& [text, e] : names) listed += (listed.empty() ? "" : "|") + text;
    CLI::Option* o =
        app->add_option(name, value, help)->transform(CLI::CheckedTransformer(names).description("{" + listed + "}"));
    for (const auto& [text, e] : names)
        if (e == value) o->default_str(text);
    return o;
}

}  // namespace cagd::cli
