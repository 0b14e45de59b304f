// `cagd energy --theta0 A --theta1 B [--deg]`: the minimum pseudo-energy J(θ0, θ1) of a unit-chord
// cubic Hermite segment (pseudo_energy eq 8) with r0, r1, L, S and the segment type, computed
// exactly (fairness/pseudo_energy_minimum.hpp). One CSV row with a header on stdout.
#include <cstdio>
#include <iostream>
#include <memory>
#include <numbers>

#include "cagd/core/errors.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

struct EnergyArgs {
    double theta0 = 0, theta1 = 0;
    bool degrees = false;
};

int run_energy(const EnergyArgs& a) {
    const double k = a.degrees ? std::numbers::pi / 180.0 : 1.0;
    const double t0 = a.theta0 * k, t1 = a.theta1 * k;
    const char* who = a.degrees ? "cagd energy (--deg converted to radians)" : "cagd energy";
    fairness::require_tangent_angle(who, t0, "--theta0");
    fairness::require_tangent_angle(who, t1, "--theta1");
    const fairness::PseudoEnergyMinimum m = fairness::minimize_pseudo_energy(t0, t1);
    if (fairness::is_undefined_node(t0, t1)) fail_input("cagd energy", m.outcome.message);
    if (!m.outcome.ok()) throw NoResult(m.outcome.message);
    for (const auto& [value, name] :
         {std::pair{m.pseudo_energy, "J"}, {m.r0, "r0"}, {m.r1, "r1"}, {m.length, "L"}, {m.area, "S"}})
        finite_field(value, 17, name);
    char row[512];
    std::snprintf(row, sizeof row, "theta0,theta1,J,r0,r1,L,S,type\n%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%s\n",
                  a.theta0, a.theta1, m.pseudo_energy, m.r0, m.r1, m.length, m.area, fairness::to_string(m.type));
    print_standard_output(row);
    return 0;
}

}  // namespace

Command add_energy_command(CLI::App& app) {
    auto a = std::make_shared<EnergyArgs>();
    CLI::App* c = app.add_subcommand("energy",
                                     "Minimum pseudo-energy J(theta0, theta1) of a unit-chord cubic Hermite segment "
                                     "(pseudo_energy eq 8), exact computation");
    c->add_option("--theta0", a->theta0, "start tangent angle, in [-pi, pi] (or [-180, 180] with --deg)")->required();
    c->add_option("--theta1", a->theta1, "end tangent angle, in [-pi, pi] (or [-180, 180] with --deg)")->required();
    c->add_flag("--deg", a->degrees, "angles in degrees");
    return {c, [a] { return run_energy(*a); }};
}

}  // namespace cagd::cli
