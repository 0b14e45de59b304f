#pragma once
/// @file
/// The library's version, as the build was configured (CMake's project version).

namespace cagd {

/// "MAJOR.MINOR", e.g. "0.1": written into exported curve documents (export/curve_json.hpp).
const char* library_version();

}  // namespace cagd
