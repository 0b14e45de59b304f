#include "cli/method_options.hpp"

#include <set>
#include <vector>

#include "cagd/methods/method_registry.hpp"

namespace cagd::cli {

CLI::Option* add_method_options(CLI::App* app, std::string& method, MethodOptions& o) {
    std::string names;
    for (const std::string& n : methods::method_names()) names += (names.empty() ? "" : " | ") + n;
    CLI::Option* m =
        app->add_option("--method", method, "interpolation method: " + names + " (--list-methods describes each)")
            ->check(CLI::IsMember(methods::method_names()));
    // Each parameter name once; its help says what it is for each method that has it, methods
    // with the same declaration named together.
    std::vector<std::string> order;
    std::map<std::string, std::vector<std::pair<std::string, std::string>>> meanings;  // name → (methods, text)
    std::map<std::string, std::set<std::string>> choices;
    for (const methods::Method& method_entry : methods::registry())
        for (const methods::Parameter& p : method_entry.parameters) {
            if (!meanings.count(p.name)) order.push_back(p.name);
            const std::string text =
                p.help + " [" + p.domain() + (p.default_text.empty() ? "" : ", default " + p.default_text) + "]";
            auto& list = meanings[p.name];
            bool merged = false;
            for (auto& [who, t] : list)
                if (t == text) who += ", " + method_entry.name, merged = true;
            if (!merged) list.emplace_back(method_entry.name, text);
            if (p.type == methods::ParameterType::choice) choices[p.name].insert(p.choices.begin(), p.choices.end());
        }
    std::map<std::string, std::string> help;
    for (const auto& [name, list] : meanings)
        for (const auto& [who, text] : list) help[name] += (help[name].empty() ? "" : "; ") + who + ": " + text;
    for (const std::string& name : order) {
        CLI::Option* opt = app->add_option("--" + name, o.text[name], help[name]);
        if (choices.count(name))
            opt->check(CLI::IsMember(std::vector<std::string>(choices[name].begin(), choices[name].end())));
        o.options[name] = opt;
    }
    return m;
}

methods::ParameterText given_parameters(const MethodOptions& o) {
    methods::ParameterText given;
    for (const auto& [name, opt] : o.options)
        if (opt->count() > 0) given[name] = o.text.at(name);
    return given;
}

}  // namespace cagd::cli
