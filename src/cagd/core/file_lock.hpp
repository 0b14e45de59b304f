#pragma once
/// @file
/// An exclusive advisory lock on a file (POSIX flock), held for the object's lifetime: the caches
/// of computed tables use it so that processes which miss the same cache at once (parallel ctest,
/// make reproduce, a user's two runs) build the table once — the second waits, then loads it.
/// The lock file is created if missing and left in place (empty). When it cannot be created
/// (read-only directory) the object holds no lock and callers proceed as before: the cache then
/// saves atomically by rename, so the worst case is a duplicated build, never a mixed file.
#include <optional>
#include <string>
#include <utility>

namespace cagd {

/// An exclusive advisory lock (flock) on a file, held from construction to destruction.
class FileLock {
public:
    /// Opens (creating if needed) `path` and waits until the lock is held.
    explicit FileLock(const std::string& path);
    ~FileLock();
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;
    /// Whether the lock is held (false only if the file could not be opened).
    bool held() const { return fd_ >= 0; }

private:
    int fd_ = -1;
};

/// The caches' pattern: try_load() (a std::optional of the table; empty when the file is missing or
/// holds another table); on a miss, take the lock on path + ".lock" and try again (another process
/// may have built it meanwhile), else build_and_save() under the lock.
template <class TryLoad, class BuildAndSave>
auto load_or_build_locked(const std::string& path, const TryLoad& try_load, const BuildAndSave& build_and_save) -> decltype(build_and_save()) {
    if (auto cached = try_load()) return std::move(*cached);
    const FileLock lock(path + ".lock");
    if (auto cached = try_load()) return std::move(*cached);
    return build_and_save();
}

}  // namespace cagd
