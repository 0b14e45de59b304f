#pragma once
/// @file
/// Errors and numerical outcomes (docs/design.md, "Errors and outcomes").
///
/// A violated precondition (bad input) throws cagd::InvalidInput whose message names
/// the function, the condition and the offending value at full precision.
/// A legitimate numerical outcome for valid input (no convergence, no solution) is not
/// an exception: functions that can meet one return a value carrying a cagd::Outcome.
#include <stdexcept>
#include <string>

namespace cagd {

class InvalidInput : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// not_representable: the result overflows or underflows double precision for these inputs (e.g.
/// coordinates near 1e308, whose differences overflow).
enum class Status { ok, no_convergence, no_solution, not_representable };

/// The outcome of a computation on valid input: ok, or why there is no result (never an exception).
struct Outcome {
    Status status = Status::ok;  ///< ok, or the reason there is no result
    std::string message;         ///< what happened, in one line, when not ok
    /// Whether a result exists.
    bool ok() const { return status == Status::ok; }
};

/// Full-precision decimal rendering for error messages (17 significant digits).
std::string full_precision(double value);

/// `text` as one line: line breaks and tabs become spaces, other control bytes (ESC, NUL, …) are
/// shown as `\xHH`, trailing blanks are dropped. Bytes of UTF-8 characters are kept.
std::string one_line(const std::string& text);

/// A data point in messages: "point k (row i)", k = i + 1 its ordinal and i its 0-based row of the
/// point list (a numpy index; the command turns "(row i)" into the line of its file).
std::string point_label(long row);

/// A library message in its user's terms, so that no C++ qualified name reaches a user: a leading
/// qualified function name with its ": " is dropped ("cagd::analysis::curvature: …"); any other
/// loses its qualifiers ("cagd::methods::interpolate(cubic-b)" → "interpolate(cubic-b)",
/// "cagd::BSplineCurve::jet" → "jet"), and "cagd::methods(s-spline)" becomes the method's name.
/// The command and the Python module pass every message through it.
std::string in_user_terms(const std::string& message);

/// Throws InvalidInput("<who>: <what>"), `what` made one line (one_line) — the one way library
/// code reports bad input.
[[noreturn]] void fail_input(const std::string& who, const std::string& what);

}  // namespace cagd
