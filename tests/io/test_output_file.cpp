// io/output_file: a write is published whole by commit() or not at all; a failed write names the
// path and the reason and keeps the old file; bad places are refused when the output is made; a
// multi-file output is published as one; signal cleanup removes every temporary.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/io/temporary_file.hpp"
#include "cagd/io/csv_writer.hpp"
#include "cagd/io/output_file.hpp"

#include "../support/messages.hpp"
#include "../support/scratch_directory.hpp"

using namespace cagd;
using cagd::test::invalid_input_message;
namespace fs = std::filesystem;

namespace {

std::string contents(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Names in `dir` that the writer makes for itself (".name.cagd-XXXXXX").
int temporaries_in(const fs::path& dir) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir))
        n += e.path().filename().string().find(".cagd-") != std::string::npos;
    return n;
}

}  // namespace

TEST(OutputFile, CommitPublishesAndKeepsTheReplacedFilesMode) {
    cagd::test::ScratchDirectory s;
    const std::string f = s.path("out.csv");
    { std::ofstream(f) << "old\n"; }
    ::chmod(f.c_str(), 0640);
    OutputFile out(f);
    out.stream() << "new\n";
    EXPECT_EQ(contents(f), "old\n") << "nothing appears before commit()";
    EXPECT_EQ(temporaries_in(s.dir), 1);
    out.commit();
    EXPECT_EQ(contents(f), "new\n");
    EXPECT_EQ(temporaries_in(s.dir), 0);
    struct stat st {};
    ASSERT_EQ(::stat(f.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u) << "the replaced file's mode";
}

TEST(OutputFile, WithoutCommitTheOldFileStaysAndNothingIsLeft) {
    cagd::test::ScratchDirectory s;
    const std::string f = s.path("out.csv");
    { std::ofstream(f) << "old\n"; }
    {
        OutputFile out(f);
        out.stream() << "half a result";
    }
    EXPECT_EQ(contents(f), "old\n");
    EXPECT_EQ(temporaries_in(s.dir), 0);
}

TEST(OutputFile, ALinkKeepsPointingWhereItDidAndItsTargetIsReplaced) {
    cagd::test::ScratchDirectory s;
    { std::ofstream(s.path("target.csv")) << "old\n"; }
    fs::create_symlink("target.csv", s.path("link.csv"));
    OutputFile out(s.path("link.csv"));
    out.stream() << "new\n";
    out.commit();
    EXPECT_TRUE(fs::is_symlink(s.path("link.csv")));
    EXPECT_EQ(contents(s.path("target.csv")), "new\n");
}

TEST(OutputFile, BadPlacesAreRefusedWhenTheOutputIsMade) {
    cagd::test::ScratchDirectory s;
    fs::create_symlink("b", s.path("a"));
    fs::create_symlink("a", s.path("b"));
    const std::string loop = invalid_input_message([&] { OutputFile out(s.path("a")); });
    EXPECT_NE(loop.find("loop of symbolic links"), std::string::npos) << loop;
    const std::string directory = invalid_input_message([&] { OutputFile out(s.dir.string()); });
    EXPECT_NE(directory.find("is a directory"), std::string::npos) << directory;
    const std::string missing = invalid_input_message([&] { OutputFile out(s.path("no/such/file.csv")); });
    EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
    const std::string empty = invalid_input_message([&] { OutputFile out(""); });
    EXPECT_NE(empty.find("empty"), std::string::npos) << empty;
    EXPECT_TRUE(fs::is_symlink(s.path("a")) && fs::is_symlink(s.path("b"))) << "the loop is left as it was";
}

TEST(OutputFile, AFailedWriteNamesThePathAndTheReason) {
    // /dev/full: every write fails with ENOSPC. A device is written in place at commit().
    OutputFile out("/dev/full");
    out.stream() << "data\n";
    try {
        out.commit();
        FAIL() << "a write to /dev/full was reported as a success";
    } catch (const OutputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("'/dev/full'"), std::string::npos) << m;
        EXPECT_NE(m.find("No space left on device"), std::string::npos) << m;
    }
}

TEST(OutputDirectory, PublishesItsFilesTogetherAndReplacesPlantedLinks) {
    cagd::test::ScratchDirectory s;
    const std::string target = s.path("result");
    {
        OutputDirectory out(target);
        for (const char* name : {"a.csv", "b.csv"}) {
            OutputFile f(out.staged(name));
            f.stream() << name << "\n";
            f.commit();
        }
        EXPECT_FALSE(fs::exists(target)) << "nothing appears before commit()";
        out.commit();
    }
    EXPECT_EQ(contents(target + "/a.csv"), "a.csv\n");
    EXPECT_EQ(contents(target + "/b.csv"), "b.csv\n");
    // A second run into the existing folder, which now holds a link to a file outside it.
    { std::ofstream(s.path("outside.txt")) << "secret\n"; }
    fs::remove(target + "/a.csv");
    fs::create_symlink("../outside.txt", target + "/a.csv");
    {
        OutputDirectory out(target);
        OutputFile f(out.staged("a.csv"));
        f.stream() << "again\n";
        f.commit();
        out.commit();
    }
    EXPECT_EQ(contents(s.path("outside.txt")), "secret\n") << "the planted link was followed";
    EXPECT_FALSE(fs::is_symlink(target + "/a.csv"));
    EXPECT_EQ(contents(target + "/a.csv"), "again\n");
    EXPECT_EQ(contents(target + "/b.csv"), "b.csv\n") << "a file of the folder that this run does not write is kept";
    EXPECT_EQ(temporaries_in(s.dir), 0);
}

