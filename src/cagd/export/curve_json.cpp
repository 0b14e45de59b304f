#include "cagd/export/curve_json.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <streambuf>
#include <string_view>

#include "cagd/export/bspline_form.hpp"

#include "cagd/core/version.hpp"

namespace cagd::exports {

namespace {

using nlohmann::json;

constexpr const char* kCurveFormat = "cagd-curve";
constexpr int kCurveFormatVersion = 1;
constexpr const char* kSurfaceFormat = "cagd-surface";
constexpr int kSurfaceFormatVersion = 1;
constexpr long kMaxBreaks = 100'001;  // surfaces' u_breaks and v_breaks
constexpr std::size_t kMaxNesting = 64;

// ---- writing: streamed, member by member; the text is never held whole ----

// A number in the shortest form that reads back to the same double (nlohmann's), finite only.
void put_number(std::ostream& out, double v, const char* member) {
    if (!std::isfinite(v))
        fail_input("cagd::exports::write_json",
                   std::string(member) + " holds " + full_precision(v) + ": a document holds finite numbers only");
    out << json(v).dump();
}

void put_row(std::ostream& out, const Eigen::MatrixXd& m, Eigen::Index i, const char* member) {
    out << '[';
    for (Eigen::Index k = 0; k < m.cols(); ++k) {
        if (k > 0) out << ", ";
        put_number(out, m(i, k), member);
    }
    out << ']';
}

// `"name": [` one point per line `]`.
void put_points(std::ostream& out, const char* name, const Eigen::MatrixXd& m) {
    out << "\"" << name << "\": [";
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
        out << (i > 0 ? ",\n  " : "\n  ");
        put_row(out, m, i, name);
    }
    out << (m.rows() > 0 ? "\n ]" : "]");
}

void put_numbers(std::ostream& out, const char* name, const std::vector<double>& v) {
    out << "\"" << name << "\": [";
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (i > 0) out << ", ";
        put_number(out, v[i], name);
    }
    out << ']';
}

json parameter_object(const ParameterText& parameters) {
    json params = json::object();
    for (const auto& [name, value] : parameters) params[name] = value;
    return params;
}

// ---- reading: a bounded stream; a DOM of the small members, the numeric arrays streamed ----

// The text a reader takes from its stream: at most `limit` bytes, then end of input with the excess
// noted, so that a FIFO or /dev/zero is refused at the limit, never read whole. It also ends the
// input at a run of white space, a string or a bare token (number, literal) longer than kMaxRun:
// the parser keeps each token, and the white space before it, whole in memory.
class BoundedBuffer : public std::streambuf {
public:
    static constexpr std::uint64_t kMaxRun = std::uint64_t{1} << 20;
    BoundedBuffer(std::streambuf* source, std::uint64_t limit) : source_(source), left_(limit) {}
    // Why the input ended early ("" when it did not).
    const std::string& cut() const { return cut_; }

protected:
    int_type underflow() override {
        if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
        if (!cut_.empty()) return traits_type::eof();
        if (left_ == 0) {
            if (source_->sgetc() != traits_type::eof())
                cut_ = "longer than the limit of " + std::to_string(read_) + " bytes";
            return traits_type::eof();
        }
        const std::streamsize n = source_->sgetn(
            buffer_.data(), static_cast<std::streamsize>(std::min<std::uint64_t>(buffer_.size(), left_)));
        if (n <= 0) return traits_type::eof();
        left_ -= static_cast<std::uint64_t>(n);
        const std::streamsize kept = scan(n);
        if (kept == 0) return traits_type::eof();
        setg(buffer_.data(), buffer_.data(), buffer_.data() + kept);
        return traits_type::to_int_type(*gptr());
    }

private:
    enum class Run { space, string, token, other };
    std::streambuf* source_;
    std::uint64_t left_, read_ = 0, run_ = 0;
    Run kind_ = Run::other;
    bool escaped_ = false;
    std::string cut_;
    std::array<char, 1 << 16> buffer_{};

