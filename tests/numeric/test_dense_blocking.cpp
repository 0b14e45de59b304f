// numeric/dense_blocking.hpp: with the blocking pinned, a dense solve gives the same bits whatever
// cache sizes Eigen read from the CPU (unpinned, the two cache sizes below give different bits in
// 598 of the 600 entries on the machine this was written on).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "cagd/numeric/dense_blocking.hpp"

namespace {

// A Householder QR solve of a 600 × 600 system: large enough for Eigen's blocked products.
Eigen::VectorXd dense_solve() {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::MatrixXd A(600, 600);
    Eigen::VectorXd b(600);
    for (Eigen::Index i = 0; i < A.size(); ++i) A.data()[i] = u(rng);
    for (Eigen::Index i = 0; i < b.size(); ++i) b(i) = u(rng);
    return A.householderQr().solve(b);
}

}  // namespace

TEST(DenseBlocking, PinnedBlockingGivesTheSameBitsWhateverCachesTheCpuReports) {
    std::ptrdiff_t l1 = 0, l2 = 0, l3 = 0;
    Eigen::internal::manage_caching_sizes(Eigen::GetAction, &l1, &l2, &l3);  // this machine's, restored below
    // Two machines: a 48 KiB L1 with a 2 MiB L2 and a 16 KiB L1 with a 256 KiB L2, each pinned.
    Eigen::setCpuCacheSizes(48 * 1024, 2 * 1024 * 1024, 504 * 1024 * 1024);
    cagd::numeric::pin_dense_blocking();
    const Eigen::VectorXd first = dense_solve();
    std::ptrdiff_t p1 = 0, p2 = 0, p3 = 0;
    Eigen::internal::manage_caching_sizes(Eigen::GetAction, &p1, &p2, &p3);
    EXPECT_EQ(p1, cagd::numeric::kPinnedL1CacheBytes);
    EXPECT_EQ(p2, cagd::numeric::kPinnedL2CacheBytes);
    EXPECT_EQ(p3, cagd::numeric::kPinnedL3CacheBytes);
    Eigen::setCpuCacheSizes(16 * 1024, 256 * 1024, 4 * 1024 * 1024);
    cagd::numeric::pin_dense_blocking();
    const Eigen::VectorXd second = dense_solve();
    Eigen::setCpuCacheSizes(l1, l2, l3);
    ASSERT_EQ(first.size(), second.size());
    for (Eigen::Index i = 0; i < first.size(); ++i) ASSERT_EQ(first(i), second(i)) << "entry " << i;
}
