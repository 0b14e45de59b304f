#include "cagd/intrinsic/knot_difference_list.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "cagd/core/errors.hpp"

namespace cagd::intrinsic {

KnotLayout::KnotLayout(int degree, std::vector<int> segments_per_span, std::vector<int> multiplicity,
                       std::vector<int> length_index)
    : degree_(degree), multiplicity_(std::move(multiplicity)), length_index_(std::move(length_index)) {
    const std::string who = "intrinsic::KnotLayout";
    if (degree_ < 2 || degree_ > 4) fail_input(who, "degree must be 2, 3 or 4, got " + std::to_string(degree_));
    if (segments_per_span.empty()) fail_input(who, "needs at least one span");
    span_first_.push_back(0);
    for (std::size_t i = 0; i < segments_per_span.size(); ++i) {
        if (segments_per_span[i] < 1)
            fail_input(who, "span " + std::to_string(i) + " has " + std::to_string(segments_per_span[i]) +
                                " segments (≥ 1 required)");
        for (int s = 0; s < segments_per_span[i]; ++s) segment_span_.push_back(static_cast<int>(i));
        span_first_.push_back(span_first_.back() + segments_per_span[i]);
    }
    const int k = segments();
    if (static_cast<int>(multiplicity_.size()) != k + 1)
        fail_input(who, "needs " + std::to_string(k + 1) + " breakpoint multiplicities, got " +
                            std::to_string(multiplicity_.size()));
    if (static_cast<int>(length_index_.size()) != k)
        fail_input(who, "needs " + std::to_string(k) + " length indices, got " + std::to_string(length_index_.size()));
    for (int g = 0; g <= k; ++g) {
        const int m = multiplicity_[static_cast<std::size_t>(g)];
        const bool end = g == 0 || g == k;
        if (end && m != degree_)
            fail_input(who, "end breakpoint " + std::to_string(g) + " has multiplicity " + std::to_string(m) +
                                "; the ends must have multiplicity p = " + std::to_string(degree_));
        if (!end && (m < 1 || m > degree_))
            fail_input(who, "interior breakpoint " + std::to_string(g) + " has multiplicity " + std::to_string(m) +
                                "; allowed 1.." + std::to_string(degree_));
    }
    for (int j = 0; j < k; ++j) {
        const int li = length_index_[static_cast<std::size_t>(j)];
        if (li < 0 || li > lengths_)
            fail_input(who, "segment " + std::to_string(j) + " has length index " + std::to_string(li) +
                                "; indices must be numbered in order of first use (next new index " +
                                std::to_string(lengths_) + ")");
        if (li == lengths_) ++lengths_;
    }
    int count = 0;
    for (int g = 0; g <= k; ++g) {
        for (int c = 0; c < multiplicity_[static_cast<std::size_t>(g)]; ++c) knot_breakpoint_.push_back(g);
        count += multiplicity_[static_cast<std::size_t>(g)];
        last_knot_.push_back(count - 1);
    }
    ordinates_ = count - degree_ + 1;
}

KnotLayout KnotLayout::elevated() const {
    std::vector<int> per_span, mult = multiplicity_;
    for (int i = 0; i < spans(); ++i) per_span.push_back(end_segment(i) - first_segment(i));
    for (auto& m : mult) ++m;
    return KnotLayout(degree_ + 1, per_span, mult, length_index_);
}

bool KnotLayout::operator==(const KnotLayout& o) const {
    return degree_ == o.degree_ && span_first_ == o.span_first_ && multiplicity_ == o.multiplicity_ &&
           length_index_ == o.length_index_;
}

namespace {

const char* kKnotListWho = "intrinsic::parse_knot_difference_list";

struct Token {
    enum Kind { open, close, comma, number, name, end } kind;
    std::string text;
    std::size_t position;
};

std::vector<Token> tokenize(const std::string& s) {
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < s.size()) {
        const char c = s[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        if (c == '{') {
            out.push_back({Token::open, "{", i});
            ++i;
            continue;
        }
        if (c == '}') {
            out.push_back({Token::close, "}", i});
            ++i;
            continue;
        }
        if (c == ',') {
            out.push_back({Token::comma, ",", i});
            ++i;
            continue;
        }
        const std::size_t start = i;
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_')) ++i;
            out.push_back({Token::name, s.substr(start, i - start), start});
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+') {
            while (i < s.size() &&
                   (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '.' || s[i] == '-' || s[i] == '+'))
                ++i;
            out.push_back({Token::number, s.substr(start, i - start), start});
            continue;
        }
        fail_input(kKnotListWho, "unexpected character '" + std::string(1, c) + "' at position " + std::to_string(i) +
                                     " of \"" + s + "\" (allowed: { } , numbers, names)");
    }
    out.push_back({Token::end, "", s.size()});
    return out;
}

// One parsed entry: a zero difference, or a segment (length label), or a sub-list of entries.
struct Entry {
    bool zero = false;
    std::string label;            // segment
    std::vector<Entry> children;  // sub-list (non-empty ⇒ a span of several segments)
    bool is_list = false;
    std::size_t position = 0;
};

class Parser {
public:
    Parser(const std::string& text) : text_(text), tokens_(tokenize(text)) {}
    std::vector<Entry> parse_top() {
        expect(Token::open, "the list must start with '{'");
        std::vector<Entry> items = parse_items(0);
        if (tokens_[pos_].kind != Token::end)
            fail_input(kKnotListWho, "unexpected '" + tokens_[pos_].text + "' after the closing '}' at position " +
                                         std::to_string(tokens_[pos_].position));
        return items;
    }

private:
    std::vector<Entry> parse_items(int depth) {
        std::vector<Entry> items;
        if (tokens_[pos_].kind == Token::close)
            fail_input(kKnotListWho,
                       "empty list at position " + std::to_string(tokens_[pos_].position) + " of \"" + text_ + "\"");
        while (true) {
            const Token& t = tokens_[pos_];
            Entry e;
            e.position = t.position;
            if (t.kind == Token::open) {
                if (depth > 0)
                    fail_input(kKnotListWho, "sub-lists cannot nest (position " + std::to_string(t.position) +
                                                 " of \"" + text_ + "\")");
                ++pos_;
                e.is_list = true;
                e.children = parse_items(depth + 1);
            } else if (t.kind == Token::number) {
                char* endp = nullptr;
                const double v = std::strtod(t.text.c_str(), &endp);
                if (endp != t.text.c_str() + t.text.size() || !std::isfinite(v) || v < 0)
                    fail_input(kKnotListWho,
                               "entry \"" + t.text + "\" at position " + std::to_string(t.position) +
                                   " is not a finite number ≥ 0 (\"…\" is not accepted: write every entry)");
                if (v == 0.0)
                    e.zero = true;
                else
                    e.label = t.text;
                ++pos_;
            } else if (t.kind == Token::name) {
                e.label = t.text;
                ++pos_;
            } else {
                fail_input(kKnotListWho, "expected an entry at position " + std::to_string(t.position) + " of \"" +
                                             text_ + "\", found '" +
                                             (t.kind == Token::end ? std::string("end of text") : t.text) + "'");
            }
            items.push_back(std::move(e));
            const Token& sep = tokens_[pos_];
            if (sep.kind == Token::comma) {
                ++pos_;
                continue;
            }
            if (sep.kind == Token::close) {
                ++pos_;
                return items;
            }
            fail_input(kKnotListWho,
                       "expected ',' or '}' at position " + std::to_string(sep.position) + " of \"" + text_ + "\"");
        }
    }
    void expect(Token::Kind k, const std::string& what) {
        if (tokens_[pos_].kind != k) fail_input(kKnotListWho, what + " (\"" + text_ + "\")");
        ++pos_;
    }
    std::string text_;
    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
};

// v with `decimals` decimals, exactly rounded: printf's "%.*f", which std::to_chars(fixed, precision)
// is specified to print.
// The buffer holds any finite double's 309 integer digits and 17 decimals.
std::string fixed(double v, int decimals) {
    char buf[400];
#if defined(__cpp_lib_to_chars)
    const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
    return std::string(buf, r.ptr);
#else
    // The WebAssembly build's standard library (Emscripten's libc++ 14) has no floating-point to_chars.
    const int length = std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return std::string(buf, static_cast<std::size_t>(length));
#endif
}

}  // namespace

