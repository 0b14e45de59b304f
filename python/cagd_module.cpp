// The compiled part of the Python module `cagd` (python/cagd/__init__.py documents the API).
// Only conversion lives here: NumPy arrays ↔ Eigen, parameters as the registry's text, the
// library's exceptions as Python's. Every computation is the C++ library's (the same functions as
// `cagd` and the experiments), so the module's values equal the library's bit for bit.
//
// Errors: cagd::InvalidInput → ValueError with the library's message; a numerical outcome (no
// solution, no convergence) → cagd.NoSolution (a RuntimeError) carrying the outcome's message; a
// failed write (cagd::OutputError) → OSError, the previous file kept.
// Vectorised evaluation releases the GIL and fills the result array in place.
//
// One bindings_<folder>.cpp per library folder (bindings.hpp); this file only wires them.
#include "bindings.hpp"

using namespace cagd_python;

PYBIND11_MODULE(_cagd, m) {
    m.doc() = "cagd-repro: interpolating curves from five Japanese CAGD papers (compiled part; see cagd.__doc__)";
    static py::exception<NoSolution> no_solution(m, "NoSolution", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const cagd::InvalidInput& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const NoSolution& e) {
            no_solution(e.what());
        } catch (const cagd::OutputError& e) {  // a failed write: the old file is kept
            PyErr_SetString(PyExc_OSError, e.what());
        }
    });

    bind_core(m);
    bind_methods(m);
    bind_compare(m);
    bind_fairness(m);
    bind_aesthetic(m);
    bind_spline(m);
    bind_smoothing(m);
}
