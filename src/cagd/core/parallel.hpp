#pragma once
/// @file
/// A parallel loop: body(k) for k in [0, count) on `threads` workers (the calling thread is one of
/// them), each taking the next unclaimed index in increasing order (dynamic scheduling, so a few
/// long bodies do not leave a worker idle). Results are deterministic when body(k) writes only what
/// belongs to index k and depends on nothing another index writes. progress(done, count) is called
/// from the workers now and then (every 256 and at the end; may be empty). If body throws, the
/// workers still run every index below the lowest failed one (and skip those above it); after all
/// have joined, the exception of the lowest failed index is rethrown: the one a serial loop would
/// have thrown, whatever the thread count.
#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace cagd {

/// False in a WebAssembly build without threads: parallel_for then runs on the calling thread.
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool kThreadsAvailable = false;
#else
inline constexpr bool kThreadsAvailable = true;
#endif

/// The hardware's thread count (at least 1): the default for the callers' `threads`. 1 in a
/// WebAssembly build without threads (Emscripten without -pthread cannot start a std::thread).
inline int hardware_threads() {
    return kThreadsAvailable ? static_cast<int>(std::max(1u, std::thread::hardware_concurrency())) : 1;
}

template <class Body>
/// Runs body(k) for k = 0..count−1 on `threads` threads (at most count), each k once; an exception
/// thrown by body stops the others from starting new indices and the one of the lowest failing index
/// is rethrown here. progress(done, count) is called every 256 indices and at the end.
void parallel_for(long count, int threads, const Body& body, const std::function<void(long, long)>& progress = {}) {
    // Without thread support (WebAssembly without -pthread) every index runs on the calling thread;
    // the results are the same (see above).
    threads = static_cast<int>(std::clamp<long>(threads, 1, kThreadsAvailable ? std::max(count, 1L) : 1L));
    std::atomic<long> next{0}, done{0}, error_index{count};
    std::mutex error_mutex;
    std::exception_ptr error;
    const auto worker = [&] {
        for (long k = next++; k < count && k < error_index.load(); k = next++) {
            try {
                body(k);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(error_mutex);
                if (k < error_index.load()) error_index = k, error = std::current_exception();
                return;
            }
            const long d = ++done;
            if (progress && (d % 256 == 0 || d == count)) progress(d, count);
        }
    };
    std::vector<std::thread> pool;
    for (int w = 1; w < threads; ++w) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace cagd
