#include "cagd/export/dxf_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

namespace cagd::exports {

namespace {

// Group code and value lines of a DXF file; handles are counted from 0x30 (the tables' own are fixed below).
class DxfLines {
public:
    explicit DxfLines(std::ostream& out) : out_(out) {}
    DxfLines& operator()(int code, const std::string& value) {
        char c[8];
        std::snprintf(c, sizeof c, "%3d", code);
        out_ << c << '\n' << value << '\n';
        return *this;
    }
    DxfLines& operator()(int code, double value) {
        char v[40];
        std::snprintf(v, sizeof v, "%.17g", value);
        return (*this)(code, std::string(v));
    }
    DxfLines& integer(int code, long value) { return (*this)(code, std::to_string(value)); }
    std::string next_handle() {
        char h[20];
        std::snprintf(h, sizeof h, "%X", handle_++);
        return h;
    }
    unsigned handle_seed() const { return handle_; }

private:
    std::ostream& out_;
    unsigned handle_ = 0x30;
};

void dxf_table_head(DxfLines& d, const char* name, const char* handle, int entries) {
    d(0, "TABLE")(2, name)(5, handle)(330, "0")(100, "AcDbSymbolTable").integer(70, entries);
}

void dxf_record_head(DxfLines& d, const char* type, const char* handle, const char* owner, const char* subclass) {
    d(0, type)(5, handle)(330, owner)(100, "AcDbSymbolTableRecord")(100, subclass);
}

void dxf_layer(DxfLines& d, const char* handle, const char* name, int colour) {
    dxf_record_head(d, "LAYER", handle, "2", "AcDbLayerTableRecord");
    d(2, name).integer(70, 0).integer(62, colour)(6, "Continuous").integer(370, -3)(390, "F");
}

void dxf_vertex(DxfLines& d, int code, const Eigen::RowVectorXd& x) {
    d(code, x(0))(code + 10, x(1))(code + 20, x.size() > 2 ? x(2) : 0.0);
}

}  // namespace

void write_dxf(std::ostream& out, const BSplineCurve& curve, DxfSpline kind, const PointList& points) {
    const int dim = curve.dimension();
    if (dim != 2 && dim != 3)
        fail_input("cagd::exports::write_dxf", "needs a curve of 2 or 3 coordinates, got " + std::to_string(dim));
    if (points.rows() > 0 && points.cols() != dim)
        fail_input("cagd::exports::write_dxf", "points must have the curve's " + std::to_string(dim) + " coordinates");
    const int p = curve.degree();
    const Eigen::MatrixXd& control = curve.control_points();
    const std::vector<double>& knots = curve.knots();
    const Eigen::RowVector2d lo = control.leftCols(2).colwise().minCoeff(),
                             hi = control.leftCols(2).colwise().maxCoeff();
    DxfLines d(out);
    // Handles: the entities' first, so that $HANDSEED (written first) is known.
    const std::string spline_handle = d.next_handle();
    std::vector<std::string> point_handles;
    for (Eigen::Index i = 0; i < points.rows(); ++i) point_handles.push_back(d.next_handle());
    char seed[20];
    std::snprintf(seed, sizeof seed, "%X", d.handle_seed());

    d(999, "cagd: an interpolating curve as one B-spline (degree " + std::to_string(p) + ", " +
               std::to_string(control.rows()) + " control points)");
    d(0, "SECTION")(2, "HEADER");
    d(9, "$ACADVER")(1, "AC1015");
    d(9, "$HANDSEED")(5, seed);
    d(9, "$INSUNITS").integer(70, 0);
    d(9, "$EXTMIN")(10, lo(0))(20, lo(1))(30, 0.0);
    d(9, "$EXTMAX")(10, hi(0))(20, hi(1))(30, 0.0);
    d(0, "ENDSEC");
    d(0, "SECTION")(2, "CLASSES")(0, "ENDSEC");

    d(0, "SECTION")(2, "TABLES");
    dxf_table_head(d, "VPORT", "8", 1);
    dxf_record_head(d, "VPORT", "29", "8", "AcDbViewportTableRecord");
    const double cx = 0.5 * (lo(0) + hi(0)), cy = 0.5 * (lo(1) + hi(1)),
                 height = std::max(1e-9, 1.1 * std::max(hi(1) - lo(1), hi(0) - lo(0)));
    d(2, "*Active")
        .integer(70, 0)(10, 0.0)(20, 0.0)(11, 1.0)(21, 1.0)(12, cx)(22, cy)(13, 0.0)(23, 0.0)(14, 10.0)(24, 10.0)(
            15, 10.0)(25, 10.0);
    d(16, 0.0)(26, 0.0)(36, 1.0)(17, 0.0)(27, 0.0)(37, 0.0)(40, height)(41, 1.5)(42, 50.0)(43, 0.0)(44, 0.0)(50, 0.0)(
        51, 0.0);
    d.integer(71, 0)
        .integer(72, 100)
        .integer(73, 1)
        .integer(74, 3)
        .integer(75, 0)
        .integer(76, 0)
        .integer(77, 0)
        .integer(78, 0);
    d(0, "ENDTAB");
    dxf_table_head(d, "LTYPE", "5", 3);
    for (const auto& [handle, name, text] : {std::tuple{"14", "ByBlock", ""}, std::tuple{"15", "ByLayer", ""},
                                             std::tuple{"16", "Continuous", "Solid line"}}) {
        dxf_record_head(d, "LTYPE", handle, "5", "AcDbLinetypeTableRecord");
        d(2, name).integer(70, 0)(3, text).integer(72, 65).integer(73, 0)(40, 0.0);
    }
    d(0, "ENDTAB");
    dxf_table_head(d, "LAYER", "2", 3);
    dxf_layer(d, "10", "0", 7);
    dxf_layer(d, "17", "CURVE", 7);
    dxf_layer(d, "18", "POINTS", 1);
    d(0, "ENDTAB");
    dxf_table_head(d, "STYLE", "3", 1);
    dxf_record_head(d, "STYLE", "11", "3", "AcDbTextStyleTableRecord");
    d(2, "Standard").integer(70, 0)(40, 0.0)(41, 1.0)(50, 0.0).integer(71, 0)(42, 2.5)(3, "txt")(4, "");
    d(0, "ENDTAB");
    dxf_table_head(d, "VIEW", "6", 0);
    d(0, "ENDTAB");
    dxf_table_head(d, "UCS", "7", 0);
    d(0, "ENDTAB");
    dxf_table_head(d, "APPID", "9", 1);
    dxf_record_head(d, "APPID", "12", "9", "AcDbRegAppTableRecord");
    d(2, "ACAD").integer(70, 0);
    d(0, "ENDTAB");
    dxf_table_head(d, "DIMSTYLE", "A", 1);
    d(100, "AcDbDimStyleTable");
    d(0, "DIMSTYLE")(105, "27")(330, "A")(100, "AcDbSymbolTableRecord")(100, "AcDbDimStyleTableRecord")(2, "Standard")
        .integer(70, 0);
    d(0, "ENDTAB");
    dxf_table_head(d, "BLOCK_RECORD", "1", 2);
    dxf_record_head(d, "BLOCK_RECORD", "1F", "1", "AcDbBlockTableRecord");
    d(2, "*Model_Space");
    dxf_record_head(d, "BLOCK_RECORD", "1B", "1", "AcDbBlockTableRecord");
    d(2, "*Paper_Space");
    d(0, "ENDTAB");
    d(0, "ENDSEC");

    d(0, "SECTION")(2, "BLOCKS");
    d(0, "BLOCK")(5, "20")(330, "1F")(100, "AcDbEntity")(8, "0")(100, "AcDbBlockBegin")(2, "*Model_Space")
        .integer(70, 0)(10, 0.0)(20, 0.0)(30, 0.0)(3, "*Model_Space")(1, "");
    d(0, "ENDBLK")(5, "21")(330, "1F")(100, "AcDbEntity")(8, "0")(100, "AcDbBlockEnd");
    d(0, "BLOCK")(5, "1C")(330, "1B")(100, "AcDbEntity")
        .integer(67, 1)(8, "0")(100, "AcDbBlockBegin")(2, "*Paper_Space")
        .integer(70, 0)(10, 0.0)(20, 0.0)(30, 0.0)(3, "*Paper_Space")(1, "");
    d(0, "ENDBLK")(5, "1D")(330, "1B")(100, "AcDbEntity").integer(67, 1)(8, "0")(100, "AcDbBlockEnd");
    d(0, "ENDSEC");

    d(0, "SECTION")(2, "ENTITIES");
    d(0, "SPLINE")(5, spline_handle)(330, "1F")(100, "AcDbEntity")(8, "CURVE")(100, "AcDbSpline");
    const int flags = (kind == DxfSpline::open ? 0 : 1) | (kind == DxfSpline::periodic ? 2 : 0) | (dim == 2 ? 8 : 0);
    if (dim == 2) d(210, 0.0)(220, 0.0)(230, 1.0);
    d.integer(70, flags)
        .integer(71, p)
        .integer(72, static_cast<long>(knots.size()))
        .integer(73, static_cast<long>(control.rows()))
        .integer(74, 0);
    d(42, 1e-10)(43, 1e-10)(44, 1e-10);
    for (const double k : knots) d(40, k);
    for (Eigen::Index i = 0; i < control.rows(); ++i) dxf_vertex(d, 10, control.row(i));
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        d(0, "POINT")(5, point_handles[static_cast<std::size_t>(i)])(330, "1F")(100, "AcDbEntity")(8, "POINTS")(
            100, "AcDbPoint");
        dxf_vertex(d, 10, points.row(i));
    }
    d(0, "ENDSEC");

    d(0, "SECTION")(2, "OBJECTS");
    d(0, "DICTIONARY")(5, "C")(330, "0")(100, "AcDbDictionary").integer(281, 1)(3, "ACAD_GROUP")(350, "D");
    d(0, "DICTIONARY")(5, "D")(330, "C")(100, "AcDbDictionary").integer(281, 1);
    d(0, "ENDSEC");
    d(0, "EOF");
}

void write_dxf(std::ostream& out, const PeriodicBSpline& periodic, const PointList& points) {
    const int p = periodic.degree;
    const Eigen::Index n = periodic.control.rows();
    if (periodic.knots.size() != static_cast<std::size_t>(n + 2 * p + 1) || n < p)
        fail_input("cagd::exports::write_dxf",
                   "a periodic form needs n >= degree control points and n + 2 degree + 1 knots");
    Eigen::MatrixXd wrapped(n + p, periodic.control.cols());
    wrapped << periodic.control, periodic.control.topRows(p);
    std::vector<double> knots = periodic.knots;
    const double shift = knots.front();
    for (double& k : knots) k -= shift;
    write_dxf(out, BSplineCurve(p, std::move(knots), std::move(wrapped)), DxfSpline::periodic, points);
}

}  // namespace cagd::exports
