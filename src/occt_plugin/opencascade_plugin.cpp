// libcagd_occt.so: the library's calls into OpenCASCADE, loaded by the library on first use
// (src/cagd/core/detail/opencascade_plugin.hpp says why and how). OpenCASCADE's exceptions end here:
// every entry point returns false with the message instead.
#include "cagd/core/detail/opencascade_plugin.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Precision.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <cstdio>
#include <mutex>
#include <type_traits>

namespace {

using cagd::detail::OpenCascadeBSpline;

// OpenCASCADE's default messenger prints to standard output; its printers are removed once, when
// the plugin is first loaded (cagd_opencascade_plugin below). Clearing them on every call, as this
// plugin once did, let two threads free the same printers: a double free in `cagd benchmark`,
// which interpolates on two threads.
void silence_messenger() { Message::DefaultMessenger()->ChangePrinters().Clear(); }

gp_Pnt point(const Eigen::MatrixXd& rows, Eigen::Index i) {
    return gp_Pnt(rows(i, 0), rows(i, 1), rows.cols() > 2 ? rows(i, 2) : 0.0);
}

// Row i of `rows` mapped to (row − centre) / scale: a gp_Pnt2d for planar rows, a gp_Pnt otherwise.
template <class Point>
Point mapped_point(const Eigen::MatrixXd& rows, Eigen::Index i, const Eigen::RowVectorXd& centre, double scale) {
    double xyz[3] = {0.0, 0.0, 0.0};
    for (Eigen::Index c = 0; c < rows.cols(); ++c) xyz[c] = (rows(i, c) - centre(c)) / scale;
    if constexpr (std::is_same_v<Point, gp_Pnt2d>) {
        return gp_Pnt2d(xyz[0], xyz[1]);
    } else {
        return gp_Pnt(xyz[0], xyz[1], xyz[2]);
    }
}

// GeomAPI_Interpolate, or for planar points Geom2dAPI_Interpolate (the same algorithm on 2-D
// points: its arrays hold two coordinates, not three with z = 0), into `out`, mapped back.
template <class Interpolator, class PointArray, class Point>
bool interpolate_with(const Eigen::MatrixXd& points, const Eigen::RowVectorXd& centre, double scale, bool closed,
                      double tolerance, OpenCascadeBSpline& out, std::string& message) {
    Handle(PointArray) array = new PointArray(1, static_cast<int>(points.rows()));
    for (Eigen::Index i = 0; i < points.rows(); ++i)
        array->SetValue(static_cast<int>(i) + 1, mapped_point<Point>(points, i, centre, scale));
    Interpolator interpolate(array, closed, tolerance);
    interpolate.Perform();
    if (!interpolate.IsDone()) {
        message = std::string("OpenCASCADE's ") +
                  (std::is_same_v<Point, gp_Pnt2d> ? "Geom2dAPI_Interpolate" : "GeomAPI_Interpolate") +
                  " did not find a curve";
        return false;
    }
    // The interpolator's own curve, changed in place (no copy: the interpolator ends here).
    const auto& curve = interpolate.Curve();
    if (curve->IsPeriodic()) curve->SetNotPeriodic();
    out.degree = curve->Degree();
    out.knots.clear();
    out.knots.reserve(static_cast<std::size_t>(curve->NbPoles() + curve->Degree() + 1));
    for (int k = 1; k <= curve->NbKnots(); ++k)
        out.knots.insert(out.knots.end(), static_cast<std::size_t>(curve->Multiplicity(k)), curve->Knot(k) * scale);
    out.poles.resize(curve->NbPoles(), points.cols());
    for (int i = 1; i <= curve->NbPoles(); ++i) {
        const Point& q = curve->Pole(i);
        for (Eigen::Index c = 0; c < points.cols(); ++c)
            out.poles(i - 1, c) = q.Coord(static_cast<int>(c) + 1) * scale + centre(c);
    }
    return true;
}

bool interpolate(const Eigen::MatrixXd& points, const Eigen::RowVectorXd& centre, double scale, bool closed,
                 double tolerance, OpenCascadeBSpline& out, std::string& message) {
    try {
        if (points.cols() == 2)
            return interpolate_with<Geom2dAPI_Interpolate, TColgp_HArray1OfPnt2d, gp_Pnt2d>(
                points, centre, scale, closed, tolerance, out, message);
        return interpolate_with<GeomAPI_Interpolate, TColgp_HArray1OfPnt, gp_Pnt>(points, centre, scale, closed,
                                                                                  tolerance, out, message);
    } catch (const Standard_Failure& e) {
        message = std::string("OpenCASCADE's ") +
                  (points.cols() == 2 ? "Geom2dAPI_Interpolate: " : "GeomAPI_Interpolate: ") + e.GetMessageString();
        return false;
    }
}

std::mutex step_writer_mutex;  // OpenCASCADE's static interface parameters are process-wide

// Writes the STEP file of `shape` (AP214, millimetres) to `path`. The caller holds step_writer_mutex.
bool write_shape(const TopoDS_Shape& shape, const char* what, const char* path, std::string& message) {
    STEPControl_Writer writer;
    Interface_Static::SetCVal("write.step.schema", "AP214IS");
    Interface_Static::SetCVal("write.step.unit", "MM");
    if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone) {
        message = std::string("OpenCASCADE could not translate the ") + what + " to STEP";
        return false;
    }
    if (writer.Write(path) != IFSelect_RetDone) {
        message = std::string("OpenCASCADE's STEP writer failed to write ") + path;
        return false;
    }
    return true;
}

