#pragma once
// The message of the InvalidInput a call throws, for tests that check it names the offending value.
#include <functional>
#include <string>

#include "cagd/core/errors.hpp"

namespace cagd::test {

inline std::string invalid_input_message(const std::function<void()>& f) {
    try {
        f();
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "(no InvalidInput)";
}

}  // namespace cagd::test
