#include "cagd/core/checksum.hpp"

#include <cstdio>

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