// The distinct knot values of `all` with their multiplicities, as OpenCASCADE's arrays.
void fill_knots(const std::vector<double>& all, TColStd_Array1OfReal& knots, TColStd_Array1OfInteger& mults) {
    std::vector<double> values;
    std::vector<int> counts;
    for (const double k : all) {
        if (!values.empty() && k == values.back())
            ++counts.back();
        else
            values.push_back(k), counts.push_back(1);
    }
    knots.Resize(1, static_cast<int>(values.size()), false);
    mults.Resize(1, static_cast<int>(values.size()), false);
    for (std::size_t i = 0; i < values.size(); ++i) {
        knots.SetValue(static_cast<int>(i) + 1, values[i]);
        mults.SetValue(static_cast<int>(i) + 1, counts[i]);
    }
}

bool step_curve(const OpenCascadeBSpline& curve, const char* path, std::string& message) {
    const std::lock_guard<std::mutex> lock(step_writer_mutex);
    try {
        TColgp_Array1OfPnt poles(1, static_cast<int>(curve.poles.rows()));
        for (Eigen::Index i = 0; i < curve.poles.rows(); ++i)
            poles.SetValue(static_cast<int>(i) + 1, point(curve.poles, i));
        TColStd_Array1OfReal knots(1, 1);
        TColStd_Array1OfInteger multiplicities(1, 1);
        fill_knots(curve.knots, knots, multiplicities);
        const Handle(Geom_BSplineCurve) c = new Geom_BSplineCurve(poles, knots, multiplicities, curve.degree);
        BRepBuilderAPI_MakeEdge edge(c);
        if (!edge.IsDone()) {
            message = "OpenCASCADE could not make an edge of the B-spline";
            return false;
        }
        return write_shape(edge.Edge(), "curve", path, message);
    } catch (const Standard_Failure& e) {
        message = std::string("OpenCASCADE: ") + e.GetMessageString();
        return false;
    }
}

bool step_surface(int du, int dv, const std::vector<double>& ku, const std::vector<double>& kv,
                  const Eigen::MatrixXd& x, const Eigen::MatrixXd& y, const Eigen::MatrixXd& z, const char* path,
                  std::string& message) {
    const std::lock_guard<std::mutex> lock(step_writer_mutex);
    try {
        TColgp_Array2OfPnt poles(1, static_cast<int>(x.rows()), 1, static_cast<int>(x.cols()));
        for (Eigen::Index i = 0; i < x.rows(); ++i)
            for (Eigen::Index j = 0; j < x.cols(); ++j)
                poles.SetValue(static_cast<int>(i) + 1, static_cast<int>(j) + 1, gp_Pnt(x(i, j), y(i, j), z(i, j)));
        TColStd_Array1OfReal uknots(1, 1), vknots(1, 1);
        TColStd_Array1OfInteger umults(1, 1), vmults(1, 1);
        fill_knots(ku, uknots, umults);
        fill_knots(kv, vknots, vmults);
        const Handle(Geom_BSplineSurface) s = new Geom_BSplineSurface(poles, uknots, vknots, umults, vmults, du, dv);
        BRepBuilderAPI_MakeFace face(s, Precision::Confusion());
        if (!face.IsDone()) {
            message = "OpenCASCADE could not make a face of the B-spline surface";
            return false;
        }
        return write_shape(face.Face(), "surface", path, message);
    } catch (const Standard_Failure& e) {
        message = std::string("OpenCASCADE: ") + e.GetMessageString();
        return false;
    }
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const cagd::detail::OpenCascadePlugin* cagd_opencascade_plugin() {
    // A function-local static: initialised once, also when two threads ask at the same time.
    static const cagd::detail::OpenCascadePlugin plugin = [] {
        silence_messenger();
        return cagd::detail::OpenCascadePlugin{
            .interface = cagd::detail::kOpenCascadePluginInterface,
            .interpolate = &interpolate,
            .step_curve = &step_curve,
            .step_surface = &step_surface,
            .max_surface_degree = Geom_BSplineSurface::MaxDegree(),
        };
    }();
    return &plugin;
}
