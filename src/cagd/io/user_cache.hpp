#pragma once
/// @file
/// The user's cache of computed tables: tables that take seconds to build (the pseudo-energy
/// tables of the pseudo-spline) are built once per user, not once per process.
///
/// Where: `$XDG_CACHE_HOME/cagd` when XDG_CACHE_HOME is an absolute path (the XDG Base Directory
/// Specification ignores a relative one), else `$HOME/.cache/cagd`; created on first use.
///
/// Off when the environment variable CAGD_NO_CACHE is set to anything but "" or "0", after
/// set_user_cache_enabled(false) (the command's `--no-cache`), or when neither variable gives a
/// directory or it cannot be created: the table is then built in memory, as before, and nothing
/// is written.
///
/// What a cached table file is: the table's own text format with its checksum line, written whole
/// (rename) under a lock on `<file>.lock`, so that two processes that miss at once build it once
/// (io/file_lock.hpp); a damaged or foreign file is rebuilt with the rebuild notice. A file that
/// cannot be written leaves the built table in memory and the cache as it was.
///
/// The library prints nothing: a program that wants a line when a cached table is built (the
/// command: one line on stderr, then the build's progress) sets a notice.
#include <functional>
#include <optional>
#include <string>

namespace cagd {

/// The cache directory, created if needed; nullopt when the cache is off (see above).
std::optional<std::string> user_cache_directory();
/// Turns the user cache off (false) or on again for this process; the environment still rules.
void set_user_cache_enabled(bool enabled);

/// Told the path and what is built, before a cached table is built (not when it is loaded).
using CacheBuildNotice = void (*)(const std::string& path, const std::string& what);
/// Sets the process's notice; nullptr (the default) is silent.
void set_cache_build_notice(CacheBuildNotice notice);
/// Calls the notice, if one is set.
void announce_cache_build(const std::string& path, const std::string& what);

/// The progress of a long build (nodes done, nodes in all), for the notice's program; empty by
/// default. The command sets one that prints a line per tenth.
void set_cache_build_progress(std::function<void(long, long)> progress);
/// The progress callback set (possibly empty).
const std::function<void(long, long)>& cache_build_progress();

}  // namespace cagd
