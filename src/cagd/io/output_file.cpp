#include "cagd/io/output_file.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string_view>
#include <system_error>

#include "cagd/core/errors.hpp"

namespace cagd {

namespace {

// write(2) until every byte is written; 0, or the errno of the failure.
int write_all(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return 0;
}

std::string reason(int error) { return std::error_code(error, std::generic_category()).message(); }

// The descriptor a path names by itself ("-", /dev/stdout, /dev/fd/N, …), or −1.
int named_descriptor(const std::string& path) {
    if (path == "-" || path == "/dev/stdout") return 1;
    if (path == "/dev/stderr") return 2;
    for (std::string_view prefix : {"/dev/fd/", "/proc/self/fd/"}) {
        if (path.size() > prefix.size() && path.compare(0, prefix.size(), prefix) == 0) {
            const std::string digits = path.substr(prefix.size());
            if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
            return std::atoi(digits.c_str());
        }
    }
    return -1;
}

std::string display_name(const std::string& path) { return path == "-" ? "standard output" : "'" + path + "'"; }
// "--out 'f.csv'", "--out standard output", or without an option "standard output".
std::string output_name(const std::string& option, const std::string& path) {
    return option.empty() ? display_name(path) : option + " " + display_name(path);
}

mode_t current_umask() {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return mask;
}
mode_t new_file_mode() { return static_cast<mode_t>(0666 & ~current_umask()); }
mode_t new_directory_mode() { return static_cast<mode_t>(0777 & ~current_umask()); }

}  // namespace

// ---- OutputFile ---------------------------------------------------------------------------------

// A stream buffer over a file descriptor that remembers the first write error (errno).
class OutputFile::FdBuffer : public std::streambuf {
public:
    explicit FdBuffer(int fd) : fd_(fd), buffer_(1 << 16) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
    int fd() const { return fd_; }
    int error() const { return error_; }

protected:
    int_type overflow(int_type ch) override {
        if (drain() != 0) return traits_type::eof();
        if (!traits_type::eq_int_type(ch, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(ch);
            pbump(1);
        }
        return traits_type::not_eof(ch);
    }
    int sync() override { return drain(); }

private:
    int drain() {
        const std::size_t n = static_cast<std::size_t>(pptr() - pbase());
        if (n > 0 && error_ == 0) error_ = write_all(fd_, pbase(), n);
        setp(buffer_.data(), buffer_.data() + buffer_.size());
        return error_ == 0 ? 0 : -1;
    }
    int fd_;
    std::vector<char> buffer_;
    int error_ = 0;
};

OutputFile::OutputFile(const std::string& path, const std::string& option) : path_(path), option_(option) {
    namespace fs = std::filesystem;
    const std::string who = "cagd";
    const std::string name = output_name(option, path);
    if (path.empty()) fail_input(who, option + " is empty; give a file path or - for standard output");
    int fd = named_descriptor(path);
    struct stat st {};
    bool exists = false;
    if (fd < 0) {
        if (::stat(path.c_str(), &st) == 0) {
            exists = true;
            if (S_ISDIR(st.st_mode)) fail_input(who, name + " is a directory; give a file path");
            // The very file standard output or standard error writes: written through it.
            for (int d : {1, 2}) {
                struct stat ds {};
                if (::fstat(d, &ds) == 0 && ds.st_dev == st.st_dev && ds.st_ino == st.st_ino) fd = d;
            }
        } else if (errno == ELOOP) {
            fail_input(who, name + ": a loop of symbolic links");
        } else if (errno != ENOENT) {
            fail_input(who, name + ": " + reason(errno));
        }
    }
    if (fd >= 0) {
        const int flags = ::fcntl(fd, F_GETFL);
        if (flags < 0 || (flags & O_ACCMODE) == O_RDONLY)
            fail_input(who, name + ": descriptor " + std::to_string(fd) + " is not open for writing" +
                                (fd == 1 ? " (standard output is closed)" : ""));
        target_ = Target::descriptor;
        descriptor_ = fd;
        stream_ = &memory_;
        return;
    }
    if (exists && !S_ISREG(st.st_mode)) {  // a device, a FIFO or a socket: written in place at commit()
        if (::access(path.c_str(), W_OK) != 0) fail_input(who, name + ": " + reason(errno));
        target_ = Target::special;
        final_ = path;
        stream_ = &memory_;
        return;
    }
    // A regular file or a new path. A symbolic link keeps pointing where it did: the file it finally
    // names is replaced (stat above has already refused a loop; a dangling chain ends at a new file).
    fs::path p = path;
    std::error_code ec;
    for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(p, ec)); ++hops) {
        const fs::path target = fs::read_symlink(p, ec);
        if (ec) break;
        p = (target.is_absolute() ? target : p.parent_path() / target).lexically_normal();
    }
    if (fs::is_symlink(fs::symlink_status(p, ec))) fail_input(who, name + ": a loop of symbolic links");
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec)) fail_input(who, name + ": the directory '" + dir.string() + "' does not exist");
    std::string temp_name;
    const int temp = create_temporary((dir / ("." + p.filename().string() + ".cagd-")).string(), TemporaryKind::file,
                                      temp_name, temp_slot_);
    if (temp < 0) fail_input(who, name + ": cannot write in '" + dir.string() + "': " + reason(errno));
    temp_path_ = temp_name;
    final_ = p;
    // Made 0600: the file gets the mode of the one it replaces, or a new file's.
    ::fchmod(temp, exists ? (st.st_mode & 07777) : new_file_mode());
    file_buffer_ = std::make_unique<FdBuffer>(temp);
    file_stream_ = std::make_unique<std::ostream>(file_buffer_.get());
    stream_ = file_stream_.get();
}

