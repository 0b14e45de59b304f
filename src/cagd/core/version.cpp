#include "cagd/core/version.hpp"

namespace cagd {

const char* library_version() { return CAGD_LIBRARY_VERSION; }

}  // namespace cagd
