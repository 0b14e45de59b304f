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

/// What a cache does not use although its file exists (damaged, of an older format, another
/// table): told the path and the reason before the table is rebuilt. The library prints nothing;
/// a program that wants the line (the harness: one line on stderr) sets a notice.
using CacheRebuildNotice = void (*)(const std::string& path, const std::string& reason);
/// Sets the process's notice; nullptr (the default) is silent.
void set_cache_rebuild_notice(CacheRebuildNotice notice);
/// Calls the notice, if one is set.
void announce_cache_rebuild(const std::string& path, const std::string& reason);
/// Whether a file (or anything) exists at `path`.
bool cache_file_exists(const std::string& path);

/// The caches' pattern: try_load(why) (a std::optional of the table; empty when the file is missing
/// or is not used, `why` then saying why when it can); on a miss, take the lock on path + ".lock"
/// and try again (another process may have built it meanwhile), else build_and_save() under the
/// lock, announcing the rebuild of an existing file first.
template <class TryLoad, class BuildAndSave>
auto load_or_build_locked(const std::string& path, const TryLoad& try_load, const BuildAndSave& build_and_save)
    -> decltype(build_and_save()) {
    std::string why;
    if (auto cached = try_load(why)) return std::move(*cached);
    const FileLock lock(path + ".lock");
    why.clear();
    if (auto cached = try_load(why)) return std::move(*cached);
    if (cache_file_exists(path))
        announce_cache_rebuild(path, why.empty() ? "not a table of this grid, method and format" : why);
    return build_and_save();
}

}  // namespace cagd
