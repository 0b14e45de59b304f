#include "cagd/methods/method_parameters.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::methods {

const char* to_string(ParameterType t) {
    switch (t) {
        case ParameterType::integer: return "integer";
        case ParameterType::real: return "number";
        case ParameterType::choice: return "choice";
        case ParameterType::text: return "text";
        case ParameterType::vector: return "vector";
    }
    return "?";
}

namespace {

std::string range_text(double lower, double upper) {
    const auto bound = [](double v) {
        return std::isinf(v) ? std::string(v < 0 ? "-inf" : "inf") : format_number(v, 17);
    };
    std::string s = "[";
    s += bound(lower);
    s += ", ";
    s += bound(upper);
    return s + "]";
}

}  // namespace

std::string Parameter::domain() const {
    switch (type) {
        case ParameterType::integer: return "integer in " + range_text(lower, upper);
        case ParameterType::real: return "number in " + range_text(lower, upper);
        case ParameterType::choice: {
            std::string s = "one of ";
            for (std::size_t i = 0; i < choices.size(); ++i) s += (i ? " | " : "") + choices[i];
            return s;
        }
        case ParameterType::text: return "text";
        case ParameterType::vector: return "comma-separated numbers";
    }
    return "?";
}

bool ParameterValues::has(const std::string& name) const { return values_.count(name) > 0; }

bool ParameterValues::given(const std::string& name) const {
    const auto it = values_.find(name);
    return it != values_.end() && it->second.given;
}

const ParameterValues::Value& ParameterValues::at(const std::string& name, ParameterType type) const {
    const auto it = values_.find(name);
    // A builder asking for a parameter its method does not declare, or with another type, is a
    // programming error in the registry, not bad input.
    if (it == values_.end())
        throw std::logic_error("cagd::methods::ParameterValues: no value for parameter '" + name + "'");
    if (it->second.type != type && !(type == ParameterType::text && it->second.type == ParameterType::choice))
        throw std::logic_error("cagd::methods::ParameterValues: parameter '" + name + "' is a " +
                               to_string(it->second.type) + ", asked as " + to_string(type));
    return it->second;
}

int ParameterValues::integer(const std::string& name) const {
    return static_cast<int>(at(name, ParameterType::integer).number);
}
double ParameterValues::real(const std::string& name) const { return at(name, ParameterType::real).number; }
const Eigen::VectorXd& ParameterValues::vector(const std::string& name) const {
    return at(name, ParameterType::vector).vector;
}

const std::string& ParameterValues::text(const std::string& name) const {
    static const std::string absent;
    const auto it = values_.find(name);
    return it == values_.end() ? absent : at(name, ParameterType::text).text;
}

ParameterText ParameterValues::as_text() const {
    ParameterText out;
    for (const auto& [name, v] : values_) out[name] = v.text;
    return out;
}

ParameterValues parse_parameter_values(const std::string& method, const std::vector<Parameter>& parameters,
                                       const ParameterText& given) {
    const std::string who = "cagd::methods(" + method + ")";
    for (const auto& [name, text] : given) {
        bool declared = false;
        for (const Parameter& p : parameters) declared = declared || p.name == name;
        if (declared) continue;
        std::string known;
        for (const Parameter& p : parameters) known += (known.empty() ? "--" : ", --") + p.name;
        fail_input(who, "--" + name + " is not a parameter of " + method + " (" +
                            (known.empty() ? "it has none" : "its parameters: " + known) + ")");
    }
    ParameterValues out;
    for (const Parameter& p : parameters) {
        const auto it = given.find(p.name);
        const bool is_given = it != given.end();
        const std::string text = is_given ? it->second : p.default_text;
        if (text.empty()) continue;  // absent
        const auto bad = [&](const std::string& why) {
            fail_input(who, "--" + p.name + " '" + text + "'" + (is_given ? "" : " (default)") + ": " + why +
                                "; allowed: " + p.domain());
        };
        ParameterValues::Value v;
        v.type = p.type;
        v.text = text;
        v.given = is_given;
        switch (p.type) {
            case ParameterType::integer:
            case ParameterType::real: {
                double x = 0.0;
                try {
                    x = parse_number(text);
                } catch (const InvalidInput&) {
                    bad("not a number");
                }
                if (!std::isfinite(x)) bad("not finite");
                if (p.type == ParameterType::integer && x != std::floor(x)) bad("not a whole number");
                if (x < p.lower || x > p.upper) bad("out of range");
                v.number = x;
                break;
            }
            case ParameterType::choice: {
                bool ok = false;
                for (const std::string& c : p.choices) ok = ok || c == text;
                if (!ok) bad("not a choice");
                break;
            }
            case ParameterType::text: break;
            case ParameterType::vector: {
                std::vector<double> xs;
                std::stringstream ss(text);
                std::string field;
                while (std::getline(ss, field, ',')) {
                    double x = 0.0;
                    try {
                        x = parse_number(field);
                    } catch (const InvalidInput&) {
                        bad("'" + field + "' is not a number");
                    }
                    if (!std::isfinite(x)) bad("'" + field + "' is not finite");
                    xs.push_back(x);
                }
                if (xs.empty()) bad("no numbers");
                v.vector = Eigen::Map<const Eigen::VectorXd>(xs.data(), static_cast<Eigen::Index>(xs.size()));
                break;
            }
        }
        out.values_[p.name] = std::move(v);
    }
    return out;
}

}  // namespace cagd::methods
