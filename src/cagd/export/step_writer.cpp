#include "cagd/export/step_writer.hpp"

#if CAGD_WITH_OPENCASCADE
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <Geom_BSplineCurve.hxx>
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

}  // namespace

Outcome write_step(std::ostream& out, const BSplineCurve& curve) {
    const Eigen::MatrixXd& control = curve.control_points();
    const int p = curve.degree();
    std::vector<double> values;
    std::vector<int> mults;
    distinct_knots(curve.knots(), values, mults);
    std::lock_guard<std::mutex> lock(step_writer_mutex);
    std::filesystem::path temp;
    try {
        Message::DefaultMessenger()->ChangePrinters().Clear();  // no messages on standard output
        TColgp_Array1OfPnt poles(1, static_cast<int>(control.rows()));
        for (Eigen::Index i = 0; i < control.rows(); ++i) poles.SetValue(static_cast<int>(i) + 1, gp_Pnt(control(i, 0), control(i, 1), control.cols() > 2 ? control(i, 2) : 0.0));
        TColStd_Array1OfReal knots(1, static_cast<int>(values.size()));
        TColStd_Array1OfInteger multiplicities(1, static_cast<int>(values.size()));
        for (std::size_t i = 0; i < values.size(); ++i) {
            knots.SetValue(static_cast<int>(i) + 1, values[i]);
            multiplicities.SetValue(static_cast<int>(i) + 1, mults[i]);
        }
        const Handle(Geom_BSplineCurve) c = new Geom_BSplineCurve(poles, knots, multiplicities, p);
        BRepBuilderAPI_MakeEdge edge(c);
        if (!edge.IsDone()) return {Status::no_solution, "OpenCASCADE could not make an edge of the B-spline"};
        STEPControl_Writer writer;
        Interface_Static::SetCVal("write.step.schema", "AP214IS");
        Interface_Static::SetCVal("write.step.unit", "MM");
        if (writer.Transfer(edge.Edge(), STEPControl_AsIs) != IFSelect_RetDone) return {Status::no_solution, "OpenCASCADE could not translate the curve to STEP"};
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
#else
bool step_available() { return false; }

Outcome write_step(std::ostream&, const BSplineCurve&) {
    fail_input("cagd::exports::write_step", "STEP needs a cagd library built with OpenCASCADE (Debian libocct-data-exchange-dev); this one was built without it");
}
#endif

}  // namespace cagd::exports
