// The registry as text: the Markdown table of docs/methods.md and the plain listing of
// `cagd interpolate --list-methods`.
#include <string>

#include "cagd/methods/method_registry.hpp"

namespace cagd::methods {

const char* to_string(Invariance i) {
    switch (i) {
        case Invariance::none: return "none claimed";
        case Invariance::translation_scale: return "translation, uniform scaling";
        case Invariance::similarity: return "similarity (translation, rotation, uniform scaling)";
        case Invariance::affine: return "affine";
    }
    return "?";
}

namespace {

std::string claims_text(const MethodClaims& c) {
    std::string s;
    if (c.parametric_continuity > 0) s += "C" + std::to_string(c.parametric_continuity) + " in τ (" + c.parameter + ")";
    if (c.geometric_continuity > 0)
        s += (s.empty() ? "" : ", ") + std::string("G") + std::to_string(c.geometric_continuity);
    s += std::string("; invariance: ") + to_string(c.invariance);
    s += "; " + std::string(c.max_dimension == 3 ? "2-D, 3-D" : "2-D");
    s += c.supports_closed ? "; open, closed" : "; open only";
    s += "; points >= " + std::to_string(c.min_points);
    if (c.max_points > 0) s += ", <= " + std::to_string(c.max_points);
    if (!c.always_solves) s += "; no solution for some points";
    return s;
}

std::string parameters_text(const Method& m, const char* separator) {
    std::string s;
    for (const Parameter& p : m.parameters)
        s += (s.empty() ? "" : separator) + std::string("--") + p.name +
             (p.default_text.empty() ? "" : " " + p.default_text);
    return s.empty() ? "none" : s;
}

}  // namespace

std::string registry_markdown() {
    std::string s =
        "| method | paper | source | what it is | parameters (default) | claims (defaults) | compared as "
        "|\n|---|---|---|---|---|---|---|\n";
    for (const Method& m : registry()) {
        std::string presets;
        for (const Preset& p : m.presets) presets += (presets.empty() ? "" : ", ") + std::string("`") + p.name + "`";
        std::string name = "`" + m.name + "`";
        for (const std::string& a : m.aliases) name += " (alias `" + a + "`)";
        s += "| " + name + " | " + m.paper + " | " + m.source + " | " + m.summary + " | " + parameters_text(m, ", ") +
             " | " + claims_text(m.claims(parse_parameter_values(m.name, m.parameters, {}))) + " | " +
             (presets.empty() ? "`" + m.name + "`" : presets) + " |\n";
    }
    return s;
}

std::string registry_listing() {
    std::string s;
    for (const Method& m : registry()) {
        s += m.name;
        for (const std::string& a : m.aliases) s += " (alias " + a + ")";
        s += "  [" + m.paper + " " + m.source + "]  " + m.summary + "\n";
        s += "    claims: " + claims_text(m.claims(parse_parameter_values(m.name, m.parameters, {}))) + "\n";
        for (const Parameter& p : m.parameters)
            s += "    --" + p.name + "  " + p.domain() + (p.default_text.empty() ? "" : ", default " + p.default_text) +
                 ": " + p.help + "\n";
    }
    return s;
}

}  // namespace cagd::methods
