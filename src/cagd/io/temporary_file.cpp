#include "cagd/io/temporary_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <random>
#include <system_error>

#include "cagd/core/errors.hpp"

namespace cagd {

namespace {

// Slots: 0 free, 1 being filled, 2 a file, 3 a directory (read by a signal handler).
constexpr int kSlots = 256;
constexpr std::size_t kSlotPath = 4096;
constexpr int kFileSlot = 2, kDirectorySlot = 3;
struct Slot {
    std::atomic<int> state{0};
    char path[kSlotPath]{};
};
// Constant-initialised (zero, in .bss): no code runs at start-up, and the megabyte's pages are
// touched only when a slot is used.
constinit Slot slots[kSlots];

// 16 letters and digits from the system's entropy: 62^16 names, none another file's.
std::string random_suffix() {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    thread_local std::mt19937_64 draw{[] {
        std::random_device device;
        return (static_cast<std::uint64_t>(device()) << 32) ^ device();
    }()};
    std::uniform_int_distribution<std::size_t> letter(0, sizeof kAlphabet - 2);
    std::string s(16, ' ');
    for (char& c : s) c = kAlphabet[letter(draw)];
    return s;
}

}  // namespace

int register_temporary(const std::string& path, TemporaryKind kind) {
    if (path.size() + 1 > kSlotPath) return -1;
    for (int i = 0; i < kSlots; ++i) {
        int free = 0;
        if (slots[i].state.compare_exchange_strong(free, 1)) {
            std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
            slots[i].state.store(kind == TemporaryKind::file ? kFileSlot : kDirectorySlot);
            return i;
        }
    }
    return -1;
}

void unregister_temporary(int slot) {
    if (slot >= 0) slots[slot].state.store(0);
}

int create_temporary(const std::string& prefix, TemporaryKind kind, std::string& path, int& slot) {
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::string name = prefix + random_suffix();
        const int s = register_temporary(name, kind);
        if (s < 0) {
            errno = EOVERFLOW;
            return -1;
        }
        const int made = kind == TemporaryKind::file ? ::open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600)
                                                     : ::mkdir(name.c_str(), 0700);
        if (made >= 0) {
            path = name;
            slot = s;
            return made;
        }
        const int error = errno;
        unregister_temporary(s);
        if (error != EEXIST) {
            errno = error;
            return -1;
        }
    }
    errno = EEXIST;
    return -1;
}

void remove_output_temporaries() noexcept {
    for (int kind : {kFileSlot, kDirectorySlot})  // files first, then the directories that held them
        for (Slot& s : slots)
            if (s.state.load() == kind) {
                if (kind == kFileSlot)
                    ::unlink(s.path);
                else
                    ::rmdir(s.path);
            }
}

namespace {

extern "C" void remove_temporaries_and_reraise(int signal) {
    remove_output_temporaries();
    ::signal(signal, SIG_DFL);
    ::raise(signal);  // delivered when the handler returns: the default action, status 128 + signal
}

}  // namespace

void install_output_signal_cleanup() {
    for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) {
        struct sigaction old {};
        if (::sigaction(signal, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;  // kept ignored (nohup)
        struct sigaction action {};
        action.sa_handler = remove_temporaries_and_reraise;
        sigemptyset(&action.sa_mask);
        ::sigaction(signal, &action, nullptr);
    }
}

TemporaryFile::TemporaryFile(const std::string& prefix, const char* who) {
    const int fd = create_temporary(prefix, TemporaryKind::file, path_, slot_);
    if (fd < 0)
        fail_input(who,
                   "no temporary file " + prefix + "…: " + std::error_code(errno, std::generic_category()).message());
    ::close(fd);
}

TemporaryFile::~TemporaryFile() {
    ::unlink(path_.c_str());
    unregister_temporary(slot_);
}

}  // namespace cagd
