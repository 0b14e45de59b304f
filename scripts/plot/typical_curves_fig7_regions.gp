# typical_curves appendix A, Fig. 7: curvature-monotonicity regions of the unit polygon (θ0, θ1).
# fig7_regions.csv: a 301 × 301 matrix of class codes, row i ↔ θ0 = 0.3° i, column j ↔ θ1 = 0.3° j.
load 'scripts/plot/style.gp'
f = datadir.'/fig7_regions.csv'
b = datadir.'/fig7_bound.csv'
step = 90.0 / 300
set palette maxcolors 6
set palette defined (0 '#eeeeee', 1 '#ffd27f', 2 '#9ecae1', 3 '#2171b5', 4 '#d62728', 5 '#74c476')
set cbrange [-0.5:5.5]
set cbtics ('not monotone' 0, 'monotone (exact sign only)' 1, 'all C_i < 0 without (29)' 2, '(29) holds: κ decreasing' 3, '(29) but some C_i ≥ 0' 4, 'κ increasing (mirror)' 5)
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1100,750 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1100,750 enhanced font 'DejaVu Sans,11' }
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
