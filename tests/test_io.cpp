// The readers' rules (core/point_csv.hpp): headers, byte-order marks, CRLF, separators, comments,
// and messages that name the line. Each case once lost or altered a point silently.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <sstream>
#include <thread>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/file_lock.hpp"
#include "cagd/core/point_csv.hpp"

using namespace cagd;

namespace {

PointList points(const std::string& text) {
    std::istringstream in(text);
    return read_points_csv(in, "p.csv");
}

std::string message_of(const std::string& text) {
    try {
        points(text);
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

TEST(PointReader, KeepsEveryPointWhateverTheLineEndsAndMarks) {
    for (const std::string text : {"0,0\n1,2\n", "0,0\r\n1,2\r\n",
                                   "\xEF\xBB\xBF"
                                   "0,0\n1,2\n",
                                   "\xEF\xBB\xBFx,y\r\n0,0\r\n1,2\r\n", "# c\n 0 , 0 # first\n\n1,\t2\n", "x_1,y-2\n0,0\n1,2\n"}) {
        const PointList p = points(text);
        ASSERT_EQ(p.rows(), 2) << text;
        EXPECT_EQ(p(0, 0), 0.0) << text;
        EXPECT_EQ(p(1, 1), 2.0) << text;
    }
}

TEST(PointReader, AFirstLineIsAHeaderOnlyIfAllItsFieldsAreNames) {
    // A typo, a whitespace separator, a mixed line, names that are numbers: errors naming line 1.
    for (const std::string text : {"0,0x\n1,1\n2,0\n", "0 0\n1 1\n", "x,1\n1,1\n2,0\n", "nan,inf\n1,1\n2,0\n", "x,\n1,1\n", "1x,y\n1,1\n"}) {
        const std::string m = message_of(text);
        EXPECT_NE(m.find("p.csv:1:"), std::string::npos) << text << " -> " << m;
    }
    EXPECT_NE(message_of("0,0x\n").find("'0x' in '0,0x' is not a number"), std::string::npos) << message_of("0,0x\n");
    // A second header-like line is data that does not parse.
    EXPECT_NE(message_of("x,y\nu,v\n1,1\n").find("p.csv:2:"), std::string::npos);
}

TEST(PointReader, NamesTheLineOfEveryOtherFault) {
    EXPECT_NE(message_of("0,0\n1,1,1\n").find("p.csv:2: 3 columns, earlier lines have 2"), std::string::npos) << message_of("0,0\n1,1,1\n");
    EXPECT_NE(message_of("0,0\n1,nan\n").find("p.csv:2: coordinate nan is not finite"), std::string::npos) << message_of("0,0\n1,nan\n");
    EXPECT_NE(message_of("0\n1\n").find("p.csv:1: 1 columns"), std::string::npos) << message_of("0\n1\n");
    EXPECT_NE(message_of("x,y\n").find("no data rows"), std::string::npos);
    EXPECT_NE(message_of("").find("no data rows"), std::string::npos);
    // A long line is quoted by its first 37 characters only.
    const std::string long_line(100000, '7');
    const std::string m = message_of("0,0\n" + long_line + "x\n");
    EXPECT_LT(m.size(), 300u) << m.substr(0, 300);
    EXPECT_NE(m.find("p.csv:2:"), std::string::npos);
}

TEST(ValuesAndTables, FollowTheSameRules) {
    std::istringstream values(
        "\xEF\xBB\xBF"
        "lambda\r\n0.5\r\n# c\n1e-3\n");
    EXPECT_EQ(read_values_csv(values, "v.csv"), (std::vector<double>{0.5, 1e-3}));
    std::istringstream table("\xEF\xBB\xBFu,x,y\r\n0,1,2\r\n");
    const NumericTable t = read_numeric_table(table, "t.csv");
    EXPECT_EQ(t.header, (std::vector<std::string>{"u", "x", "y"}));
    ASSERT_EQ(t.rows.size(), 1u);
    EXPECT_EQ(t.rows[0][2], 2.0);
    std::istringstream no_header("0,1,2\n");
    try {
        read_numeric_table(no_header, "t.csv");
        ADD_FAILURE() << "a table without header accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("t.csv:1: needs a header line of column names"), std::string::npos) << e.what();
    }
    std::istringstream inf_row("u,x\n0,inf\n");
    EXPECT_THROW(read_numeric_table(inf_row, "t.csv"), InvalidInput);
    EXPECT_TRUE(is_column_name("dx") && is_column_name("_a.b-c") && !is_column_name("nan") && !is_column_name("Inf") && !is_column_name("1x") && !is_column_name(""));
}

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
