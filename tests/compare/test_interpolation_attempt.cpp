// compare::attempt_interpolation, the one attempt path of compare and the benchmark, and
// AttemptStatus, the one status type: its text is written and read back only by the writers.
#include <gtest/gtest.h>

#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/compare/method_comparison.hpp"

namespace {

using cagd::compare::AttemptStatus;

TEST(AttemptStatus, EveryStatusReadsBackFromItsTextAndNothingElseDoes) {
    for (const AttemptStatus s :
         {AttemptStatus::ok, AttemptStatus::not_applicable, AttemptStatus::refused, AttemptStatus::no_result,
          AttemptStatus::cusp, AttemptStatus::loops, AttemptStatus::failed}) {
        const std::optional<AttemptStatus> back =
            cagd::compare::attempt_status_from_string(cagd::compare::to_string(s));
        ASSERT_TRUE(back.has_value()) << cagd::compare::to_string(s);
        EXPECT_EQ(*back, s) << cagd::compare::to_string(s);
    }
    for (const char* text : {"", "OK", "no-result", "not_applicable", "?"})
        EXPECT_FALSE(cagd::compare::attempt_status_from_string(text).has_value()) << text;
}

TEST(AttemptInterpolation, CompareReportsWhatTheAttemptReports) {
    // A closed quadrilateral: pchip does not apply (open curves only), cubic-b builds, and
    // whatever curvature-profile's Newton gives, compare's row says the same.
    cagd::PointList p(4, 2);
    p << 0, 0, 1, 0, 2, 1, 1, 2;
    cagd::compare::ComparisonOptions o;
    o.closed = true;
    o.measures = false;
    o.methods = {"boost-pchip", "cubic-b", "curvature-profile"};
    const std::vector<cagd::compare::MethodComparison> rows = cagd::compare::compare_methods(p, o);
    ASSERT_EQ(rows.size(), 3u);
    for (const auto& row : rows) {
        const auto attempt =
            cagd::compare::attempt_interpolation(cagd::methods::find_configuration(row.method), p, true);
        EXPECT_EQ(row.status, attempt.status) << row.method << ": " << row.note << " / " << attempt.note;
        EXPECT_EQ(row.note, attempt.note) << row.method;
    }
    EXPECT_EQ(rows[0].status, AttemptStatus::not_applicable) << "pchip is open only: " << rows[0].note;
    EXPECT_EQ(rows[1].status, AttemptStatus::ok) << rows[1].note;
}

}  // namespace