OutputFile::~OutputFile() {
    if (target_ != Target::regular || committed_) return;
    if (file_buffer_) ::close(file_buffer_->fd());
    ::unlink(temp_path_.c_str());
    unregister_temporary(temp_slot_);
}

void OutputFile::fail(const std::string& what, int error) const {
    throw OutputError(output_name(option_, path_) + ": " + what + ": " + reason(error));
}

void OutputFile::commit() {
    if (committed_) throw std::logic_error("cagd::OutputFile::commit: committed twice");
    if (target_ == Target::regular) {
        stream_->flush();
        int error = file_buffer_->error();
        const int fd = file_buffer_->fd();
        file_buffer_.reset();
        if (::close(fd) != 0 && error == 0) error = errno;
        file_stream_.reset();
        if (error != 0) {
            ::unlink(temp_path_.c_str());
            unregister_temporary(temp_slot_);
            committed_ = true;  // nothing left to remove
            fail("writing failed", error);
        }
        if (::rename(temp_path_.c_str(), final_.c_str()) != 0) {
            const int e = errno;
            ::unlink(temp_path_.c_str());
            unregister_temporary(temp_slot_);
            committed_ = true;
            fail("cannot replace it", e);
        }
        unregister_temporary(temp_slot_);
        committed_ = true;
        return;
    }
    committed_ = true;
    const std::string data = memory_.str();
    if (target_ == Target::descriptor) {
        // What the process printed before goes first.
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        if (const int error = write_all(descriptor_, data.data(), data.size())) fail("writing failed", error);
        return;
    }
    const int fd = ::open(final_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) fail("cannot open it for writing", errno);
    int error = write_all(fd, data.data(), data.size());
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) fail("writing failed", error);
}

// ---- OutputDirectory ----------------------------------------------------------------------------

