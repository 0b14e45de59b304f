#pragma once
// A fresh directory under the system's temporary directory for one test, removed with everything
// in it when the test ends.
#include <stdlib.h>

#include <filesystem>
#include <string>

namespace cagd::test {

struct ScratchDirectory {
    std::filesystem::path dir;
    ScratchDirectory() {
        std::string pattern = (std::filesystem::temp_directory_path() / "cagd-test-XXXXXX").string();
        dir = ::mkdtemp(pattern.data());
    }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;
    ~ScratchDirectory() {
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
    }
    /// The path of `name` inside it.
    std::string path(const std::string& name) const { return (dir / name).string(); }
};

}  // namespace cagd::test
