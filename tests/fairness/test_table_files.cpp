// The table files of fairness/ (pseudo_energy_table_file.cpp, space_pseudo_energy_table.cpp,
// angle_minimum_table.cpp): a save loads back bit for bit; a flipped digit, a truncation or a value
// outside its domain is refused naming the file, the line and the field; a damaged cache is rebuilt.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cagd/core/checksum.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/fairness/angle_minimum_table.hpp"
#include "cagd/fairness/pseudo_energy_table.hpp"
#include "cagd/fairness/space_pseudo_energy_table.hpp"
#include "cagd/io/file_lock.hpp"

#include "../support/messages.hpp"
#include "../support/scratch_directory.hpp"

using namespace cagd;
using namespace cagd::fairness;
using cagd::test::invalid_input_message;
namespace fs = std::filesystem;

namespace {

std::string file_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// The content with its checksum line recomputed: a file that passes the digest, to test the value checks.
std::string with_checksum(const std::string& content) { return content + checksum_line(content); }

std::string without_checksum(const std::string& text) {
    const std::size_t last = text.rfind('\n', text.size() - 2);
    return text.substr(0, last + 1);
}

}  // namespace

TEST(TableFiles, AChecksumFindsAFlippedDigitAndATruncation) {
    EXPECT_EQ(checksum_line(""), "# checksum fnv1a64 cbf29ce484222325\n") << "FNV-1a's offset basis for no bytes";
    EXPECT_EQ(fnv1a64_hex("a"), "af63dc4c8601ec8c") << "FNV-1a of one byte 'a' (the published test vector)";
    EXPECT_EQ(fnv1a64_hex("13900"), "00f5898e9456454c") << "leading zeros kept: 16 digits always";
    const std::string good = with_checksum("a,b\n1,2\n");
    EXPECT_EQ(checked_content(good, "f"), "a,b\n1,2\n");
    std::string flipped = good;
    flipped[5] = '3';
    const std::string m = invalid_input_message([&] { checked_content(flipped, "f.txt"); });
    EXPECT_NE(m.find("f.txt: its checksum does not match"), std::string::npos) << m;
    const std::string truncated = good.substr(0, 6);
    EXPECT_NE(invalid_input_message([&] { checked_content(truncated, "f.txt"); }).find("no checksum line"),
              std::string::npos);
}

TEST(TableFiles, APlanarTableLoadsBackBitForBitAndRefusesBadValues) {
    cagd::test::ScratchDirectory s;
    const PseudoEnergyTable t = PseudoEnergyTable::build({8, NodePlacement::periodic}, TableMethod::fast);
    t.save(s.path("t.txt"));
    const PseudoEnergyTable u = PseudoEnergyTable::load(s.path("t.txt"));
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
            EXPECT_EQ(u.node(i, j).pseudo_energy, t.node(i, j).pseudo_energy);
            EXPECT_EQ(u.node(i, j).r0, t.node(i, j).r0);
        }
    const std::string content = without_checksum(file_text(s.path("t.txt")));
    // Node (1, 2) sits on line 1·8 + 2 + 3 = 13; its r0 is field 6.
    std::istringstream lines(content);
    std::string line, rebuilt;
    for (int n = 1; std::getline(lines, line); ++n) {
        if (n == 13) {
            std::stringstream row(line);
            std::string field, out;
            for (int k = 1; std::getline(row, field, ','); ++k)
                out += (k > 1 ? "," : "") + (k == 6 ? std::string("-1") : field);
            line = out;
        }
        rebuilt += line + "\n";
    }
    write_text(s.path("bad.txt"), with_checksum(rebuilt));
    const std::string m = invalid_input_message([&] { PseudoEnergyTable::load(s.path("bad.txt")); });
    EXPECT_NE(m.find("bad.txt':13: r0 = -1"), std::string::npos) << m;
    // A header that declares a huge grid is refused before a row is read (and before memory for it).
    write_text(
        s.path("huge.txt"),
        with_checksum("# cagd pseudo_energy table format 7 grid 6000 placement periodic method fast\ncolumns\n"));
    const std::string h = invalid_input_message([&] { PseudoEnergyTable::load(s.path("huge.txt")); });
    EXPECT_NE(h.find("grid 6000; it must be in [2, 720]"), std::string::npos) << h;
    // Too few rows for the grid.
    write_text(s.path("short.txt"), with_checksum(content.substr(0, content.rfind('\n', content.size() - 2) + 1)));
    EXPECT_NE(invalid_input_message([&] {
                  PseudoEnergyTable::load(s.path("short.txt"));
              }).find("63 node rows, the grid 8 has 64"),
              std::string::npos);
}

