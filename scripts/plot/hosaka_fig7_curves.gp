# hosaka Fig. 7 analogue: five points smoothed by the elastic line (eq 50-52) for three λ.
load 'scripts/plot/style.gp'
f = datadir.'/fig7_curves.csv'
p = datadir.'/fig7_points.csv'
set key autotitle columnheader
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 900,600 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 900,600 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig7_curves.'.t
  set title 'Hosaka Fig. 7: smoothing by an elastic line (eq 50-52); a graph y(x), axes not to scale'
  set xlabel 'x'
  set ylabel 'y'
  set key bottom left
  plot f u 1:2 w l ls 1, f u 1:3 w l ls 2, f u 1:4 w l ls 3, p u 1:2 w p ls 5 t 'data a_i'
  unset output
}
