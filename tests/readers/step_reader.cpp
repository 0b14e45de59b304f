// Reads a STEP file with OpenCASCADE (independently of the writer) and evaluates what it holds:
// - one face: prints "u0,u1,v0,v1" of its surface's parameter range, then, for every line "u,v" on
//   standard input, "x,y,z" at (u, v);
// - else one edge: prints "first,last" of the curve's parameter range, then, for every parameter t
//   on standard input (one per line), "x,y,z" at t.
// A test program for tests/export_readers_test.py; not installed.
#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
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
    int faces = 0;
    TopoDS_Face face;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
        face = TopoDS::Face(e.Current());
        ++faces;
    }
    if (faces > 1) {
        std::cerr << "step_reader: " << argv[1] << ": " << faces << " faces, expected 1\n";
        return 1;
    }
    if (faces == 1) {
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
        if (surface.IsNull()) {
            std::cerr << "step_reader: no surface on the face\n";
            return 1;
        }
        double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
        surface->Bounds(u0, u1, v0, v1);
        std::printf("%.17g,%.17g,%.17g,%.17g\n", u0, u1, v0, v1);
        std::string line;
        while (std::getline(std::cin, line)) {
            const std::size_t comma = line.find(',');
            const gp_Pnt p = surface->Value(std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1)));
            std::printf("%.17g,%.17g,%.17g\n", p.X(), p.Y(), p.Z());
        }
        return 0;
    }
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