    // The bytes of the buffer up to the first that makes a run too long (all n when none does).
    std::streamsize scan(std::streamsize n) {
        for (std::streamsize i = 0; i < n; ++i, ++read_) {
            const char c = buffer_[static_cast<std::size_t>(i)];
            Run kind = Run::other;
            if (kind_ == Run::string) {
                kind = Run::string;
                if (escaped_)
                    escaped_ = false;
                else if (c == '\\')
                    escaped_ = true;
                else if (c == '"')
                    kind = Run::other;
            } else if (c == '"') {
                kind = Run::string;
            } else if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
                kind = Run::space;
            } else if (std::string_view("{}[],:").find(c) == std::string_view::npos) {
                kind = Run::token;
            }
            run_ = kind == kind_ ? run_ + 1 : 1;
            kind_ = kind;
            if (kind != Run::other && run_ > kMaxRun) {
                cut_ = std::string(kind == Run::space    ? "white space"
                                   : kind == Run::string ? "a string"
                                                         : "a token") +
                       " longer than " + std::to_string(kMaxRun) + " bytes at byte " + std::to_string(read_ - kMaxRun);
                return i;
            }
        }
        return n;
    }
};

// A member whose value is an array of numbers nested `depth` deep (breaks 1, points 2, pieces 3,
// patches 4), read into flat storage without a DOM.
struct NumericArray {
    int depth = 1;
    bool present = false;
    std::vector<double> values;                  // in document order
    std::array<long, 4> length{-1, -1, -1, -1};  // per level: the first array's length
    std::array<std::string, 4> ragged{};         // per level: the first array of another length
    std::array<long, 4> ragged_length{};
};

// A reader that names the document and the member in every complaint.
struct DocumentReader {
    const std::string& source;
    const char* who = "cagd::exports::read_curve_json";
    [[noreturn]] void fail(const std::string& what) const { fail_input(who, source + ": " + what); }
    const json& member(const json& j, const char* name) const {
        if (!j.is_object() || !j.contains(name)) fail(std::string("missing member \"") + name + "\"");
        return j.at(name);
    }
    double number(const json& j, const std::string& what) const {
        if (!j.is_number()) fail(what + " must be a number");
        return j.get<double>();  // the parser admits finite numbers only
    }
    int integer(const json& j, const std::string& what, int lo, int hi) const {
        if (!j.is_number_integer()) fail(what + " must be a whole number");
        // An unsigned number beyond long long's range lies outside every [lo, hi] of int.
        const bool huge =
            j.is_number_unsigned() && j.get<std::uint64_t>() > std::numeric_limits<std::uint64_t>::max() / 2;
        const long long v = huge ? 0 : j.get<long long>();
        if (huge || v < lo || v > hi)
            fail(what + " = " + j.dump() + " outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return static_cast<int>(v);
    }
    std::string text(const json& j, const std::string& what) const {
        if (!j.is_string()) fail(what + " must be a string");
        return j.get<std::string>();
    }
    bool boolean(const json& j, const std::string& what) const {
        if (!j.is_boolean()) fail(what + " must be true or false");
        return j.get<bool>();
    }
    // The arrays of `a` at `level` (2 … depth) all have `count` entries (`what`: "coordinates").
    void check_level(const NumericArray& a, const std::string& name, int level, long count, const char* what) const {
        const auto l = static_cast<std::size_t>(level - 1);
        if (a.length[0] <= 0) return;
        std::string at = name;
        for (int i = 1; i < level; ++i) at += "[0]";
        long has = a.length[l];
        if (has == count) {
            if (a.ragged[l].empty()) return;
            at = a.ragged[l];
            has = a.ragged_length[l];
        }
        fail(at + " must have " + std::to_string(count) + " " + what + ", has " + std::to_string(has));
    }
    // The numbers of `a` as rows × dim (row-major in the document), after check_level.
    Eigen::MatrixXd rows(NumericArray& a, int dim) const {
        const auto n = static_cast<Eigen::Index>(a.values.size()) / dim;
        Eigen::MatrixXd m = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            a.values.data(), n, dim);
        std::vector<double>().swap(a.values);
        return m;
    }
    // Strictly increasing breaks, 2 to `most`.
    std::vector<double> breaks(NumericArray& a, const std::string& name, long most) const {
        if (!a.present) fail("missing member \"" + name + "\"");
        if (a.values.size() < 2 || static_cast<long>(a.values.size()) > most)
            fail(name + " must be an array of 2 to " + std::to_string(most) + " numbers");
        for (std::size_t i = 1; i < a.values.size(); ++i)
            if (!(a.values[i - 1] < a.values[i]))
                fail(name + " must increase (" + name + "[" + std::to_string(i) + "])");
        if (!std::isfinite(a.values.back() - a.values.front()))
            fail(name + " spans " + full_precision(a.values.front()) + " to " + full_precision(a.values.back()) +
                 ": the span overflows");
        return std::move(a.values);
    }
};

