#pragma once
// An exclusive advisory lock on a file (POSIX flock), held for the object's lifetime: the caches
// of computed tables use it so that processes which miss the same cache at once (parallel ctest,
// make reproduce, a user's two runs) build the table once — the second waits, then loads it.
// The lock file is created if missing and left in place (empty). When it cannot be created
// (read-only directory) the object holds no lock and callers proceed as before: the cache then
// saves atomically by rename, so the worst case is a duplicated build, never a mixed file.
#include <string>

namespace cagd {

class FileLock {
public:
    explicit FileLock(const std::string& path);
    ~FileLock();
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;
    bool held() const { return fd_ >= 0; }

private:
    int fd_ = -1;
};

}  // namespace cagd
