#include "cagd/export/step_writer.hpp"

#if CAGD_WITH_OPENCASCADE
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Precision.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Face.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Edge.hxx>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <unistd.h>
#include <vector>
#endif

namespace cagd::exports {

#if CAGD_WITH_OPENCASCADE
bool step_available() { return true; }

namespace {

// The distinct knot values with their multiplicities.
void distinct_knots(const std::vector<double>& knots, std::vector<double>& values, std::vector<int>& mults) {
    for (std::size_t i = 0; i < knots.size(); ++i) {
        if (!values.empty() && knots[i] == values.back())
            ++mults.back();
        else {
            values.push_back(knots[i]);
            mults.push_back(1);
        }
    }
}

std::mutex step_writer_mutex;  // OpenCASCADE's static interface parameters are process-wide

// Writes `shape` as AP214 through a temporary file (OpenCASCADE writes only to paths) copied to
// `out`. The caller holds step_writer_mutex.
Outcome write_shape(std::ostream& out, const TopoDS_Shape& shape, const char* what) {
    std::filesystem::path temp;
    try {
        STEPControl_Writer writer;
        Interface_Static::SetCVal("write.step.schema", "AP214IS");
        Interface_Static::SetCVal("write.step.unit", "MM");
        if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone) return {Status::no_solution, std::string("OpenCASCADE could not translate the ") + what + " to STEP"};
        std::string pattern = (std::filesystem::temp_directory_path() / "cagd-step-XXXXXX").string();
        const int fd = mkstemp(pattern.data());
        if (fd < 0) return {Status::no_solution, "no temporary file for OpenCASCADE's STEP writer in " + std::filesystem::temp_directory_path().string()};
        close(fd);
        temp = pattern;
        const IFSelect_ReturnStatus written = writer.Write(temp.c_str());
        std::ifstream in(temp, std::ios::binary);
        if (written != IFSelect_RetDone || !in) {
            std::filesystem::remove(temp);
            return {Status::no_solution, "OpenCASCADE's STEP writer failed"};
        }
        out << in.rdbuf();
        in.close();
        std::filesystem::remove(temp);
        return {};
    } catch (const Standard_Failure& e) {
        if (!temp.empty()) std::filesystem::remove(temp);
        return {Status::no_solution, std::string("OpenCASCADE: ") + e.GetMessageString()};
    }
}

template <class Array>
void fill_knots(const std::vector<double>& all, Array& knots, TColStd_Array1OfInteger& mults) {
    std::vector<double> values;
    std::vector<int> counts;
    distinct_knots(all, values, counts);
    knots.Resize(1, static_cast<int>(values.size()), false);
    mults.Resize(1, static_cast<int>(values.size()), false);
    for (std::size_t i = 0; i < values.size(); ++i) {
        knots.SetValue(static_cast<int>(i) + 1, values[i]);
        mults.SetValue(static_cast<int>(i) + 1, counts[i]);
    }
}

}  // namespace

Outcome write_step(std::ostream& out, const BSplineCurve& curve) {
    const Eigen::MatrixXd& control = curve.control_points();
    std::lock_guard<std::mutex> lock(step_writer_mutex);
    try {
        Message::DefaultMessenger()->ChangePrinters().Clear();  // no messages on standard output
        TColgp_Array1OfPnt poles(1, static_cast<int>(control.rows()));
        for (Eigen::Index i = 0; i < control.rows(); ++i) poles.SetValue(static_cast<int>(i) + 1, gp_Pnt(control(i, 0), control(i, 1), control.cols() > 2 ? control(i, 2) : 0.0));
        TColStd_Array1OfReal knots(1, 1);
        TColStd_Array1OfInteger multiplicities(1, 1);
        fill_knots(curve.knots(), knots, multiplicities);
        const Handle(Geom_BSplineCurve) c = new Geom_BSplineCurve(poles, knots, multiplicities, curve.degree());
        BRepBuilderAPI_MakeEdge edge(c);
        if (!edge.IsDone()) return {Status::no_solution, "OpenCASCADE could not make an edge of the B-spline"};
        return write_shape(out, edge.Edge(), "curve");
    } catch (const Standard_Failure& e) {
        return {Status::no_solution, std::string("OpenCASCADE: ") + e.GetMessageString()};
    }
}

Outcome write_step(std::ostream& out, const BSplineSurface& surface) {
    const char* who = "cagd::exports::write_step";
    const int max_degree = Geom_BSplineSurface::MaxDegree();
    if (surface.degree_u > max_degree || surface.degree_v > max_degree)
        fail_input(who, "a surface of degree " + std::to_string(surface.degree_u) + " x " + std::to_string(surface.degree_v) + "; OpenCASCADE's B-spline surfaces take degree <= " +
                            std::to_string(max_degree) + " (json takes any degree)");
    std::lock_guard<std::mutex> lock(step_writer_mutex);
    try {
        Message::DefaultMessenger()->ChangePrinters().Clear();
        const Eigen::Index nu = surface.control[0].rows(), nv = surface.control[0].cols();
        TColgp_Array2OfPnt poles(1, static_cast<int>(nu), 1, static_cast<int>(nv));
        for (Eigen::Index i = 0; i < nu; ++i)
            for (Eigen::Index j = 0; j < nv; ++j)
                poles.SetValue(static_cast<int>(i) + 1, static_cast<int>(j) + 1, gp_Pnt(surface.control[0](i, j), surface.control[1](i, j), surface.control[2](i, j)));
        TColStd_Array1OfReal uknots(1, 1), vknots(1, 1);
        TColStd_Array1OfInteger umults(1, 1), vmults(1, 1);
        fill_knots(surface.knots_u, uknots, umults);
        fill_knots(surface.knots_v, vknots, vmults);
        const Handle(Geom_BSplineSurface) s = new Geom_BSplineSurface(poles, uknots, vknots, umults, vmults, surface.degree_u, surface.degree_v);
        BRepBuilderAPI_MakeFace face(s, Precision::Confusion());
        if (!face.IsDone()) return {Status::no_solution, "OpenCASCADE could not make a face of the B-spline surface"};
        return write_shape(out, face.Face(), "surface");
    } catch (const Standard_Failure& e) {
        return {Status::no_solution, std::string("OpenCASCADE: ") + e.GetMessageString()};
    }
}
#else
bool step_available() { return false; }

Outcome write_step(std::ostream&, const BSplineCurve&) {
    fail_input("cagd::exports::write_step", "STEP needs a cagd library built with OpenCASCADE (Debian libocct-data-exchange-dev); this one was built without it");
}

Outcome write_step(std::ostream&, const BSplineSurface&) {
    fail_input("cagd::exports::write_step", "STEP needs a cagd library built with OpenCASCADE (Debian libocct-data-exchange-dev); this one was built without it");
}
#endif

}  // namespace cagd::exports
