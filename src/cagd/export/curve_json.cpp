#include "cagd/export/curve_json.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cagd/core/version.hpp"

namespace cagd::exports {

namespace {

using nlohmann::json;

constexpr const char* kCurveFormat = "cagd-curve";
constexpr int kCurveFormatVersion = 1;
constexpr int kMaxDocumentDegree = 31;
constexpr long kMaxDocumentPieces = 10'000'000;

json point_rows(const Eigen::MatrixXd& m) {
    json rows = json::array();
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
        json r = json::array();
        for (Eigen::Index k = 0; k < m.cols(); ++k) r.push_back(m(i, k));
        rows.push_back(std::move(r));
    }
    return rows;
}

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
        const double v = j.get<double>();
        if (!std::isfinite(v)) fail(what + " must be finite");
        return v;
    }
    int integer(const json& j, const std::string& what, int lo, int hi) const {
        if (!j.is_number_integer()) fail(what + " must be a whole number");
        const long long v = j.get<long long>();
        if (v < lo || v > hi)
            fail(what + " = " + std::to_string(v) + " outside [" + std::to_string(lo) + ", " + std::to_string(hi) +
                 "]");
        return static_cast<int>(v);
    }
    std::string text(const json& j, const std::string& what) const {
        if (!j.is_string()) fail(what + " must be a string");
        return j.get<std::string>();
    }
    // rows × dim coordinates; `rows` < 0: any count.
    Eigen::MatrixXd matrix(const json& j, const std::string& what, long rows, int dim) const {
        if (!j.is_array()) fail(what + " must be an array of points");
        if (rows >= 0 && static_cast<long>(j.size()) != rows)
            fail(what + " must have " + std::to_string(rows) + " points, has " + std::to_string(j.size()));
        Eigen::MatrixXd m(static_cast<Eigen::Index>(j.size()), dim);
        for (std::size_t i = 0; i < j.size(); ++i) {
            const json& r = j[i];
            if (!r.is_array() || static_cast<int>(r.size()) != dim)
                fail(what + "[" + std::to_string(i) + "] must have " + std::to_string(dim) + " coordinates");
            for (int k = 0; k < dim; ++k)
                m(static_cast<Eigen::Index>(i), k) =
                    number(r[static_cast<std::size_t>(k)], what + "[" + std::to_string(i) + "]");
        }
        return m;
    }
};

// Parses the document and checks its format and version.
json parse_document(std::istream& in, const DocumentReader& r, const char* format, int version) {
    json j;
    try {
        j = json::parse(in);
    } catch (const json::parse_error& e) {
        r.fail(std::string("not JSON: ") + e.what());
    }
    if (r.text(r.member(j, "format"), "format") != format) r.fail("\"format\" must be \"" + std::string(format) + "\"");
    r.integer(r.member(j, "format_version"), "format_version", version, version);
    return j;
}

constexpr const char* kSurfaceFormat = "cagd-surface";
constexpr int kSurfaceFormatVersion = 1;
constexpr int kMaxSurfaceDegree = 1000;
constexpr long long kMaxSurfaceControlPoints = 10'000'000;

// Strictly increasing finite breaks, at least two.
std::vector<double> read_breaks(const json& j, const DocumentReader& r, const std::string& what) {
    if (!j.is_array() || j.size() < 2 || j.size() > 100'001) r.fail(what + " must be an array of 2 to 100001 numbers");
    std::vector<double> b;
    for (std::size_t i = 0; i < j.size(); ++i) {
        b.push_back(r.number(j[i], what + "[" + std::to_string(i) + "]"));
        if (i > 0 && !(b[i - 1] < b[i])) r.fail(what + " must increase (" + what + "[" + std::to_string(i) + "])");
    }
    return b;
}

}  // namespace

