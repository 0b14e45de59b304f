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
    plot f u ($1==d && $2==1 ? $4 : 1/0):($1==d && $2==1 ? $5 : 1/0) w l ls 1 t 'k_i of eq (19)', \
         f u ($1==d && $2==2 ? $4 : 1/0):($1==d && $2==2 ? $5 : 1/0) w l ls 2 t 'k_i = 1', \
         f u ($1==d && $2==1 && $3==int($3) ? $4 : 1/0):($1==d && $2==1 && $3==int($3) ? $5 : 1/0) w p ls 5 t 'data'
  }
  do for [d=1:2] {
    set title 'curvature κ(s)'
    set xlabel 'arc length s'
    set ylabel 'κ'
    if (d == 1) { set yrange [-20:20] } else { set autoscale y }
    plot f u ($1==d && $2==1 ? $6 : 1/0):($1==d && $2==1 ? $7 : 1/0) w l ls 1 t 'k_i of eq (19)', \
         f u ($1==d && $2==2 ? $6 : 1/0):($1==d && $2==2 ? $7 : 1/0) w l ls 2 t 'k_i = 1 (clipped at ±20)'
  }
  unset multiplot
  unset output
}
