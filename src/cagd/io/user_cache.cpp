#include "cagd/io/user_cache.hpp"

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <utility>

namespace cagd {

namespace {
std::atomic<bool> enabled_in_process{true};
std::atomic<CacheBuildNotice> build_notice{nullptr};
std::function<void(long, long)>& progress_callback() {
    static std::function<void(long, long)> progress;
    return progress;
}

bool switched_off_by_environment() {
    const char* v = std::getenv("CAGD_NO_CACHE");
    return v != nullptr && std::string(v) != "" && std::string(v) != "0";
}
}  // namespace

std::optional<std::string> user_cache_directory() {
    if (!enabled_in_process.load() || switched_off_by_environment()) return std::nullopt;
    namespace fs = std::filesystem;
    fs::path dir;
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    if (xdg != nullptr && fs::path(xdg).is_absolute())
        dir = fs::path(xdg) / "cagd";
    else if (home != nullptr && fs::path(home).is_absolute())
        dir = fs::path(home) / ".cache" / "cagd";
    else
        return std::nullopt;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir, ec)) return std::nullopt;
    return dir.string();
}

void set_user_cache_enabled(bool enabled) { enabled_in_process.store(enabled); }

void set_cache_build_notice(CacheBuildNotice notice) { build_notice.store(notice); }

void announce_cache_build(const std::string& path, const std::string& what) {
    if (CacheBuildNotice n = build_notice.load()) n(path, what);
}

void set_cache_build_progress(std::function<void(long, long)> progress) { progress_callback() = std::move(progress); }

const std::function<void(long, long)>& cache_build_progress() { return progress_callback(); }

}  // namespace cagd