// Parses a document: the members named in `streamed` into NumericArrays, the others into a DOM of
// at most kMaxDocumentValues values, nested at most kMaxNesting deep; the text bounded by
// kMaxDocumentBytes. Every failure is InvalidInput naming the document and the place.
class DocumentParser {
public:
    DocumentParser(const DocumentReader& r, std::initializer_list<std::pair<const char*, int>> streamed) : r_(r) {
        for (const auto& [name, depth] : streamed) arrays_[name].depth = depth;
    }
    NumericArray& array(const std::string& name) { return arrays_.at(name); }

    json parse(std::istream& in, const char* format, int version) {
        BoundedBuffer bounded(in.rdbuf(), kMaxDocumentBytes);
        std::istream limited(&bounded);
        json j;
        try {
            j = json::parse(limited, [this](int, json::parse_event_t e, json& parsed) { return event(e, parsed); });
        } catch (const json::exception& e) {
            if (!bounded.cut().empty()) r_.fail(bounded.cut());
            std::string what = e.what();
            if (const std::size_t close = what.find("] "); what.rfind("[json.exception", 0) == 0 && close != what.npos)
                what.erase(0, close + 2);
            if (what.size() > 200) what = what.substr(0, 200) + "…";
            r_.fail("not JSON" + (frames_.empty() ? std::string() : " (in " + path() + ")") + ": " + what);
        } catch (const std::ios_base::failure& e) {
            r_.fail(std::string("cannot be read: ") + e.what());
        }
        if (!j.is_object()) r_.fail("must be a JSON object");
        if (r_.text(r_.member(j, "format"), "format") != format)
            r_.fail("\"format\" must be \"" + std::string(format) + "\"");
        r_.integer(r_.member(j, "format_version"), "format_version", version, version);
        return j;
    }

private:
    struct Frame {
        bool is_array = false;
        long index = 0;   // in an array: the current element
        std::string key;  // in an object: the current member
    };
    const DocumentReader& r_;
    std::map<std::string, NumericArray> arrays_;
    std::vector<Frame> frames_;
    NumericArray* bulk_ = nullptr;  // the numeric array being read
    int level_ = 0;                 // its arrays open (1: the member itself)
    long long numbers_ = 0, others_ = 0;

    std::string path() const {
        std::string p;
        for (std::size_t i = 0; i < frames_.size(); ++i) {
            if (frames_[i].is_array) {
                p += '[';
                p += std::to_string(frames_[i].index);
                p += ']';
            } else if (!frames_[i].key.empty()) {
                if (i > 0) p += '.';
                p += frames_[i].key;
            }
        }
        return p.empty() ? "the document" : p;
    }
    void next() {
        if (!frames_.empty() && frames_.back().is_array) ++frames_.back().index;
    }
    void count_other() {
        if (++others_ > kMaxDocumentValues)
            r_.fail("more than " + std::to_string(kMaxDocumentValues) + " values outside the numeric arrays (at " +
                    path() + ")");
    }
    void open(bool is_array) {
        if (frames_.size() >= kMaxNesting)
            r_.fail("nested deeper than " + std::to_string(kMaxNesting) + " at " + path());
        frames_.push_back({is_array, 0, {}});
    }
    [[noreturn]] void misplaced() const {
        r_.fail(path() + " must be " + (level_ < bulk_->depth ? "an array" : "a number"));
    }