void write_curve_json(std::ostream& out, const BezierForm& f, const CurveProvenance& p) {
    json params = json::object();
    for (const auto& [name, value] : p.parameters) params[name] = value;
    json pieces = json::array();
    for (int i = 0; i < f.pieces.pieces(); ++i) pieces.push_back(point_rows(f.pieces.piece(i)));
    const json doc = {
        {"format", kCurveFormat},
        {"format_version", kCurveFormatVersion},
        {"library_version", library_version()},
        {"registry", p.registry},
        {"method", {{"name", p.method}, {"parameters", params}, {"parameter", p.parameter}, {"closed", p.closed}}},
        {"points", point_rows(p.points)},
        {"dimension", f.pieces.dimension()},
        {"degree", f.pieces.degree},
        {"exact", f.exact},
        {"max_distance", f.max_distance},
        {"tolerance", f.tolerance},
        {"breaks", f.pieces.breaks},
        {"pieces", pieces},
    };
    out << doc.dump(1) << '\n';
}

CurveDocument read_curve_json(std::istream& in, const std::string& source) {
    const DocumentReader r{source};
    const json j = parse_document(in, r, kCurveFormat, kCurveFormatVersion);
    CurveDocument d;
    d.library_version = r.text(r.member(j, "library_version"), "library_version");
    d.provenance.registry = r.text(r.member(j, "registry"), "registry");
    const json& m = r.member(j, "method");
    d.provenance.method = r.text(r.member(m, "name"), "method.name");
    d.provenance.parameter = r.text(r.member(m, "parameter"), "method.parameter");
    const json& closed = r.member(m, "closed");
    if (!closed.is_boolean()) r.fail("method.closed must be true or false");
    d.provenance.closed = closed.get<bool>();
    const json& params = r.member(m, "parameters");
    if (!params.is_object()) r.fail("method.parameters must be an object");
    for (const auto& [name, value] : params.items())
        d.provenance.parameters[name] = r.text(value, "method.parameters." + name);
    const int dim = r.integer(r.member(j, "dimension"), "dimension", 2, 3);
    const int degree = r.integer(r.member(j, "degree"), "degree", 0, kMaxDocumentDegree);
    d.provenance.points = r.matrix(r.member(j, "points"), "points", -1, dim);
    const json& exact = r.member(j, "exact");
    if (!exact.is_boolean()) r.fail("exact must be true or false");
    d.form.exact = exact.get<bool>();
    d.form.max_distance = r.number(r.member(j, "max_distance"), "max_distance");
    d.form.tolerance = r.number(r.member(j, "tolerance"), "tolerance");
    const json& breaks = r.member(j, "breaks");
    const json& pieces = r.member(j, "pieces");
    if (!breaks.is_array() || !pieces.is_array()) r.fail("breaks and pieces must be arrays");
    if (pieces.empty() || static_cast<long>(pieces.size()) > kMaxDocumentPieces)
        r.fail("needs 1 to " + std::to_string(kMaxDocumentPieces) + " pieces, has " + std::to_string(pieces.size()));
    if (breaks.size() != pieces.size() + 1)
        r.fail("needs one more break than pieces, has " + std::to_string(breaks.size()) + " breaks and " +
               std::to_string(pieces.size()) + " pieces");
    d.form.pieces.degree = degree;
    for (std::size_t i = 0; i < breaks.size(); ++i) {
        d.form.pieces.breaks.push_back(r.number(breaks[i], "breaks[" + std::to_string(i) + "]"));
        if (i > 0 && !(d.form.pieces.breaks[i - 1] < d.form.pieces.breaks[i]))
            r.fail("breaks must increase (breaks[" + std::to_string(i) + "])");
    }
    d.form.pieces.control.resize(static_cast<Eigen::Index>(pieces.size()) * (degree + 1), dim);
    for (std::size_t i = 0; i < pieces.size(); ++i)
        d.form.pieces.control.middleRows(static_cast<Eigen::Index>(i) * (degree + 1), degree + 1) =
            r.matrix(pieces[i], "pieces[" + std::to_string(i) + "]", degree + 1, dim);
    return d;
}

CurveDocument read_curve_json_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail_input("cagd::exports::read_curve_json", path + ": cannot be opened for reading");
    return read_curve_json(in, path);
}

