// io/file_lock: a second holder of the lock waits for the first.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <sstream>
#include <thread>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/io/file_lock.hpp"

using namespace cagd;

// The table caches' lock: a second holder of the same lock file waits until the first lets go, and
// a lock that cannot be created holds nothing (callers then go on unlocked).
TEST(FileLock, SecondHolderWaitsForTheFirst) {
    const std::string path = ::testing::TempDir() + "/file_lock_test.lock";
    auto first = std::make_unique<FileLock>(path);
    ASSERT_TRUE(first->held());
    std::atomic<bool> released{false}, second_holds{false}, released_before_second{false};
    std::thread other([&] {
        const FileLock second(path);
        released_before_second = released.load();
        second_holds = second.held();
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_FALSE(second_holds.load()) << "the second lock was granted while the first was held";
    released = true;
    first.reset();
    other.join();
    EXPECT_TRUE(second_holds.load());
    EXPECT_TRUE(released_before_second.load());
    EXPECT_FALSE(FileLock("/nonexistent-cagd-directory/x.lock").held());
}