    bool event(json::parse_event_t e, json& parsed) {
        using E = json::parse_event_t;
        switch (e) {
            case E::object_start:
                if (bulk_ != nullptr) misplaced();
                count_other();
                open(false);
                return true;
            case E::key: frames_.back().key = parsed.get<std::string>(); return true;
            case E::array_start:
                if (bulk_ != nullptr) {
                    if (level_ == bulk_->depth) misplaced();
                    ++level_;
                } else if (frames_.size() == 1 && !frames_[0].is_array && arrays_.count(frames_[0].key) > 0) {
                    bulk_ = &arrays_[frames_[0].key];
                    if (bulk_->present) r_.fail("member \"" + frames_[0].key + "\" given twice");
                    bulk_->present = true;
                    level_ = 1;
                } else {
                    count_other();
                }
                open(true);
                return true;
            case E::array_end: {
                const long n = frames_.back().index;
                frames_.pop_back();
                bool keep = true;
                if (bulk_ != nullptr) {
                    const auto l = static_cast<std::size_t>(level_ - 1);
                    if (bulk_->length[l] < 0) {
                        bulk_->length[l] = n;
                    } else if (n != bulk_->length[l] && bulk_->ragged[l].empty()) {
                        bulk_->ragged[l] = path();
                        bulk_->ragged_length[l] = n;
                    }
                    keep = level_ == 1;  // the member stays, empty; its inner arrays go
                    if (--level_ == 0) bulk_ = nullptr;
                }
                next();
                return keep;
            }
            case E::object_end:
                frames_.pop_back();
                next();
                return true;
            case E::value:
                if (bulk_ != nullptr) {
                    if (level_ != bulk_->depth || !parsed.is_number()) misplaced();
                    if (++numbers_ > kMaxDocumentNumbers)
                        r_.fail("more than " + std::to_string(kMaxDocumentNumbers) + " numbers (at " + path() + ")");
                    bulk_->values.push_back(parsed.get<double>());
                    next();
                    return false;
                }
                count_other();
                next();
                return true;
        }
        return true;
    }
};

// The text of every member of `parameters` (an object of strings).
ParameterText parameter_text(const DocumentReader& r, const json& parameters, const std::string& what) {
    if (!parameters.is_object()) r.fail(what + " must be an object");
    ParameterText t;
    for (const auto& [name, value] : parameters.items()) t[name] = r.text(value, what + "." + name);
    return t;
}

std::string point_text(const Eigen::RowVectorXd& p) {
    std::string s = "(";
    for (Eigen::Index k = 0; k < p.size(); ++k) s += (k > 0 ? ", " : "") + full_precision(p(k));
    return s + ")";
}

}  // namespace

void write_curve_json(std::ostream& out, const BezierForm& f, const CurveProvenance& p) {
    const json method = {{"name", p.method},
                         {"parameters", parameter_object(p.parameters)},
                         {"parameter", p.parameter},
                         {"closed", p.closed}};
    out << "{\n \"format\": " << json(kCurveFormat).dump() << ",\n \"format_version\": " << kCurveFormatVersion
        << ",\n \"library_version\": " << json(library_version()).dump()
        << ",\n \"registry\": " << json(p.registry).dump() << ",\n \"method\": " << method.dump() << ",\n ";
    put_points(out, "points", p.points);
    out << ",\n \"dimension\": " << f.pieces.dimension() << ",\n \"degree\": " << f.pieces.degree
        << ",\n \"exact\": " << (f.exact ? "true" : "false") << ",\n \"max_distance\": ";
    put_number(out, f.max_distance, "max_distance");
    out << ",\n \"tolerance\": ";
    put_number(out, f.tolerance, "tolerance");
    out << ",\n ";
    put_numbers(out, "breaks", f.pieces.breaks);
    out << ",\n \"pieces\": [";
    const Eigen::Index n = f.pieces.degree + 1;
    for (int i = 0; i < f.pieces.pieces(); ++i) {
        out << (i > 0 ? ",\n  [" : "\n  [");
        for (Eigen::Index k = 0; k < n; ++k) {
            if (k > 0) out << ", ";
            put_row(out, f.pieces.control, i * n + k, "pieces");
        }
        out << ']';
    }
    out << "\n ]\n}\n";
}

