// The compiled part of the Python module `cagd` (python/cagd/__init__.py documents the API).
// Only conversion lives here: NumPy arrays ↔ Eigen, parameters as the registry's text, the
// library's exceptions as Python's. Every computation is the C++ library's (the same functions as
// `cagd` and the experiments), so the module's values equal the library's bit for bit.
//
// Errors: cagd::InvalidInput → ValueError with the library's message; a numerical outcome (no
// solution, no convergence) → cagd.NoSolution (a RuntimeError) carrying the outcome's message; a
// failed write (cagd::OutputError) → OSError, the previous file kept. Every message is put in
// Python's terms first (python_message): no C++ qualified names, no command-line options.
// Vectorised evaluation releases the GIL and fills the result array in place.
//
// One bindings_<folder>.cpp per library folder (bindings.hpp); this file only wires them.
#include <cctype>
#include <string_view>

#include "bindings.hpp"

#ifndef CAGD_VERSION
#define CAGD_VERSION "unknown"
#endif

using namespace cagd_python;

namespace {

// A library message in Python's terms: no C++ qualified names (cagd::in_user_terms), and an option
// `--start-tangent` becomes the keyword argument `start_tangent`.
std::string python_message(const std::string& message) {
    const std::string m = cagd::in_user_terms(message);
    std::string out;
    std::size_t i = 0;
    while (i < m.size()) {
        const bool option_start = i + 2 < m.size() && m[i] == '-' && m[i + 1] == '-' &&
                                  std::islower(static_cast<unsigned char>(m[i + 2])) &&
                                  (i == 0 || std::string_view(" (,'\"").find(m[i - 1]) != std::string_view::npos);
        if (option_start) {
            std::size_t end = i + 2;
            while (end < m.size() && (std::islower(static_cast<unsigned char>(m[end])) ||
                                      std::isdigit(static_cast<unsigned char>(m[end])) || m[end] == '-'))
                ++end;
            for (std::size_t k = i + 2; k < end; ++k) out += m[k] == '-' ? '_' : m[k];
            i = end;
            continue;
        }
        out += m[i++];
    }
    return out;
}

}  // namespace

PYBIND11_MODULE(_cagd, m) {
    m.doc() = "cagd-repro: interpolating curves from five Japanese CAGD papers (compiled part; see cagd.__doc__)";
    m.attr("__version__") = CAGD_VERSION;  // the CMake project's version
    static py::exception<NoSolution> no_solution(m, "NoSolution", PyExc_RuntimeError);
    no_solution.attr("__doc__") =
        "A numerical outcome for valid input: no solution exists, or the solver did not converge (a RuntimeError). "
        "interpolate_result returns the same outcome as a status instead of raising.";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const cagd::InvalidInput& e) {
            PyErr_SetString(PyExc_ValueError, python_message(e.what()).c_str());
        } catch (const NoSolution& e) {
            no_solution(python_message(e.what()).c_str());
        } catch (const cagd::OutputError& e) {  // a failed write: the old file is kept
            PyErr_SetString(PyExc_OSError, python_message(e.what()).c_str());
        }
    });

    bind_core(m);
    bind_methods(m);
    bind_compare(m);
    bind_fairness(m);
    bind_aesthetic(m);
    bind_spline(m);
    bind_smoothing(m);
    bind_surface(m);
    bind_export(m);
}
