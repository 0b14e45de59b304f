# typical_curves appendix A, Fig. 7: curvature-monotonicity regions of the unit polygon (θ0, θ1).
# fig7_regions.csv: a 301 × 301 matrix of class codes, row i ↔ θ0 = 0.3° i, column j ↔ θ1 = 0.3° j.
load 'scripts/plot/style.gp'
f = datadir.'/fig7_regions.csv'
b = datadir.'/fig7_bound.csv'
step = 90.0 / 300
set palette maxcolors 6
set palette defined (0 '#eeeeee', 1 '#ffd27f', 2 '#9ecae1', 3 '#2171b5', 4 '#d62728', 5 '#74c476')
set cbrange [-0.5:5.5]
# Each class's colour bar label gives its count of grid cells: a class that no cell has is marked
# empty, so that the legend claims nothing the figure does not show.
classes = "'not monotone' 'monotone (exact sign only)' 'all C_i < 0 without (29)' '(29) holds: κ decreasing' '(29) but some C_i ≥ 0' 'κ increasing (mirror)'"
array count[6]
do for [k=0:5] {
  stats f skip 1 matrix using (column(3) == k ? 1 : 0) nooutput
  count[k + 1] = int(STATS_sum)
}
label(k) = word(classes, k + 1).(count[k + 1] > 0 ? sprintf(' (%d cells)', count[k + 1]) : ' — empty on this grid')
set cbtics (label(0) 0, label(1) 1, label(2) 2, label(3) 3, label(4) 4, label(5) 5)
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1450,750 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1450,750 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig7_regions.'.t
  set title 'Cubic B-spline segment, unit control-polygon edges, turns θ_0, θ_1: where is the curvature monotone?'
  set xlabel 'θ_1 (degrees)'
  set ylabel 'θ_0 (degrees)'
  set xrange [0:90]
  set yrange [0:90]
  set size ratio -1
  set key bottom right
  plot f skip 1 matrix using ($1*step):($2*step):3 with image notitle, \
       b using 2:1 with lines lw 2 lc rgb '#000000' title 'eq (30): θ_1 bound'
  unset output
}
