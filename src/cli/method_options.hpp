#pragma once
// The registry's method parameters as command-line options (`cagd interpolate`, `cagd analyze
// --in`): one `--NAME` per parameter name across all methods, its help listing, per method, what it
// means, its domain and default. The values are passed on as typed text; the registry checks them
// against the chosen method (methods::parse_parameter_values), so `--scale` given to s-spline is
// an error naming both.
#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "cagd/methods/method_parameters.hpp"

namespace cagd::cli {

struct MethodOptions {
    std::map<std::string, std::string> text;      // by parameter name
    std::map<std::string, CLI::Option*> options;  // by parameter name
};

// Registers --method (its default is the value `method` holds) and every parameter's option on `app`.
CLI::Option* add_method_options(CLI::App* app, std::string& method, MethodOptions& options);
// The options the user gave.
methods::ParameterText given_parameters(const MethodOptions& options);

}  // namespace cagd::cli
