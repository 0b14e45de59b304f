#pragma once
/// @file
/// Typed parameters of an interpolation method (the registry, methods/method_registry.hpp).
///
/// A parameter is declared once, with its type, default, range or choices and help text; the
/// command line shows it as `--NAME` and passes what the user typed as text; the tests and
/// `cagd compare` pass preset values the same way. parse_parameter_values checks every value
/// against its declaration and gives the builder typed values:
///
///   integer   a whole number in [lower, upper]                 ParameterValues::integer
///   real      a finite number in [lower, upper]                ParameterValues::real
///   choice    one of `choices`                                 ParameterValues::text
///   text      free text the builder parses itself (a list)      ParameterValues::text
///   vector    comma-separated finite numbers, e.g. "1,0,0"      ParameterValues::vector
///
/// An empty default means "absent unless given" (the help says what absence means); given()
/// tells a value the user set from one taken from the default.
/// Bad input (InvalidInput naming the method, the option and the value): a parameter the method
/// does not declare, a value of the wrong type, out of range, or not among the choices.
#include <Eigen/Dense>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace cagd::methods {

/// The type of a parameter's value (see above).
enum class ParameterType { integer, real, choice, text, vector };
/// "integer", "real", "choice", "text" or "vector".
const char* to_string(ParameterType t);

/// One declared parameter of a method.
struct Parameter {
    std::string name{};                                       ///< the option, without "--"
    ParameterType type = ParameterType::text;                 ///< how its text is checked and read
    std::string default_text{};                               ///< as a user would type it; empty: absent unless given
    double lower = -std::numeric_limits<double>::infinity();  ///< integer, real: inclusive range
    double upper = std::numeric_limits<double>::infinity();   ///< integer, real: inclusive upper bound
    std::vector<std::string> choices{};                       ///< choice
    std::string help{};                                       ///< one line for help texts
    bool space_only = false;  ///< applies to 3-D points only (planar points refuse any other value than its default)

    /// "integer in [0, 1000]", "one of none | exact | approx", … for help texts and messages.
    std::string domain() const;
};

/// Text values as typed, by parameter name.
using ParameterText = std::map<std::string, std::string>;

/// A method's parameter values, checked against their declarations (parse_parameter_values).
class ParameterValues {
public:
    bool has(const std::string& name) const;    ///< given, or has a default
    bool given(const std::string& name) const;  ///< given explicitly
    /// An integer parameter's value (given or default).
    int integer(const std::string& name) const;
    /// A real parameter's value (given or default).
    double real(const std::string& name) const;
    const std::string& text(const std::string& name) const;  ///< choice or text; "" when absent
    /// A vector parameter's value.
    const Eigen::VectorXd& vector(const std::string& name) const;
    /// The text of every parameter that has a value (given or default), as typed: enough to build
    /// the same curve again (parse_parameter_values of it gives these values).
    ParameterText as_text() const;

private:
    struct Value {
        ParameterType type = ParameterType::text;
        std::string text;
        double number = 0.0;
        Eigen::VectorXd vector;
        bool given = false;
    };
    const Value& at(const std::string& name, ParameterType type) const;
    std::map<std::string, Value> values_;
    friend ParameterValues parse_parameter_values(const std::string&, const std::vector<Parameter>&,
                                                  const ParameterText&);
};

/// Checks `given` against the declarations of method `method` and fills in the defaults.
ParameterValues parse_parameter_values(const std::string& method, const std::vector<Parameter>& parameters,
                                       const ParameterText& given);

}  // namespace cagd::methods
