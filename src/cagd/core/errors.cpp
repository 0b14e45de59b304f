#include "cagd/core/errors.hpp"

#include <cctype>
#include <cstdio>

namespace cagd {

std::string full_precision(double value) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", value);
    return buf;
}

std::string one_line(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '\n' || c == '\r' || c == '\t') {
            out += ' ';
        } else if (c < 0x20 || c == 0x7f) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        } else {
            out += ch;
        }
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

std::string point_label(long row) { return "point " + std::to_string(row + 1) + " (row " + std::to_string(row) + ")"; }

namespace {
bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
}  // namespace

std::string in_user_terms(const std::string& m) {
    std::string out;
    std::size_t i = 0;
    // A leading qualified function name ("cagd::methods::find_configuration: …") says where in the
    // library the check sits, nothing a user can act on: dropped with its ": ".
    if (m.rfind("cagd::", 0) == 0) {
        std::size_t end = 0;
        while (end < m.size() && (identifier_char(m[end]) || m[end] == ':')) ++end;
        if (m.compare(end > 0 ? end - 1 : 0, 2, ": ") == 0 && m.find("::") < end) i = end + 1;
    }
    while (i < m.size()) {
        if (identifier_char(m[i]) && (i == 0 || !identifier_char(m[i - 1]))) {
            std::size_t end = i, last = i;
            while (end < m.size() && identifier_char(m[end])) ++end;
            const std::size_t first_end = end;
            while (end + 2 < m.size() && m[end] == ':' && m[end + 1] == ':' && identifier_char(m[end + 2])) {
                last = end + 2;
                end = last;
                while (end < m.size() && identifier_char(m[end])) ++end;
            }
            if (end == first_end) {
                out.append(m, i, end - i);
            } else if (m.compare(last, end - last, "methods") == 0 && end < m.size() && m[end] == '(' &&
                       m.find(')', end) != std::string::npos) {
                const std::size_t close = m.find(')', end);  // "cagd::methods(s-spline)": the method's name
                out.append(m, end + 1, close - end - 1);
                end = close + 1;
            } else {
                out.append(m, last, end - last);
            }
            i = end;
            continue;
        }
        out += m[i++];
    }
    return out;
}

void fail_input(const std::string& who, const std::string& what) { throw InvalidInput(who + ": " + one_line(what)); }

}  // namespace cagd