CurveDocument read_curve_json(std::istream& in, const std::string& source) {
    const DocumentReader r{source};
    DocumentParser parser(r, {{"points", 2}, {"breaks", 1}, {"pieces", 3}});
    const json j = parser.parse(in, kCurveFormat, kCurveFormatVersion);
    CurveDocument d;
    d.library_version = r.text(r.member(j, "library_version"), "library_version");
    d.provenance.registry = r.text(r.member(j, "registry"), "registry");
    const json& m = r.member(j, "method");
    d.provenance.method = r.text(r.member(m, "name"), "method.name");
    d.provenance.parameter = r.text(r.member(m, "parameter"), "method.parameter");
    d.provenance.closed = r.boolean(r.member(m, "closed"), "method.closed");
    d.provenance.parameters = parameter_text(r, r.member(m, "parameters"), "method.parameters");
    const int dim = r.integer(r.member(j, "dimension"), "dimension", 2, 3);
    const int degree = r.integer(r.member(j, "degree"), "degree", 1, kMaxDocumentDegree);
    NumericArray& points = parser.array("points");
    if (!points.present) r.fail("missing member \"points\"");
    r.check_level(points, "points", 2, dim, "coordinates");
    d.provenance.points = r.rows(points, dim);
    d.form.exact = r.boolean(r.member(j, "exact"), "exact");
    d.form.max_distance = r.number(r.member(j, "max_distance"), "max_distance");
    d.form.tolerance = r.number(r.member(j, "tolerance"), "tolerance");
    NumericArray& pieces = parser.array("pieces");
    if (!pieces.present) r.fail("missing member \"pieces\"");
    const long count = pieces.length[0];
    if (count < 1 || count > kMaxDocumentPieces)
        r.fail("needs 1 to " + std::to_string(kMaxDocumentPieces) + " pieces, has " + std::to_string(count));
    d.form.pieces.breaks = r.breaks(parser.array("breaks"), "breaks", kMaxDocumentPieces + 1);
    if (static_cast<long>(d.form.pieces.breaks.size()) != count + 1)
        r.fail("needs one more break than pieces, has " + std::to_string(d.form.pieces.breaks.size()) + " breaks and " +
               std::to_string(count) + " pieces");
    r.check_level(pieces, "pieces", 2, degree + 1, "points");
    r.check_level(pieces, "pieces", 3, dim, "coordinates");
    d.form.pieces.degree = degree;
    d.form.pieces.control = r.rows(pieces, dim);
    if (const int i = first_unjoined_piece(d.form.pieces); i > 0)
        r.fail("pieces[" + std::to_string(i) + "] starts at " +
               point_text(d.form.pieces.control.row(static_cast<Eigen::Index>(i) * (degree + 1))) + ", pieces[" +
               std::to_string(i - 1) + "] ends at " +
               point_text(d.form.pieces.control.row(static_cast<Eigen::Index>(i) * (degree + 1) - 1)) +
               ": the pieces of a curve must join");
    return d;
}

namespace {
// Opens a document's file: a directory or a regular file beyond the limit is refused at once.
std::ifstream open_document(const std::string& path, const char* who) {
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (std::filesystem::is_directory(status)) fail_input(who, path + ": is a directory, not a document");
    if (std::filesystem::is_regular_file(status)) {
        const std::uintmax_t size = std::filesystem::file_size(path, ec);
        if (!ec && size > kMaxDocumentBytes)
            fail_input(who, path + ": " + std::to_string(size) + " bytes, more than the limit of " +
                                std::to_string(kMaxDocumentBytes));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) fail_input(who, path + ": cannot be opened for reading");
    return in;
}
}  // namespace

CurveDocument read_curve_json_file(const std::string& path) {
    std::ifstream in = open_document(path, "cagd::exports::read_curve_json");
    return read_curve_json(in, path);
}

