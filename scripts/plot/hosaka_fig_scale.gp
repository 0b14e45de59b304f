# Hosaka's C2 spline with scale factors (eq 19) and with k = 1, on uneven (left) and even (right)
# data; curvature κ(s) below. Columns: data (1 uneven, 2 even), scale (1 chord, 2 unit), u, x, y, s, kappa.
load 'scripts/plot/style.gp'
f = datadir.'/fig_scale.csv'
names = "'uneven chords' 'even chords (y = sin x)'"
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1300,800 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1300,800 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_scale.'.t
  set multiplot layout 2,2 title 'Hosaka eq (20): scale factors k_i = |A_i|/|A_{i+1}| vs the conventional k_i = 1'
  do for [d=1:2] {
    set title word(names, d)
    set xlabel 'x'
    set ylabel 'y'
    set key top right
    set size ratio -1
    plot f u ($1==d && $2==1 ? $4 : 1/0):($1==d && $2==1 ? $5 : 1/0) w l ls 1 t 'k_i of eq (19)', \
         f u ($1==d && $2==2 ? $4 : 1/0):($1==d && $2==2 ? $5 : 1/0) w l ls 2 t 'k_i = 1', \
         f u ($1==d && $2==1 && $3==int($3) ? $4 : 1/0):($1==d && $2==1 && $3==int($3) ? $5 : 1/0) w p ls 5 t 'data'
  }
  do for [d=1:2] {
    set size noratio
    set autoscale y   # (stats keeps to the y range set before)
    stats f u ($1==d ? $7 : 1/0) nooutput
    if (d == 1) { set yrange [-20:20]; set title sprintf('curvature κ(s), shown from -20 to 20 (it spans %.3g to %.3g)', STATS_min, STATS_max) } \
    else { set title sprintf('curvature κ(s), from %.3g to %.3g (its own scale)', STATS_min, STATS_max) }
    set xlabel 'arc length s'
    set ylabel 'κ'
    plot f u ($1==d && $2==1 ? $6 : 1/0):($1==d && $2==1 ? $7 : 1/0) w l ls 1 t 'k_i of eq (19)', \
         f u ($1==d && $2==2 ? $6 : 1/0):($1==d && $2==2 ? $7 : 1/0) w l ls 2 t 'k_i = 1 (clipped at ±20)'
  }
  unset multiplot
  unset output
}
