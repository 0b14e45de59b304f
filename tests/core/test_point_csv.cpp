// core/point_csv and core/csv: the readers' rules (header, comments, line ends, marks), every
// fault named by its line; values and tables read by the same rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/pchip.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/core/random_walk.hpp"
#include "cagd/io/file_lock.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "cagd/methods/method_registry.hpp"

using std::isnan;
using namespace cagd;
using namespace cagd::compare;
using namespace cagd::methods;
using namespace cagd::locality;

namespace {

PointList points_from_text(const std::string& text) {
    std::istringstream in(text);
    return read_points_csv(in, "p.csv");
}

std::string message_of(const std::string& text) {
    try {
        points_from_text(text);
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

// The point reader: header or none, comments, blank lines, whitespace, 2 or 3 columns; errors
// name the line.
TEST(PointReader, AcceptsTheDocumentedForms) {
    const auto read = [](const std::string& text) {
        std::istringstream in(text);
        return read_points_csv(in, "test.csv");
    };
    const PointList a = read("x,y\n0,1\n2,3\n");
    ASSERT_EQ(a.rows(), 2);
    EXPECT_EQ(a(1, 1), 3.0);
    const PointList b = read("# points\n\n  0 , 1  \n\t2,3 # trailing\n\n");
    ASSERT_EQ(b.rows(), 2);
    EXPECT_EQ(b(0, 1), 1.0);
    EXPECT_EQ(b(1, 0), 2.0);
    const PointList c = read("1,2,3\n4,5,6\n");
    EXPECT_EQ(c.cols(), 3);
    EXPECT_EQ(c(1, 2), 6.0);
    const PointList d = read("1e-8,-2.5E+3\r\n");
    EXPECT_EQ(d(0, 1), -2500.0);
}

TEST(PointReader, ErrorsNameTheLine) {
    const auto message = [](const std::string& text) {
        std::istringstream in(text);
        try {
            read_points_csv(in, "p.csv");
        } catch (const InvalidInput& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("x,y\n0,1\n2,zz\n").find("p.csv:3"), std::string::npos);
    EXPECT_NE(message("0,1\n2,3,4\n").find("p.csv:2"), std::string::npos);
    EXPECT_NE(message("0\n").find("p.csv:1"), std::string::npos);
    EXPECT_NE(message("0,1,2,3\n").find("p.csv:1"), std::string::npos);
    EXPECT_NE(message("0,1\n1,nan\n").find("p.csv:2"), std::string::npos);
    EXPECT_NE(message("0,1\n1,inf\n").find("p.csv:2"), std::string::npos);
    EXPECT_NE(message("# only a comment\n\n").find("no data rows"), std::string::npos);
    EXPECT_NE(message("x,y\nu,v\n").find("p.csv:2"), std::string::npos);
    EXPECT_NE(message("0,1\n2,3,\n").find("p.csv:2"), std::string::npos);
    // What the message says besides the line.
    EXPECT_NE(message("1,2\n3,4,5\n").find("p.csv:2: 3 columns"), std::string::npos);
    EXPECT_NE(message("1\n").find("p.csv:1: 1 columns"), std::string::npos);
    EXPECT_NE(message("1,nan\n").find("not finite"), std::string::npos);
    EXPECT_NE(message("# only a comment\n").find("no points"), std::string::npos);
}

TEST(PointReader, KeepsEveryPointWhateverTheLineEndsAndMarks) {
    for (const std::string text :
         {"0,0\n1,2\n", "0,0\r\n1,2\r\n",
          "\xEF\xBB\xBF"
          "0,0\n1,2\n",
          "\xEF\xBB\xBFx,y\r\n0,0\r\n1,2\r\n", "# c\n 0 , 0 # first\n\n1,\t2\n", "x_1,y-2\n0,0\n1,2\n"}) {
        const PointList p = points_from_text(text);
        ASSERT_EQ(p.rows(), 2) << text;
        EXPECT_EQ(p(0, 0), 0.0) << text;
        EXPECT_EQ(p(1, 1), 2.0) << text;
    }
}

TEST(PointReader, AFirstLineIsAHeaderOnlyIfAllItsFieldsAreNames) {
    // A typo, a whitespace separator, a mixed line, names that are numbers: errors naming line 1.
    for (const std::string text :
         {"0,0x\n1,1\n2,0\n", "0 0\n1 1\n", "x,1\n1,1\n2,0\n", "nan,inf\n1,1\n2,0\n", "x,\n1,1\n", "1x,y\n1,1\n"}) {
        const std::string m = message_of(text);
        EXPECT_NE(m.find("p.csv:1:"), std::string::npos) << text << " -> " << m;
    }
    EXPECT_NE(message_of("0,0x\n").find("'0x' in '0,0x' is not a number"), std::string::npos) << message_of("0,0x\n");
    // A second header-like line is data that does not parse.
    EXPECT_NE(message_of("x,y\nu,v\n1,1\n").find("p.csv:2:"), std::string::npos);
}

TEST(PointReader, NamesTheLineOfEveryOtherFault) {
    EXPECT_NE(message_of("0,0\n1,1,1\n").find("p.csv:2: 3 columns, earlier lines have 2"), std::string::npos)
        << message_of("0,0\n1,1,1\n");
    EXPECT_NE(message_of("0,0\n1,nan\n").find("p.csv:2: coordinate nan is not finite"), std::string::npos)
        << message_of("0,0\n1,nan\n");
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
        EXPECT_NE(std::string(e.what()).find("t.csv:1: needs a header line of column names"), std::string::npos)
            << e.what();
    }
    std::istringstream inf_row("u,x\n0,inf\n");
    EXPECT_THROW(read_numeric_table(inf_row, "t.csv"), InvalidInput);
    EXPECT_TRUE(is_column_name("dx") && is_column_name("_a.b-c") && !is_column_name("nan") && !is_column_name("Inf") &&
                !is_column_name("1x") && !is_column_name(""));
}

TEST(PointReader, ReadsHeaderCommentsBlanksAndThreeColumns) {
    std::istringstream in("# my points\nx, y, z\n\n 1, 2, 3 \n4,5,6 # trailing\n");
    const PointList p = read_points_csv(in, "mem");
    ASSERT_EQ(p.rows(), 2);
    ASSERT_EQ(p.cols(), 3);
    EXPECT_EQ(p(1, 2), 6.0);
}