TEST(OutputDirectory, WithoutCommitNothingIsPublishedOrLeft) {
    cagd::test::ScratchDirectory s;
    {
        OutputDirectory out(s.path("result"));
        OutputFile f(out.staged("a.csv"));
        f.stream() << "x\n";
        f.commit();
    }
    EXPECT_FALSE(fs::exists(s.path("result")));
    EXPECT_EQ(temporaries_in(s.dir), 0);
    const std::string file = invalid_input_message([&] {
        std::ofstream(s.path("plain")) << "x";
        OutputDirectory out(s.path("plain"));
    });
    EXPECT_NE(file.find("is not a directory"), std::string::npos) << file;
}

TEST(OutputFile, SignalCleanupRemovesEveryRegisteredTemporary) {
    cagd::test::ScratchDirectory s;
    OutputFile a(s.path("a.csv"));
    OutputDirectory d(s.path("folder"));
    OutputFile staged(d.staged("x.csv"));
    staged.stream() << "x";
    EXPECT_EQ(temporaries_in(s.dir), 2) << "a's temporary file and the folder's staging directory";
    remove_output_temporaries();  // what the signal handler calls
    EXPECT_EQ(temporaries_in(s.dir), 0);
}

// A scratch file (a tool's log) is removed by a signal with the staging directory, and never published.
TEST(OutputDirectory, ScratchFilesAreRemovedBySignalsAndNeverPublished) {
    cagd::test::ScratchDirectory s;
    {
        OutputDirectory d(s.path("folder"));
        std::ofstream(d.scratch("tool.log")) << "a warning";
        OutputFile staged(d.staged("x.csv"));
        staged.stream() << "x";
        staged.commit();
        remove_output_temporaries();
        EXPECT_EQ(temporaries_in(s.dir), 0) << "the log is registered: the staging directory goes with it";
    }
    OutputDirectory d(s.path("folder"));
    std::ofstream(d.scratch("tool.log")) << "a warning";
    OutputFile staged(d.staged("x.csv"));
    staged.stream() << "x";
    staged.commit();
    d.commit();
    EXPECT_TRUE(fs::exists(s.path("folder") + "/x.csv"));
    EXPECT_FALSE(fs::exists(s.path("folder") + "/tool.log"));
}

// Temporaries are registered before they exist: a name drawn twice is never created twice, and
// a failure leaves nothing registered.
TEST(TemporaryFile, CreatedAfterItsRegistrationAndRemovedByItsDestructor) {
    cagd::test::ScratchDirectory s;
    std::string path;
    {
        const TemporaryFile t(s.path("t-"), "test");
        path = t.path();
        EXPECT_EQ(path.size(), s.path("t-").size() + 16);
        EXPECT_TRUE(fs::is_regular_file(path));
    }
    EXPECT_FALSE(fs::exists(path));
    std::string p;
    int slot = -1;
    EXPECT_EQ(create_temporary(s.path("missing/t-"), TemporaryKind::file, p, slot), -1);
    EXPECT_EQ(errno, ENOENT);
    const std::string m = invalid_input_message([&] { TemporaryFile(s.path("missing/t-"), "who"); });
    EXPECT_NE(m.find("no temporary file"), std::string::npos) << m;
}

// core/csv's CsvWriter writes through an OutputFile: the harness's tables are published whole.
TEST(CsvWriter, PublishesAtCloseOrScopeEndAndNothingWhenAnExceptionAbandonsIt) {
    cagd::test::ScratchDirectory s;
    const std::string f = s.path("table.csv");
    std::ofstream(f) << "old\n";
    {
        CsvWriter w(f, {"a", "b"});
        w.row({1.5, 2.0});
        EXPECT_EQ(contents(f), "old\n") << "nothing is published before the writer closes";
    }
    EXPECT_EQ(contents(f), "a,b\n1.5,2\n");
    try {
        CsvWriter w(f, {"x"});
        w.row({3.0});
        throw std::runtime_error("the experiment failed");
    } catch (const std::runtime_error&) {}
    EXPECT_EQ(contents(f), "a,b\n1.5,2\n") << "an abandoned writer keeps the old file";
    EXPECT_EQ(temporaries_in(s.dir), 0) << "and leaves no temporary";
    CsvWriter w(f, {"x"});
    w.row({3.0});
    w.close();
    EXPECT_EQ(contents(f), "x\n3\n");
    EXPECT_THROW(w.row({4.0}), InvalidInput) << "a closed writer refuses rows";
}

TEST(CsvWriter, AFailedWriteThrowsOutputErrorAtClose) {
    CsvWriter w("/dev/full", {"a"});
    w.row({1.0});
    try {
        w.close();
        ADD_FAILURE() << "a write to /dev/full succeeded";
    } catch (const OutputError& e) {
        EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
    }
}
