// The C allocator's entry points, forwarded to glibc's own (__libc_malloc and the others, which
// glibc exports for this purpose) and counted: every allocation of the process, C++'s operator
// new and Eigen's included, passes here. Linked into cagd_bench only.
#include "allocation_tracking.hpp"

#include <malloc.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>

extern "C" {
void* __libc_malloc(std::size_t);
void __libc_free(void*);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
}

namespace {

std::atomic<std::ptrdiff_t> live{0}, peak{0};

void count_allocated(void* p) {
    if (!p) return;
    const auto size = static_cast<std::ptrdiff_t>(malloc_usable_size(p));
    const auto now = live.fetch_add(size, std::memory_order_relaxed) + size;
    auto seen = peak.load(std::memory_order_relaxed);
    while (now > seen && !peak.compare_exchange_weak(seen, now, std::memory_order_relaxed)) {}
}

void count_freed(void* p) {
    if (p) live.fetch_sub(static_cast<std::ptrdiff_t>(malloc_usable_size(p)), std::memory_order_relaxed);
}

}  // namespace

namespace cagd_bench {

std::ptrdiff_t live_heap_bytes() { return live.load(); }
void reset_peak_heap_bytes() { peak.store(live.load()); }
std::ptrdiff_t peak_heap_bytes() { return peak.load(); }

}  // namespace cagd_bench

extern "C" {

void* malloc(std::size_t size) {
    void* p = __libc_malloc(size);
    count_allocated(p);
    return p;
}

void free(void* p) {
    count_freed(p);
    __libc_free(p);
}

void* calloc(std::size_t count, std::size_t size) {
    void* p = __libc_calloc(count, size);
    count_allocated(p);
    return p;
}

void* realloc(void* old, std::size_t size) {
    const std::size_t before = old ? malloc_usable_size(old) : 0;
    void* p = __libc_realloc(old, size);
    if (p || size == 0) {  // the old block is gone (moved, resized or freed)
        live.fetch_sub(static_cast<std::ptrdiff_t>(before), std::memory_order_relaxed);
        count_allocated(p);
    }
    return p;
}

void* memalign(std::size_t alignment, std::size_t size) {
    void* p = __libc_memalign(alignment, size);
    count_allocated(p);
    return p;
}

void* aligned_alloc(std::size_t alignment, std::size_t size) { return memalign(alignment, size); }

int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
    if (alignment < sizeof(void*) || (alignment & (alignment - 1)) != 0) return EINVAL;
    void* p = memalign(alignment, size);
    if (!p && size != 0) return ENOMEM;
    *out = p;
    return 0;
}

}  // extern "C"
