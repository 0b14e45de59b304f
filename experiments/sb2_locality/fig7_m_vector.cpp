// sb2_locality, section 4, Fig. 7: shape control of the interpolating S-spline by an m-vector.
// The caption's two m-vectors are the paper's input data (quoted below); its points are not
// given, so we use 21 points of a winding curve starting at the upper left (chosen).
#include <cmath>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/locality/locality_spline.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::locality;

int main(int argc, char** argv) {
    repro::ArtifactRun run("sb2_locality", "fig7_m_vector", "4.1", "Shape control by an m-vector (Fig. 7)", argc, argv);
    // Fig. 7 caption, as printed (see erratum E4 for their lengths).
    const MVector dotted = parse_m_vector("1,1,1,1,2,1,0,0,0,1,1,2,1,2,1,1,2,2,1,3");
    const MVector solid_printed = parse_m_vector("1,2,2,1,2,1,2,1,0,1,1,2,2,3,2,2,1,2,3");
    run.check("fig7.vector_lengths", double(solid_printed.size()) - double(dotted.size()));
    MVector solid = solid_printed;
    solid.push_back(solid.back());  // 20 segments: last entry repeated (erratum E4)
    run.note("Caption m-vectors: dotted " + format_m_vector(dotted) + " (" + std::to_string(dotted.size()) +
             " entries); solid " + format_m_vector(solid_printed) + " (" + std::to_string(solid_printed.size()) +
             " entries, used with its last entry repeated).");

    PointList p(21, 2);
    for (int k = 0; k <= 20; ++k) {
        const double t = k / 20.0;
        p.row(k) << 10 * t + 1.2 * std::sin(9 * t), 6 * (1 - t) + 1.5 * std::sin(13 * t) + 0.6 * std::cos(29 * t);
    }
    run.note(
        "Data (chosen): p_k = (10t + 1.2 sin 9t, 6(1−t) + 1.5 sin 13t + 0.6 cos 29t), t = k/20, k = 0..20; open, "
        "natural ends.");
    const double diag = bounding_box_diagonal(p);
    Options a, b;
    a.m = dotted;
    b.m = solid;
    const BSplineCurve ca = interpolate(p, a).curve, cb = interpolate(p, b).curve;
    int disagreements = 0;
    auto spans =
        run.table("fig7_spans.csv", {"span", "m_dotted", "m_solid", "max_distance_over_diag", "predicted_to_move"});
    for (int s = 0; s < 20; ++s) {
        bool predicted = false;
        for (int i = std::max(0, s - 1); i <= std::min(19, s + 1); ++i)
            predicted = predicted || dotted[i].left != solid[i].left || dotted[i].right != solid[i].right;
        const double d = analysis::max_distance_same_parameter(ca, cb, s, s + 1, 65) / diag;
        disagreements += (d > 1e-12) != predicted;
        spans.row({double(s), double(dotted[s].left), double(solid[s].left), d, predicted ? 1.0 : 0.0});
    }
    run.check("fig7.local_change", disagreements);
    auto fig = run.table("fig7.csv", {"u", "dotted_x", "dotted_y", "solid_x", "solid_y"});
    for (int k = 0; k <= 20 * 32; ++k) {
        const double u = k / 32.0;
        const Eigen::VectorXd x = ca.point(u), y = cb.point(u);
        fig.row({u, x(0), x(1), y(0), y(1)});
    }
    auto pts = run.table("fig7_points.csv", {"x", "y"});
    for (int k = 0; k <= 20; ++k) pts.row({p(k, 0), p(k, 1)});
    run.figure(
        "fig7",
        "Fig. 7 — interpolating S-spline with the caption's two m-vectors (dotted, solid); circles: data points");
    return run.finish();
}
