#include "cagd/core/optional_dependencies.hpp"

#include "cagd/core/errors.hpp"

namespace cagd {

namespace {

// The build defines each CAGD_WITH_… as 0 or 1 (CMakeLists.txt); undefined reads as 0.
#if CAGD_WITH_CERES
constexpr bool kWithCeres = true;
#else
constexpr bool kWithCeres = false;
#endif
#if CAGD_WITH_NLOPT
constexpr bool kWithNlopt = true;
#else
constexpr bool kWithNlopt = false;
#endif
#if CAGD_WITH_OPENCASCADE
constexpr bool kWithOpencascade = true;
#else
constexpr bool kWithOpencascade = false;
#endif

}  // namespace

const char* to_string(OptionalDependency d) {
    switch (d) {
        case OptionalDependency::ceres: return "Ceres";
        case OptionalDependency::nlopt: return "NLopt";
        case OptionalDependency::opencascade: return "OpenCASCADE";
    }
    return "?";
}

bool built_with(OptionalDependency d) {
    switch (d) {
        case OptionalDependency::ceres: return kWithCeres;
        case OptionalDependency::nlopt: return kWithNlopt;
        case OptionalDependency::opencascade: return kWithOpencascade;
    }
    return false;
}

void require_built_with(OptionalDependency d, const std::string& who) {
    if (built_with(d)) return;
    const char* option = d == OptionalDependency::ceres   ? "CAGD_WITH_CERES"
                         : d == OptionalDependency::nlopt ? "CAGD_WITH_NLOPT"
                                                          : "CAGD_WITH_OPENCASCADE";
    fail_input(who, std::string("needs a cagd library built with ") + to_string(d) + " (CMake option " + option +
                        "); this one was built without it");
}

}  // namespace cagd
