// Every interpolation method of the library on the 13 points of Fig. 3 (our reading of the figure,
// reference/curvature_profile/data/fig3_points.csv), every span free: the table of `cagd compare`
// and its figures. The paper's own curve on these points (lines and arcs) is experiment
// fig3_lines_arcs; no claims of the paper are checked here, the validations check the measurements.
#include "cagd/core/point_csv.hpp"
#include "repro/comparison_record.hpp"

using namespace cagd;

int main(int argc, char** argv) {
    repro::ArtifactRun run("curvature_profile", "method_comparison", "2-4",
                           "Every method of the library on the points of Fig. 3 (cagd compare)", argc, argv);
    const PointList points = read_points_csv(run.reference_path("data/fig3_points.csv"));
    repro::record_comparison(run, "fig_compare_fig3_", points, false);
    run.note(
        "[measures](curvature_profile/fig_compare_fig3_measures.csv) of every method on the Fig. 3 points; the "
        "curvature-profile row is the all-free clothoid spline with natural "
        "ends, not the paper's lines-and-arcs design.");
    run.figure("fig_compare_fig3_curves", "Fig. 3 points: every method of the library over the points.");
    run.figure(
        "fig_compare_fig3_combs",
        "Fig. 3 points: curvature combs (each scaled so that its 95th percentile of |κ| draws 10 % of the diagonal).");
    return run.finish();
}
