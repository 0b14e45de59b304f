#pragma once
/// @file
/// Temporary files and directories that a signal never leaves behind.
///
/// Every temporary of the process is registered in a fixed table of slots *before* it exists:
/// create_temporary() draws the name (the prefix and 16 random letters and digits), registers it,
/// and only then creates it with O_CREAT | O_EXCL (a file, mode 0600) or mkdir (a directory, mode
/// 0700), drawing another name if that one exists. A signal at any moment therefore finds every
/// temporary that exists: remove_output_temporaries() unlinks the registered files, then removes the
/// registered directories (async-signal-safe: it reads the table and calls unlink and rmdir only).
/// A registered name that was not created yet is unlinked in vain; with 16 random characters it
/// never names another file. A path longer than 4095 bytes, or a 257th temporary at once, is not
/// created (EOVERFLOW): nothing is made that a signal could not find.
#include <string>

namespace cagd {

/// What a temporary is.
enum class TemporaryKind {
    file,      ///< removed by unlink
    directory  ///< removed by rmdir, after the files (registered ones inside it go first)
};

/// Creates a temporary `prefix` + 16 random characters (see above) and sets `path` to it; `slot`
/// receives its registration. Returns the open descriptor of a file (O_RDWR | O_CLOEXEC), 0 for a
/// directory, or -1 with errno set (nothing created, nothing registered).
int create_temporary(const std::string& prefix, TemporaryKind kind, std::string& path, int& slot);

/// Registers a path that the caller will create (a file inside a registered directory); the slot,
/// or -1 when the table is full or the path too long.
int register_temporary(const std::string& path, TemporaryKind kind);

/// Forgets a registration (the temporary was published by a rename, or removed). -1: nothing.
void unregister_temporary(int slot);

/// Removes every registered temporary file and directory of the process. Async-signal-safe.
void remove_output_temporaries() noexcept;

/// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGPIPE that call remove_output_temporaries()
/// and then end the process by the same signal (the conventional exit status 128 + signal).
void install_output_signal_cleanup();

/// A registered temporary file that its destructor removes (see above).
class TemporaryFile {
public:
    /// Creates `prefix` + 16 random characters; InvalidInput naming `who` and the reason when it cannot.
    TemporaryFile(const std::string& prefix, const char* who);
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    ~TemporaryFile();
    /// Its path.
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int slot_ = -1;
};

}  // namespace cagd
