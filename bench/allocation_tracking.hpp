#pragma once
// Heap bytes in use, for the memory figures of make bench (allocation_tracking.cpp replaces the
// C allocator's entry points in the benchmark executable, and only there): what a construction
// keeps (live bytes after it, less those before) and its peak (the most live at any moment during
// it, less those before). Bytes are the allocator's usable sizes, so a figure includes the
// rounding of each block; memory mapped by other means (none in the library) is not counted.
#include <cstddef>

namespace cagd_bench {

/// Bytes allocated and not yet freed, now.
std::ptrdiff_t live_heap_bytes();
/// Restarts the peak at the live bytes of now.
void reset_peak_heap_bytes();
/// The most bytes live at any moment since the last reset.
std::ptrdiff_t peak_heap_bytes();

}  // namespace cagd_bench
