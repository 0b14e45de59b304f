#include "cagd/core/errors.hpp"

#include <cstdio>

namespace cagd {

std::string full_precision(double value) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", value);
    return buf;
}

void fail_input(const std::string& who, const std::string& what) { throw InvalidInput(who + ": " + what); }

}  // namespace cagd
