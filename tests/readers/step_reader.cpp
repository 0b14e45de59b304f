// Reads a STEP file with OpenCASCADE (independently of the writer) and evaluates its one edge's
// curve: prints "first,last" of the curve's parameter range, then, for every parameter t on
// standard input (one per line), "x,y,z" at t. A test program for tests/export_readers_test.py;
// not installed.
#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>
#include <cstdio>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: step_reader FILE.step < parameters\n";
        return 2;
    }
    STEPControl_Reader reader;
    if (reader.ReadFile(argv[1]) != IFSelect_RetDone) {
        std::cerr << "step_reader: " << argv[1] << ": not read\n";
        return 1;
    }
    reader.TransferRoots();
    const TopoDS_Shape shape = reader.OneShape();
    int edges = 0;
    TopoDS_Edge edge;
    for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next()) {
        edge = TopoDS::Edge(e.Current());
        ++edges;
    }
    if (edges != 1) {
        std::cerr << "step_reader: " << argv[1] << ": " << edges << " edges, expected 1\n";
        return 1;
    }
    double first = 0, last = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
    if (curve.IsNull()) {
        std::cerr << "step_reader: no 3-D curve on the edge\n";
        return 1;
    }
    std::printf("%.17g,%.17g\n", first, last);
    std::string line;
    while (std::getline(std::cin, line)) {
        const gp_Pnt p = curve->Value(std::stod(line));
        std::printf("%.17g,%.17g,%.17g\n", p.X(), p.Y(), p.Z());
    }
    return 0;
}