// What the cache notice was told (the harness prints it as one line).
std::vector<std::string>& cache_notices() {
    static std::vector<std::string> notices;
    return notices;
}

TEST(TableFiles, ADamagedCacheIsRebuilt) {
    cagd::test::ScratchDirectory s;
    cache_notices().clear();
    set_cache_rebuild_notice(
        [](const std::string& path, const std::string& reason) { cache_notices().push_back(path + ": " + reason); });
    const AngleGrid grid{8, NodePlacement::periodic};
    const PseudoEnergyTable t = PseudoEnergyTable::load_or_build(s.path("cache.txt"), grid, TableMethod::fast);
    EXPECT_TRUE(cache_notices().empty()) << "a missing cache is built without a notice";
    std::string text = file_text(s.path("cache.txt"));
    text[text.size() / 2] = text[text.size() / 2] == '1' ? '2' : '1';  // one flipped character
    write_text(s.path("cache.txt"), text);
    const PseudoEnergyTable u = PseudoEnergyTable::load_or_build(s.path("cache.txt"), grid, TableMethod::fast);
    EXPECT_EQ(u.node(3, 5).pseudo_energy, t.node(3, 5).pseudo_energy);
    EXPECT_NO_THROW(PseudoEnergyTable::load(s.path("cache.txt"))) << "the rebuilt cache is whole again";
    ASSERT_EQ(cache_notices().size(), 1u) << "one notice for the rebuilt cache";
    EXPECT_NE(cache_notices()[0].find(s.path("cache.txt") + ": "), std::string::npos) << cache_notices()[0];
    EXPECT_NE(cache_notices()[0].find("checksum"), std::string::npos)
        << "the reason is the failed checksum: " << cache_notices()[0];
    (void)PseudoEnergyTable::load_or_build(s.path("cache.txt"), grid, TableMethod::fast);
    EXPECT_EQ(cache_notices().size(), 1u) << "a sound cache is used silently";
    // The angle table's cache likewise.
    const AngleMinimumTable a = AngleMinimumTable::load_or_build(s.path("angle.txt"), grid);
    std::string atext = file_text(s.path("angle.txt"));
    write_text(s.path("angle.txt"), atext.substr(0, atext.size() / 2));  // truncated
    const AngleMinimumTable b = AngleMinimumTable::load_or_build(s.path("angle.txt"), grid);
    EXPECT_EQ(b.values()[3].pseudo_energy, a.values()[3].pseudo_energy);
    EXPECT_EQ(file_text(s.path("angle.txt")), atext) << "rebuilt to the same bytes";
    EXPECT_EQ(cache_notices().size(), 2u) << "the truncated angle cache was announced too";
    set_cache_rebuild_notice(nullptr);
}

TEST(TableFiles, ASpaceTableRefusesBadValuesNamingTheLine) {
    cagd::test::ScratchDirectory s;
    const SpacePseudoEnergyTable t = SpacePseudoEnergyTable::build({2, 4}, TableMethod::fast, 2);
    t.save(s.path("space.txt"));
    EXPECT_NO_THROW(SpacePseudoEnergyTable::load(s.path("space.txt")));
    std::string content = without_checksum(file_text(s.path("space.txt")));
    const std::size_t row = content.find("\n0,0,1,") + 1;  // line 4: node (0, 0, 1)
    const std::size_t type_end = content.find('\n', row);
    content.replace(type_end - 1, 1, "q");
    write_text(s.path("bad_space.txt"), with_checksum(content));
    const std::string m = invalid_input_message([&] { SpacePseudoEnergyTable::load(s.path("bad_space.txt")); });
    EXPECT_NE(m.find("bad_space.txt':4: type 'q'"), std::string::npos) << m;
}
