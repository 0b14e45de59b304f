#include "cli/process_setup.hpp"

#include <fcntl.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <unistd.h>

#include "cagd/io/output_file.hpp"
#include "cagd/numeric/dense_blocking.hpp"

namespace cagd::cli {

namespace {

// A closed standard descriptor is held by /dev/null opened the wrong way round, so that no file the
// command opens takes its number: writing to a closed standard output then fails instead of
// landing in that file (standard error: messages are lost, as the caller asked).
void hold_closed_standard_descriptors() {
    for (int fd : {0, 1, 2})
        if (::fcntl(fd, F_GETFD) < 0) {
            const int held = ::open("/dev/null", fd == 0 ? O_WRONLY : O_RDONLY);
            if (held >= 0 && held != fd) {
                ::dup2(held, fd);
                ::close(held);
            }
        }
}

// A command allocates and frees the same large arrays many times over (`cagd compare` builds 23
// curves with their tables and Jacobians). glibc maps an allocation above its threshold afresh
// and unmaps it when freed, and returns the freed top of the heap to the system, so the same pages
// fault in again and again: at 10^5 points compare spent 0.58 of its 7.9 CPU-s in the kernel,
// 0.28 with this. A command is short-lived: it keeps what it frees for reuse, and maps afresh
// only allocations above 1 GiB. (Peak memory is unchanged: freed pages are reused, not added.)
void keep_freed_memory() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace

void prepare_command_process() {
    hold_closed_standard_descriptors();
    numeric::pin_dense_blocking();
    keep_freed_memory();
    install_output_signal_cleanup();
}

}  // namespace cagd::cli
