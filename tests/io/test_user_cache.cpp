// io/user_cache: where the user's table cache is, how it is turned off, and a cached table that
// equals the built one bit for bit, built once (one notice) and then loaded.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "cagd/fairness/pseudo_energy_table.hpp"
#include "cagd/io/user_cache.hpp"

using namespace cagd;
namespace fs = std::filesystem;

namespace {

// Sets (or, for nullptr, unsets) an environment variable for the test's lifetime.
class CacheEnvironment {
public:
    CacheEnvironment(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value != nullptr)
            ::setenv(name, value, 1);
        else
            ::unsetenv(name);
    }
    ~CacheEnvironment() {
        if (old_)
            ::setenv(name_.c_str(), old_->c_str(), 1);
        else
            ::unsetenv(name_.c_str());
    }
    CacheEnvironment(const CacheEnvironment&) = delete;
    CacheEnvironment& operator=(const CacheEnvironment&) = delete;

private:
    std::string name_;
    std::optional<std::string> old_;
};

std::string fresh_cache_directory(const std::string& name) {
    const fs::path d = fs::path(::testing::TempDir()) / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d.string();
}

int cache_build_notices = 0;
std::string cache_noticed_path;
void count_cache_build_notice(const std::string& path, const std::string&) {
    ++cache_build_notices;
    cache_noticed_path = path;
}

}  // namespace

TEST(UserCache, XdgCacheHomeThenHomeAndTheWaysToTurnItOff) {
    const std::string xdg = fresh_cache_directory("user_cache_xdg"), home = fresh_cache_directory("user_cache_home");
    const CacheEnvironment no_switch("CAGD_NO_CACHE", nullptr);
    const CacheEnvironment h("HOME", home.c_str());
    {
        const CacheEnvironment x("XDG_CACHE_HOME", xdg.c_str());
        EXPECT_EQ(user_cache_directory(), xdg + "/cagd");
        EXPECT_TRUE(fs::is_directory(xdg + "/cagd"));
    }
    {
        const CacheEnvironment x("XDG_CACHE_HOME", "relative/place");  // ignored, as the XDG specification says
        EXPECT_EQ(user_cache_directory(), home + "/.cache/cagd");
    }
    const CacheEnvironment x("XDG_CACHE_HOME", nullptr);
    EXPECT_EQ(user_cache_directory(), home + "/.cache/cagd");
    {
        const CacheEnvironment off("CAGD_NO_CACHE", "1");
        EXPECT_EQ(user_cache_directory(), std::nullopt);
    }
    {
        const CacheEnvironment zero("CAGD_NO_CACHE", "0");  // "0" does not turn it off
        EXPECT_EQ(user_cache_directory(), home + "/.cache/cagd");
    }
    set_user_cache_enabled(false);
    EXPECT_EQ(user_cache_directory(), std::nullopt);
    set_user_cache_enabled(true);
    {
        const std::string file = home + "/not_a_directory";
        std::ofstream(file) << "x";
        const CacheEnvironment blocked("XDG_CACHE_HOME", file.c_str());  // cannot be created: off
        EXPECT_EQ(user_cache_directory(), std::nullopt);
    }
}

// The planar table of the pseudo-spline: built once with one notice, then loaded without one, equal
// to the in-memory build bit for bit; with the cache off, built in memory and nothing written.
TEST(UserCache, PseudoEnergyTableIsBuiltOnceThenLoadedEqualToTheBuild) {
    const std::string xdg = fresh_cache_directory("user_cache_table");
    const CacheEnvironment no_switch("CAGD_NO_CACHE", nullptr);
    const CacheEnvironment x("XDG_CACHE_HOME", xdg.c_str());
    const fairness::AngleGrid grid{8, fairness::NodePlacement::periodic};
    const fairness::PseudoEnergyTable built = fairness::PseudoEnergyTable::build(grid, fairness::TableMethod::fast);
    set_cache_build_notice(count_cache_build_notice);
    cache_build_notices = 0;
    const fairness::PseudoEnergyTable first =
        fairness::PseudoEnergyTable::user_cached(grid, fairness::TableMethod::fast);
    EXPECT_EQ(cache_build_notices, 1);
    EXPECT_EQ(cache_noticed_path.rfind(xdg + "/cagd/", 0), 0u) << cache_noticed_path;
    EXPECT_TRUE(fs::exists(cache_noticed_path));
    const fairness::PseudoEnergyTable second =
        fairness::PseudoEnergyTable::user_cached(grid, fairness::TableMethod::fast);
    EXPECT_EQ(cache_build_notices, 1) << "a warm cache is loaded, not built";
    for (const fairness::PseudoEnergyTable* t : {&first, &second})
        for (int i = 0; i < grid.n; ++i)
            for (int j = 0; j < grid.n; ++j) {
                EXPECT_EQ(t->node(i, j).pseudo_energy, built.node(i, j).pseudo_energy);
                EXPECT_EQ(t->node(i, j).r0, built.node(i, j).r0);
                EXPECT_EQ(t->node(i, j).r1, built.node(i, j).r1);
            }
    const CacheEnvironment off("CAGD_NO_CACHE", "1");
    fs::remove_all(xdg + "/cagd");
    const fairness::PseudoEnergyTable third =
        fairness::PseudoEnergyTable::user_cached(grid, fairness::TableMethod::fast);
    EXPECT_EQ(cache_build_notices, 1) << "with the cache off, no cached table is built";
    EXPECT_FALSE(fs::exists(xdg + "/cagd"));
    EXPECT_EQ(third.node(3, 5).pseudo_energy, built.node(3, 5).pseudo_energy);
    set_cache_build_notice(nullptr);
}

// A cache file that cannot be written (here a directory stands where the file goes) costs nothing
// but the cache: the table is built, returned equal to the in-memory build, and the place is left
// as it was.
TEST(UserCache, AnUnwritableCacheFileLeavesTheTableInMemory) {
    const std::string xdg = fresh_cache_directory("user_cache_unwritable");
    const CacheEnvironment no_switch("CAGD_NO_CACHE", nullptr);
    const CacheEnvironment x("XDG_CACHE_HOME", xdg.c_str());
    const fairness::AngleGrid grid{6, fairness::NodePlacement::periodic};
    const std::string blocked = xdg + "/cagd/pseudo-energy-table-6-periodic-fast.txt";
    fs::create_directories(blocked);
    const fairness::PseudoEnergyTable built = fairness::PseudoEnergyTable::build(grid, fairness::TableMethod::fast);
    const fairness::PseudoEnergyTable t = fairness::PseudoEnergyTable::user_cached(grid, fairness::TableMethod::fast);
    for (int i = 0; i < grid.n; ++i)
        for (int j = 0; j < grid.n; ++j) EXPECT_EQ(t.node(i, j).pseudo_energy, built.node(i, j).pseudo_energy);
    EXPECT_TRUE(fs::is_directory(blocked));
    EXPECT_TRUE(fs::is_empty(blocked));
}
