// core/errors: every bad-input message is one line, control bytes shown escaped.
#include <gtest/gtest.h>

#include <string>

#include "cagd/core/errors.hpp"

using namespace cagd;

TEST(Messages, ControlBytesAreShownEscapedOnOneLine) {
    EXPECT_EQ(one_line("a\nb\r\tc\x1b[31md\x7f  "), "a b  c\\x1b[31md\\x7f");
    EXPECT_EQ(one_line("κ ≤ 1"), "κ ≤ 1") << "UTF-8 is kept";
    try {
        fail_input("who", "line 1\nline 2\x1b");
        FAIL() << "fail_input returned";
    } catch (const InvalidInput& e) {
        EXPECT_STREQ(e.what(), "who: line 1 line 2\\x1b");
    }
}