void write_surface_json(std::ostream& out, const SurfaceForm& f, const SurfaceProvenance& p) {
    json params = json::object();
    for (const auto& [name, value] : p.parameters) params[name] = value;
    json patches = json::array();
    for (const surface::ControlNet& net : f.pieces.nets) {
        json rows = json::array();
        for (Eigen::Index i = 0; i < net[0].rows(); ++i) {
            json row = json::array();
            for (Eigen::Index k = 0; k < net[0].cols(); ++k) row.push_back({net[0](i, k), net[1](i, k), net[2](i, k)});
            rows.push_back(std::move(row));
        }
        patches.push_back(std::move(rows));
    }
    const json doc = {
        {"format", kSurfaceFormat},
        {"format_version", kSurfaceFormatVersion},
        {"library_version", library_version()},
        {"source", {{"kind", p.kind}, {"parameters", params}}},
        {"exact", f.exact},
        {"conversion_error", f.conversion_error},
        {"degree_u", f.pieces.degree_u},
        {"degree_v", f.pieces.degree_v},
        {"u_breaks", f.pieces.u_breaks},
        {"v_breaks", f.pieces.v_breaks},
        {"patches", patches},
    };
    out << doc.dump(1) << '\n';
}

SurfaceDocument read_surface_json(std::istream& in, const std::string& source) {
    DocumentReader r{source};
    r.who = "cagd::exports::read_surface_json";
    const json j = parse_document(in, r, kSurfaceFormat, kSurfaceFormatVersion);
    SurfaceDocument d;
    d.library_version = r.text(r.member(j, "library_version"), "library_version");
    const json& src = r.member(j, "source");
    d.provenance.kind = r.text(r.member(src, "kind"), "source.kind");
    const json& params = r.member(src, "parameters");
    if (!params.is_object()) r.fail("source.parameters must be an object");
    for (const auto& [name, value] : params.items())
        d.provenance.parameters[name] = r.text(value, "source.parameters." + name);
    const json& exact = r.member(j, "exact");
    if (!exact.is_boolean()) r.fail("exact must be true or false");
    d.form.exact = exact.get<bool>();
    d.form.conversion_error = r.number(r.member(j, "conversion_error"), "conversion_error");
    BezierSurfacePieces& p = d.form.pieces;
    p.degree_u = r.integer(r.member(j, "degree_u"), "degree_u", 1, kMaxSurfaceDegree);
    p.degree_v = r.integer(r.member(j, "degree_v"), "degree_v", 1, kMaxSurfaceDegree);
    p.u_breaks = read_breaks(r.member(j, "u_breaks"), r, "u_breaks");
    p.v_breaks = read_breaks(r.member(j, "v_breaks"), r, "v_breaks");
    const long long cells = static_cast<long long>(p.cells_u()) * p.cells_v();
    if (cells * (p.degree_u + 1) * (p.degree_v + 1) > kMaxSurfaceControlPoints)
        r.fail("more than " + std::to_string(kMaxSurfaceControlPoints) + " control points");
    const json& patches = r.member(j, "patches");
    if (!patches.is_array() || static_cast<long long>(patches.size()) != cells)
        r.fail("patches must be an array of " + std::to_string(cells) + " nets, one per cell");
    for (std::size_t n = 0; n < patches.size(); ++n) {
        const std::string what = "patches[" + std::to_string(n) + "]";
        const json& rows = patches[n];
        if (!rows.is_array() || static_cast<int>(rows.size()) != p.degree_u + 1)
            r.fail(what + " must have degree_u + 1 rows");
        surface::ControlNet net;
        for (auto& c : net) c.resize(p.degree_u + 1, p.degree_v + 1);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const Eigen::MatrixXd row = r.matrix(rows[i], what + "[" + std::to_string(i) + "]", p.degree_v + 1, 3);
            for (int c = 0; c < 3; ++c)
                net[static_cast<std::size_t>(c)].row(static_cast<Eigen::Index>(i)) = row.col(c).transpose();
        }
        p.nets.push_back(std::move(net));
    }
    return d;
}

SurfaceDocument read_surface_json_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail_input("cagd::exports::read_surface_json", path + ": cannot be opened for reading");
    return read_surface_json(in, path);
}

}  // namespace cagd::exports