void write_surface_json(std::ostream& out, const SurfaceForm& f, const SurfaceProvenance& p) {
    const json source = {{"kind", p.kind}, {"parameters", parameter_object(p.parameters)}};
    out << "{\n \"format\": " << json(kSurfaceFormat).dump() << ",\n \"format_version\": " << kSurfaceFormatVersion
        << ",\n \"library_version\": " << json(library_version()).dump() << ",\n \"source\": " << source.dump()
        << ",\n \"exact\": " << (f.exact ? "true" : "false") << ",\n \"conversion_error\": ";
    put_number(out, f.conversion_error, "conversion_error");
    out << ",\n \"degree_u\": " << f.pieces.degree_u << ",\n \"degree_v\": " << f.pieces.degree_v << ",\n ";
    put_numbers(out, "u_breaks", f.pieces.u_breaks);
    out << ",\n ";
    put_numbers(out, "v_breaks", f.pieces.v_breaks);
    out << ",\n \"patches\": [";
    for (std::size_t n = 0; n < f.pieces.nets.size(); ++n) {
        const surface::ControlNet& net = f.pieces.nets[n];
        out << (n > 0 ? ",\n  [" : "\n  [");
        for (Eigen::Index i = 0; i < net[0].rows(); ++i) {
            out << (i > 0 ? ",\n   [" : "\n   [");
            for (Eigen::Index k = 0; k < net[0].cols(); ++k) {
                out << (k > 0 ? ", [" : "[");
                for (std::size_t c = 0; c < 3; ++c) {
                    if (c > 0) out << ", ";
                    put_number(out, net[c](i, k), "patches");
                }
                out << ']';
            }
            out << ']';
        }
        out << "\n  ]";
    }
    out << "\n ]\n}\n";
}

SurfaceDocument read_surface_json(std::istream& in, const std::string& source) {
    DocumentReader r{source};
    r.who = "cagd::exports::read_surface_json";
    DocumentParser parser(r, {{"u_breaks", 1}, {"v_breaks", 1}, {"patches", 4}});
    const json j = parser.parse(in, kSurfaceFormat, kSurfaceFormatVersion);
    SurfaceDocument d;
    d.library_version = r.text(r.member(j, "library_version"), "library_version");
    const json& src = r.member(j, "source");
    d.provenance.kind = r.text(r.member(src, "kind"), "source.kind");
    d.provenance.parameters = parameter_text(r, r.member(src, "parameters"), "source.parameters");
    d.form.exact = r.boolean(r.member(j, "exact"), "exact");
    d.form.conversion_error = r.number(r.member(j, "conversion_error"), "conversion_error");
    BezierSurfacePieces& p = d.form.pieces;
    p.degree_u = r.integer(r.member(j, "degree_u"), "degree_u", 1, kMaxSurfaceDocumentDegree);
    p.degree_v = r.integer(r.member(j, "degree_v"), "degree_v", 1, kMaxSurfaceDocumentDegree);
    p.u_breaks = r.breaks(parser.array("u_breaks"), "u_breaks", kMaxBreaks);
    p.v_breaks = r.breaks(parser.array("v_breaks"), "v_breaks", kMaxBreaks);
    const long long cells = static_cast<long long>(p.cells_u()) * p.cells_v();
    if (cells * (p.degree_u + 1) * (p.degree_v + 1) > kMaxSurfaceControlPoints)
        r.fail("more than " + std::to_string(kMaxSurfaceControlPoints) + " control points");
    NumericArray& patches = parser.array("patches");
    if (!patches.present || patches.length[0] != cells)
        r.fail("patches must be an array of " + std::to_string(cells) + " nets, one per cell");
    r.check_level(patches, "patches", 2, p.degree_u + 1, "rows");
    r.check_level(patches, "patches", 3, p.degree_v + 1, "points");
    r.check_level(patches, "patches", 4, 3, "coordinates");
    const Eigen::MatrixXd points = r.rows(patches, 3);  // net n, row i, column k at (n (du + 1) + i)(dv + 1) + k
    const Eigen::Index rows = p.degree_u + 1, cols = p.degree_v + 1;
    for (Eigen::Index n = 0; n < cells; ++n) {
        surface::ControlNet net;
        for (std::size_t c = 0; c < 3; ++c) {
            net[c].resize(rows, cols);
            for (Eigen::Index i = 0; i < rows; ++i)
                for (Eigen::Index k = 0; k < cols; ++k)
                    net[c](i, k) = points((n * rows + i) * cols + k, static_cast<Eigen::Index>(c));
        }
        p.nets.push_back(std::move(net));
    }
    return d;
}

SurfaceDocument read_surface_json_file(const std::string& path) {
    std::ifstream in = open_document(path, "cagd::exports::read_surface_json");
    return read_surface_json(in, path);
}

}  // namespace cagd::exports
