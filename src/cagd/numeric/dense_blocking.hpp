#pragma once
/// @file
/// The same rounding of Eigen's large dense products on every machine. Eigen splits a large matrix
/// product (and the QR and LU factorisations built on products) into blocks sized for the CPU's
/// caches, which it reads with CPUID before its first product; the blocks fix the order in which
/// each entry's terms are summed. So the same dense solve rounds differently on machines whose
/// caches differ: Eigen's spline fit of degree 5 through 384 or 768 points (the eigen-spline peer)
/// gives control points that differ in their last bits between a 32 KiB and a 48 KiB L1 data
/// cache, which moves the fourth digit of the benchmark's curvature errors near 1e−10.
/// pin_dense_blocking() makes Eigen plan for fixed cache sizes, so every product rounds the same
/// everywhere; only speed depends on them, and these fit the caches of current x86-64 CPUs. It
/// sets process-wide state: the `cagd` command and the reproduction harness call it at start, and a
/// program that wants their bits calls it before its first dense product.
#include <Eigen/Core>
#include <cstddef>

namespace cagd::numeric {

/// The L1, L2 and L3 cache sizes (bytes) pin_dense_blocking() gives Eigen: those of the machine
/// on which results/ was first regenerated (a 32 KiB L1 data cache), so that it still reproduces.
inline constexpr std::ptrdiff_t kPinnedL1CacheBytes = 32 * 1024;
inline constexpr std::ptrdiff_t kPinnedL2CacheBytes = 1024 * 1024;       ///< see kPinnedL1CacheBytes
inline constexpr std::ptrdiff_t kPinnedL3CacheBytes = 32 * 1024 * 1024;  ///< see kPinnedL1CacheBytes

/// Eigen's product blocking planned for the pinned cache sizes (above), whatever this CPU's are.
inline void pin_dense_blocking() {
    Eigen::setCpuCacheSizes(kPinnedL1CacheBytes, kPinnedL2CacheBytes, kPinnedL3CacheBytes);
}

}  // namespace cagd::numeric
