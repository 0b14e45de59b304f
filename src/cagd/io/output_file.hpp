#pragma once
/// @file
/// Writing a user's file so that a write never lies (the output contract of docs/command.md).
///
/// An OutputFile classifies its target when it is made, before any work:
///   - descriptor: "-" (standard output), /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N, or a
///     path that is the very file standard output or standard error writes (`--out /dev/stdout >> f`):
///     written through that descriptor at commit(), at its offset (appended where the shell appends),
///     never truncated, renamed over or removed;
///   - special: an existing device, FIFO or socket: opened for writing at commit() and written;
///   - regular: a regular file or a new path: a temporary file beside it (created by create_temporary, given the
///     mode of the file it replaces, or 0666 less the umask for a new one), renamed over it at commit().
///     A symbolic link keeps pointing where it did: the file it finally names is replaced.
/// Output appears only after success: what stream() receives is published by commit(). Descriptor
/// and special targets hold it in memory until then; a regular target holds it in its temporary file.
///
/// Every write, flush, close and rename is checked. A failure throws OutputError naming the option,
/// the path and the system's reason, and leaves the previous file exactly as it was. A directory, a
/// symbolic-link loop, a missing parent directory, a descriptor that is not open for writing, or a
/// place where no temporary file can be made is bad input (InvalidInput), found by the constructor.
/// An OutputFile destroyed without commit() removes its temporary file.
///
/// OutputDirectory is a multi-file output (`cagd compare --out DIR`): its files are written into a
/// fresh private directory beside DIR and published by commit() as a whole, under an exclusive lock
/// on DIR, so that two runs never mix their files; renames replace links planted in DIR, they never
/// follow them.
///
/// Temporary files and directories are registered before they exist (io/temporary_file.hpp);
/// remove_output_temporaries() removes them all and is async-signal-safe (a signal handler calls it:
/// install_output_signal_cleanup).
#include <filesystem>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cagd/io/temporary_file.hpp"

namespace cagd {

/// A write that failed for valid input (a full disk, a closed pipe, a read-only place): the option,
/// the path and the system's reason. The previous file is kept.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// One output file (see above).
class OutputFile {
public:
    /// The target `path` ("-": standard output), checked now; `option` names it in messages ("--out").
    explicit OutputFile(const std::string& path, const std::string& option = "--out");
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    /// Without commit(): removes the temporary file; the target is untouched.
    ~OutputFile();
    /// Where the output is written before commit().
    std::ostream& stream() { return *stream_; }
    /// Publishes the output; OutputError if any write, flush, close or rename failed (the target then
    /// keeps its previous content). Once only.
    void commit();
    /// The path as given.
    const std::string& path() const { return path_; }
    /// Whether the target is written through an open descriptor ("-", /dev/stdout, …).
    bool is_descriptor() const { return target_ == Target::descriptor; }

private:
    enum class Target { descriptor, special, regular };
    class FdBuffer;
    std::string path_, option_;
    Target target_ = Target::regular;
    int descriptor_ = -1;
    std::filesystem::path final_, temp_path_;
    int temp_slot_ = -1;
    std::unique_ptr<FdBuffer> file_buffer_;  ///< regular: the temporary file's buffer
    std::ostringstream memory_;              ///< descriptor and special: the output until commit()
    std::unique_ptr<std::ostream> file_stream_;
    std::ostream* stream_ = nullptr;
    bool committed_ = false;
    [[noreturn]] void fail(const std::string& what, int error) const;
};

/// A multi-file output: the files of one directory, published together (see above).
class OutputDirectory {
public:
    /// The directory `path` (created by commit() if it does not exist), checked now; a private
    /// staging directory is made beside it.
    explicit OutputDirectory(const std::string& path, const std::string& option = "--out");
    OutputDirectory(const OutputDirectory&) = delete;
    OutputDirectory& operator=(const OutputDirectory&) = delete;
    /// Without commit(): removes the staging directory and everything in it.
    ~OutputDirectory();
    /// Where a file `name` (no '/') is staged: write it there (e.g. with an OutputFile) before commit().
    std::string staged(const std::string& name);
    /// Where a scratch file `name` (no '/') goes: in the staging directory, registered (a signal removes
    /// it), never published (commit() removes it first): a tool's log, read only when the tool fails.
    std::string scratch(const std::string& name);
    /// The staging directory (for tools that write into it themselves, such as gnuplot).
    const std::string& staging() const { return staging_; }
    /// Moves every staged file into the directory, under an exclusive lock on it; OutputError on failure.
    void commit();

private:
    std::string path_, option_, staging_;
    int staging_slot_ = -1;
    std::vector<int> staged_slots_;
    std::vector<std::pair<std::string, int>> scratch_;  ///< path, slot
    bool committed_ = false;
};

}  // namespace cagd
