#pragma once
/// @file
/// The digest that every table file of the library carries on its last line, so that a flipped
/// digit, a truncation or an edit is found on load instead of read as a different table:
///   # checksum fnv1a64 <16 hexadecimal digits>
/// FNV-1a (64 bits, offset basis 14695981039346656037, prime 1099511628211) of every byte before
/// that line. It finds accidental damage; it is not a defence against a deliberate forgery (the
/// readers' value checks bound what a forged file can do).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace cagd {

/// FNV-1a, 64 bits, of `bytes`.
std::uint64_t fnv1a64(std::string_view bytes);

/// fnv1a64(bytes) as 16 lower-case hexadecimal digits: the digest as the checksum line writes it.
std::string fnv1a64_hex(std::string_view bytes);

/// The checksum line of `content` (with its '\n').
std::string checksum_line(std::string_view content);

/// The longest line a table file holds (its rows are a few hundred bytes).
inline constexpr std::size_t kMaxTableLine = 4096;

/// The text of the table file `path`, for checked_content, read line by line and bounded before it
/// is read whole: the first line (the header) of at most kMaxTableLine bytes, then at most
/// lines_after(header) lines (the caller's count for the grid the header declares: column names,
/// rows, the checksum line; −1 when the header is not its kind's; it may throw InvalidInput naming
/// what is wrong), each of at most kMaxTableLine
/// bytes. A stream without line breaks (/dev/zero) or with more lines than its header allows is
/// refused at the first byte or line too much, so memory is what the header declares. InvalidInput
/// naming `who` and the path (a directory, an unreadable file too).
std::string read_table_text(const std::string& path, const char* who,
                            const std::function<long(const std::string& header)>& lines_after);

/// `text` without its last line, which must be the checksum line of the rest: the content a reader
/// may trust. InvalidInput naming `source` when the line is missing or does not match.
std::string_view checked_content(std::string_view text, const std::string& source);

}  // namespace cagd
