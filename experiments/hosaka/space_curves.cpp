// hosaka section 3, Fig. 2: C2 space curves through 8 and 9 points, drawn in orthographic
// projections. The paper gives no coordinates; ours (stated in the report):
//   open, 8 points    P_i = ((1 + 0.1i) cos θ_i, (1 + 0.1i) sin θ_i, 0.25 θ_i),
//                     θ = 0, 0.6, 1.5, 2.1, 3.2, 3.8, 4.9, 5.5 (a conical helix, uneven steps)
//   closed, 9 points  P_i = (1.5 cos θ_i, sin θ_i, 0.5 sin 2θ_i), θ_i = 2πi/9 + 0.2 (i mod 2)
// Both use the scale factors of eq (19) (natural ends for the open curve).
#include <cmath>
#include <numbers>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/spline/hosaka_spline.hpp"
#include "repro/artifact_run.hpp"

using namespace cagd;
using namespace cagd::spline;

int main(int argc, char** argv) {
    repro::ArtifactRun run("hosaka", "space_curves", "3", "Space curves through 8 and 9 points (Fig. 2)", argc, argv);
    const double theta[] = {0, 0.6, 1.5, 2.1, 3.2, 3.8, 4.9, 5.5};
    PointList open(8, 3), closed(9, 3);
    for (int i = 0; i < 8; ++i)
        open.row(i) << (1 + 0.1 * i) * std::cos(theta[i]), (1 + 0.1 * i) * std::sin(theta[i]), 0.25 * theta[i];
    for (int i = 0; i < 9; ++i) {
        const double t = 2 * std::numbers::pi * i / 9 + 0.2 * (i % 2);
        closed.row(i) << 1.5 * std::cos(t), std::sin(t), 0.5 * std::sin(2 * t);
    }
    HosakaSplineOptions closed_options;
    closed_options.closed = true;
    const HosakaSpline a = hosaka_c2_spline(open), b = hosaka_c2_spline(closed, closed_options);

    double jump = 0, size = 0;
    CsvWriter t =
        run.table("space_joins.csv", {"curve", "join", "curvature_left", "curvature_right", "curvature_vector_jump"});
    for (const auto& [name, s] : {std::pair<const char*, const HosakaSpline*>{"open8", &a}, {"closed9", &b}}) {
        const int segs = s->curve.segments(), closed_curve = s == &b;
        for (int j = closed_curve ? 0 : 1; j < segs; ++j) {  // join between segment j−1 (wrapping) and j
            const int prev = (j + segs - 1) % segs;
            const Eigen::VectorXd left = analysis::curvature_vector(s->curve.segment_jet(prev, 1.0, 2));
            const Eigen::VectorXd right = analysis::curvature_vector(s->curve.segment_jet(j, 0.0, 2));
            jump = std::max(jump, (left - right).norm());
            size = std::max({size, left.norm(), right.norm()});
            t.row_text({name, std::to_string(j), format_number(left.norm(), 10), format_number(right.norm(), 10),
                        format_number((left - right).norm(), 3)});
        }
    }
    run.check("fig2.space_curves_curvature_continuous", jump / size);

    CsvWriter fig = run.table("fig_space.csv", {"curve", "u", "x", "y", "z", "is_data"});
    for (const auto& [index, s, p] :
         {std::tuple<int, const HosakaSpline*, const PointList*>{0, &a, &open}, {1, &b, &closed}}) {
        for (int k = 0; k <= 32 * s->curve.segments(); ++k) {
            const Eigen::VectorXd q = s->curve.point(k / 32.0);
            fig.row({double(index), k / 32.0, q(0), q(1), q(2), k % 32 == 0 ? 1.0 : 0.0});
        }
        fig.end_scan();
        fig.end_scan();
    }
    run.note("Joins of both curves, curvature from either side: [space_joins.csv](hosaka/space_joins.csv).");
    run.figure("fig_space",
               "Fig. 2 analogue: the C2 spline of eq (20) through 8 points (open) and 9 points (closed) in space, in "
               "perspective and in the three orthographic projections.");
    return run.finish();
}
