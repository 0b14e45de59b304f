// io/child_process: a program run as a pipe, its streams written and read together, its run bounded.
#include <gtest/gtest.h>

#include <csignal>
#include <string>

#include "cagd/io/child_process.hpp"

using namespace cagd;

TEST(ChildProcess, InputGoesInOutputAndStatusComeBack) {
    const ProgramRun r = run_program({"sh", "-c", "tr a-z A-Z; echo oops >&2; exit 4"}, "hello\n");
    EXPECT_TRUE(r.started);
    EXPECT_EQ(r.output, "HELLO\n");
    EXPECT_EQ(r.error, "oops\n");
    EXPECT_EQ(r.exit_status, 4);
    EXPECT_FALSE(r.succeeded());
    EXPECT_EQ(r.describe(), "exit status 4: oops");
}

TEST(ChildProcess, LargeStreamsBothWaysDoNotBlock) {
    // 8 MB through cat: neither side may wait for the other's full pipe.
    const std::string input(8 << 20, 'x');
    const ProgramRun r = run_program({"cat"}, input);
    EXPECT_TRUE(r.succeeded()) << r.describe();
    EXPECT_EQ(r.output.size(), input.size());
}

TEST(ChildProcess, TheEnvironmentIsAddedTo) {
    const ProgramRun r = run_program({"sh", "-c", "printf %s \"$CAGD_TEST_VALUE\""}, "", {{"CAGD_TEST_VALUE", "42"}});
    EXPECT_EQ(r.output, "42");
}

TEST(ChildProcess, AProgramThatStopsReadingIsNotTheEndOfThisProcess) {
    // The program exits without reading 8 MB: the write fails with EPIPE, SIGPIPE is not delivered
    // (this test process would end by it), and the run reports the program's own status.
    const ProgramRun r = run_program({"sh", "-c", "exit 0"}, std::string(8 << 20, 'x'));
    EXPECT_TRUE(r.started);
    EXPECT_EQ(r.exit_status, 0);
}

TEST(ChildProcess, LimitsKillTheProgramAndSaySo) {
    const ProgramRun slow = run_program({"sleep", "30"}, "", {}, 0.3);
    EXPECT_TRUE(slow.timed_out);
    EXPECT_EQ(slow.signal, SIGKILL);
    EXPECT_NE(slow.describe().find("timed out"), std::string::npos);
    const ProgramRun loud = run_program({"yes"}, "", {}, 30.0, 1 << 20);
    EXPECT_TRUE(loud.too_much);
    EXPECT_FALSE(loud.succeeded());
}

TEST(ChildProcess, AMissingProgramIsNotStartedAndNamed) {
    const ProgramRun r = run_program({"/nonexistent/cagd-no-such-program"}, "");
    EXPECT_FALSE(r.started);
    EXPECT_NE(r.error.find("/nonexistent/cagd-no-such-program"), std::string::npos) << r.error;
    EXPECT_NE(r.describe().find("could not be started"), std::string::npos);
}
