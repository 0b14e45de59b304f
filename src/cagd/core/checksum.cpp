#include "cagd/core/checksum.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"

namespace cagd {

namespace {

constexpr std::string_view kPrefix = "# checksum fnv1a64 ";

}  // namespace

std::uint64_t fnv1a64(std::string_view bytes) {
    std::uint64_t h = 14695981039346656037ull;
    for (const char c : bytes) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ull;
    }
    return h;
}

std::string fnv1a64_hex(std::string_view bytes) {
    char hex[24];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a64(bytes)));
    return hex;
}

std::string checksum_line(std::string_view content) { return std::string(kPrefix) + fnv1a64_hex(content) + "\n"; }

std::string read_table_text(const std::string& path, const char* who,
                            const std::function<long(const std::string& header)>& lines_after) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail_input(who, "'" + path + "' is a directory, not a table file");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail_input(who, "cannot open '" + path + "'");
    std::string text, line;
    // One line of at most kMaxTableLine bytes into `line` (without its '\n'); false at the end.
    const auto next_line = [&](long number) {
        line.clear();
        std::streambuf* b = in.rdbuf();
        for (;;) {
            int c = 0;
            try {
                c = b->sbumpc();
            } catch (const std::ios_base::failure& e) {
                fail_input(who, "'" + path + "' cannot be read: " + e.what());
            }
            if (c == std::char_traits<char>::eof()) return !line.empty();
            if (c == '\n') return true;
            if (line.size() == kMaxTableLine)
                fail_input(who, "'" + path + "':" + std::to_string(number) + ": a line longer than " +
                                    std::to_string(kMaxTableLine) + " bytes: not a table file");
            line.push_back(static_cast<char>(c));
        }
    };
    if (!next_line(1)) fail_input(who, "'" + path + "' is empty");
    const long allowed = lines_after(line);
    if (allowed < 0)
        fail_input(who, "'" + path + "' is not a table of this kind (first line: '" + excerpt(line) + "')");
    text = line + "\n";
    for (long n = 0; next_line(n + 2); ++n) {
        if (n == allowed)
            fail_input(who, "'" + path + "': more than the " + std::to_string(allowed + 1) +
                                " lines a table of the grid its header declares holds");
        text += line;
        text += '\n';
    }
    if (in.bad()) fail_input(who, "'" + path + "' cannot be read");
    return text;
}

std::string_view checked_content(std::string_view text, const std::string& source) {
    const std::string who = "cagd::checked_content";
    std::string_view body = text;
    if (!body.empty() && body.back() == '\n') body.remove_suffix(1);
    const std::size_t start = body.rfind('\n');
    const std::string_view last = start == std::string_view::npos ? body : body.substr(start + 1);
    if (last.substr(0, kPrefix.size()) != kPrefix)
        fail_input(who, source + ": no checksum line at its end (a table file ends with '" + std::string(kPrefix) +
                            "…'; the file is truncated, or not written by cagd)");
    const std::string_view content = text.substr(0, start == std::string_view::npos ? 0 : start + 1);
    const std::string expected = checksum_line(content);
    if (std::string(last) + "\n" != expected)
        fail_input(who, source + ": its checksum does not match its content (" +
                            std::string(last.substr(kPrefix.size())) + " recorded, " + fnv1a64_hex(content) +
                            " computed): the file is damaged or was edited");
    return content;
}

}  // namespace cagd
