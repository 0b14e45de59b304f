#include "cagd/io/file_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <filesystem>
#include <system_error>

namespace cagd {

FileLock::FileLock(const std::string& path) : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ < 0) return;
    int r = 0;
    while ((r = ::flock(fd_, LOCK_EX)) != 0 && errno == EINTR) {}
    if (r != 0) {
        ::close(fd_);
        fd_ = -1;
    }
}

FileLock::~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

namespace {
std::atomic<CacheRebuildNotice> cache_notice{nullptr};
}  // namespace

void set_cache_rebuild_notice(CacheRebuildNotice notice) { cache_notice.store(notice); }

void announce_cache_rebuild(const std::string& path, const std::string& reason) {
    if (const CacheRebuildNotice notice = cache_notice.load()) notice(path, reason);
}

bool cache_file_exists(const std::string& path) {
    std::error_code ec;
    return std::filesystem::exists(std::filesystem::symlink_status(path, ec));
}

}  // namespace cagd