KnotDifferenceList parse_knot_difference_list(const std::string& text, int degree) {
    if (degree < 2 || degree > 4) fail_input(kKnotListWho, "degree must be 2, 3 or 4, got " + std::to_string(degree));
    const std::vector<Entry> items = Parser(text).parse_top();
    std::vector<int> per_span, mult, length_index;
    std::vector<std::string> labels;
    std::vector<std::optional<double>> values;
    std::map<std::string, int> by_name;
    auto add_segment = [&](const Entry& e) {
        int idx;
        const bool numeric =
            std::isdigit(static_cast<unsigned char>(e.label[0])) || e.label[0] == '.' || e.label[0] == '+';
        if (!numeric && by_name.count(e.label))
            idx = by_name[e.label];
        else {
            idx = static_cast<int>(labels.size());
            labels.push_back(e.label);
            values.push_back(numeric ? std::optional<double>(std::strtod(e.label.c_str(), nullptr)) : std::nullopt);
            if (!numeric) by_name[e.label] = idx;
        }
        length_index.push_back(idx);
    };
    std::size_t i = 0;
    int zeros = 0;
    while (i < items.size() && items[i].zero) ++zeros, ++i;
    if (zeros != degree - 1)
        fail_input(kKnotListWho, "a degree-" + std::to_string(degree) + " list starts with " +
                                     std::to_string(degree - 1) + " zero(s) (end knot of multiplicity " +
                                     std::to_string(degree) + "), \"" + text + "\" starts with " +
                                     std::to_string(zeros));
    mult.push_back(degree);
    bool after_span = false;
    int pending = 0;  // zeros since the last span
    for (; i < items.size(); ++i) {
        const Entry& e = items[i];
        if (e.zero) {
            ++pending;
            continue;
        }
        if (after_span) {
            if (pending + 1 > degree)
                fail_input(kKnotListWho, std::to_string(pending) + " consecutive zeros before position " +
                                             std::to_string(e.position) + " make a knot of multiplicity " +
                                             std::to_string(pending + 1) + " > p = " + std::to_string(degree));
            mult.push_back(pending + 1);
        }
        pending = 0;
        if (!e.is_list) {
            add_segment(e);
            per_span.push_back(1);
        } else {
            const auto& c = e.children;
            if (c.front().zero || c.back().zero)
                fail_input(kKnotListWho,
                           "the sub-list at position " + std::to_string(e.position) +
                               " must begin and end with a segment length (its zeros mark knots inside the span)");
            int segs = 0, inner = 0;
            for (std::size_t m = 0; m < c.size(); ++m) {
                if (c[m].zero) {
                    ++inner;
                    continue;
                }
                if (segs > 0) {
                    if (inner + 1 > degree)
                        fail_input(kKnotListWho, std::to_string(inner) +
                                                     " consecutive zeros inside the sub-list at position " +
                                                     std::to_string(e.position) +
                                                     " exceed multiplicity p = " + std::to_string(degree));
                    mult.push_back(inner + 1);
                }
                inner = 0;
                add_segment(c[m]);
                ++segs;
            }
            per_span.push_back(segs);
        }
        after_span = true;
    }
    if (per_span.empty()) fail_input(kKnotListWho, "\"" + text + "\" has no segment");
    if (pending != degree - 1)
        fail_input(kKnotListWho, "a degree-" + std::to_string(degree) + " list ends with " +
                                     std::to_string(degree - 1) + " zero(s), \"" + text + "\" ends with " +
                                     std::to_string(pending));
    mult.push_back(degree);
    return {KnotLayout(degree, per_span, mult, length_index), labels, values};
}