OutputDirectory::OutputDirectory(const std::string& path, const std::string& option) : path_(path), option_(option) {
    namespace fs = std::filesystem;
    const std::string who = "cagd";
    if (path.empty() || path == "-")
        fail_input(who, option + " '" + path + "': give a directory (several files are written)");
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        if (!S_ISDIR(st.st_mode)) fail_input(who, option + " '" + path + "' exists and is not a directory");
        if (::access(path.c_str(), W_OK | X_OK) != 0) fail_input(who, option + " '" + path + "': " + reason(errno));
    } else if (errno == ELOOP) {
        fail_input(who, option + " '" + path + "': a loop of symbolic links");
    } else if (errno != ENOENT) {
        fail_input(who, option + " '" + path + "': " + reason(errno));
    }
    std::error_code ec;
    fs::path target = fs::path(path).lexically_normal();
    if (target.filename().empty()) target = target.parent_path();
    const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(parent, ec)) fail_input(who, option + " '" + path + "': its parent directory does not exist");
    // (appends: GCC 12 warns falsely of an oversized memcpy in "." + std::string&&)
    if (create_temporary((parent / std::string(".").append(target.filename().string()).append(".cagd-")).string(),
                         TemporaryKind::directory, staging_, staging_slot_) < 0)
        fail_input(who, option + " '" + path + "': cannot write in '" + parent.string() + "': " + reason(errno));
    ::chmod(staging_.c_str(), new_directory_mode());  // made 0700; a new directory's mode
}

OutputDirectory::~OutputDirectory() {
    for (int slot : staged_slots_) unregister_temporary(slot);
    for (const auto& scratch : scratch_) unregister_temporary(scratch.second);
    if (committed_) return;
    std::error_code ec;
    std::filesystem::remove_all(staging_, ec);
    unregister_temporary(staging_slot_);
}

std::string OutputDirectory::staged(const std::string& name) {
    if (name.empty() || name.find('/') != std::string::npos)
        throw std::logic_error("cagd::OutputDirectory::staged: '" + name + "' is not a file name");
    const std::string path = staging_ + "/" + name;
    staged_slots_.push_back(
        register_temporary(path, TemporaryKind::file));  // a signal removes it with the staging directory
    return path;
}

std::string OutputDirectory::scratch(const std::string& name) {
    if (name.empty() || name.find('/') != std::string::npos)
        throw std::logic_error("cagd::OutputDirectory::scratch: '" + name + "' is not a file name");
    const std::string path = staging_ + "/" + name;
    scratch_.emplace_back(path, register_temporary(path, TemporaryKind::file));
    return path;
}

void OutputDirectory::commit() {
    namespace fs = std::filesystem;
    if (committed_) throw std::logic_error("cagd::OutputDirectory::commit: committed twice");
    const auto fail = [&](const std::string& what, int error) {
        throw OutputError(option_ + " '" + path_ + "': " + what + ": " + reason(error));
    };
    for (const auto& [path, slot] : scratch_) {
        ::unlink(path.c_str());
        unregister_temporary(slot);
    }
    scratch_.clear();
    // A new directory: the staging directory becomes it, whole.
    for (int slot : staged_slots_) unregister_temporary(slot);
    staged_slots_.clear();
    if (::rename(staging_.c_str(), path_.c_str()) == 0) {
        unregister_temporary(staging_slot_);
        committed_ = true;
        return;
    }
    if (errno != EEXIST && errno != ENOTEMPTY) fail("cannot create it", errno);
    // An existing directory: its files are replaced one by one under an exclusive lock, so that two
    // runs never mix; rename replaces a link planted there instead of following it.
    const int dir = ::open(path_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0) fail("cannot open it", errno);
    if (::flock(dir, LOCK_EX) != 0) {
        const int e = errno;
        ::close(dir);
        fail("cannot lock it", e);
    }
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(staging_, ec)) {
        const std::string name = e.path().filename().string();
        if (::rename(e.path().c_str(), (fs::path(path_) / name).c_str()) != 0) {
            const int error = errno;
            ::close(dir);
            fail("cannot move '" + name + "' into it", error);
        }
    }
    ::close(dir);  // releases the lock
    ::rmdir(staging_.c_str());
    unregister_temporary(staging_slot_);
    committed_ = true;
}

}  // namespace cagd
