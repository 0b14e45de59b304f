#include "cagd/core/optional_dependencies.hpp"

#include "cagd/core/errors.hpp"

namespace cagd {

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
        case OptionalDependency::ceres: return CAGD_WITH_CERES != 0;
        case OptionalDependency::nlopt: return CAGD_WITH_NLOPT != 0;
        case OptionalDependency::opencascade: return CAGD_WITH_OPENCASCADE != 0;
    }
    return false;
}

void require_built_with(OptionalDependency d, const std::string& who) {
    if (built_with(d)) return;
    const char* option = d == OptionalDependency::ceres ? "CAGD_WITH_CERES" : d == OptionalDependency::nlopt ? "CAGD_WITH_NLOPT" : "CAGD_WITH_OPENCASCADE";
    fail_input(who, std::string("needs a cagd library built with ") + to_string(d) + " (CMake option " + option + "); this one was built without it");
}

}  // namespace cagd