namespace {

// "{0, S0, {S1, 0, S2}, S3, 0}": the entries, separated by ", ", written straight into one string.
std::string format_list(const KnotLayout& L, const std::vector<std::string>& seg_text) {
    std::string r = "{";
    std::size_t length = 2;
    for (const std::string& t : seg_text) length += t.size() + 4;
    r.reserve(length + 8 * static_cast<std::size_t>(L.degree()));
    bool first = true;
    const auto entry = [&](const std::string& text) {
        if (!first) r += ", ";
        first = false;
        r += text;
    };
    const auto zeros = [&](int count) {
        for (int z = 0; z < count; ++z) entry("0");
    };
    zeros(L.degree() - 1);
    for (int s = 0; s < L.spans(); ++s) {
        const int a = L.first_segment(s), b = L.end_segment(s);
        if (s > 0) zeros(L.multiplicity(a) - 1);
        if (b - a == 1) {
            entry(seg_text[static_cast<std::size_t>(a)]);
            continue;
        }
        std::string sub = "{";
        for (int j = a; j < b; ++j) {
            if (j > a) {
                for (int z = 0; z < L.multiplicity(j) - 1; ++z) sub += "0, ";
            }
            sub += seg_text[static_cast<std::size_t>(j)];
            if (j + 1 < b) sub += ", ";
        }
        entry(sub + "}");
    }
    zeros(L.degree() - 1);
    return r + "}";
}

}  // namespace

std::string format_knot_difference_list(const KnotLayout& layout, const std::vector<double>& segment_lengths,
                                        int decimals) {
    if (static_cast<int>(segment_lengths.size()) != layout.segments())
        fail_input("intrinsic::format_knot_difference_list", "needs " + std::to_string(layout.segments()) +
                                                                 " segment lengths, got " +
                                                                 std::to_string(segment_lengths.size()));
    if (decimals < 0 || decimals > 17)
        fail_input("intrinsic::format_knot_difference_list",
                   "decimals must be in 0..17, got " + std::to_string(decimals));
    std::vector<std::string> t;
    t.reserve(segment_lengths.size());
    for (double v : segment_lengths) {
        if (!std::isfinite(v) || v <= 0)
            fail_input("intrinsic::format_knot_difference_list",
                       "segment length " + full_precision(v) + " is not finite and > 0");
        t.push_back(fixed(v, decimals));
        if (t.back().find_first_of("123456789") == std::string::npos)  // reads as 0
            fail_input("intrinsic::format_knot_difference_list", "segment length " + full_precision(v) +
                                                                     " prints as 0 with " + std::to_string(decimals) +
                                                                     " decimals (it would read as a repeated knot)");
    }
    return format_list(layout, t);
}

std::string format_knot_difference_list(const KnotLayout& layout) {
    std::vector<std::string> t;
    for (int j = 0; j < layout.segments(); ++j) {
        std::string name = "S";
        name += std::to_string(layout.length_index(j));
        t.push_back(name);
    }
    return format_list(layout, t);
}

}  // namespace cagd::intrinsic
