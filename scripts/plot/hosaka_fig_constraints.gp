# hosaka section 6: the elastic line with constraints by Lagrange multipliers.
load 'scripts/plot/style.gp'
f = datadir.'/constraints.csv'
p = datadir.'/fig7_points.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 900,600 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 900,600 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_constraints.'.t
  set title 'Elastic line (λ = 0.1) with constraints by Lagrange multipliers; a graph y(x), axes not to scale'
  set xlabel 'x'
  set ylabel 'y'
  set key bottom left
  plot f u 1:2 w l ls 1 t 'free', f u 1:3 w l ls 2 t 'y(2) = 0.4 fixed', f u 1:4 w l ls 3 t "y'(0) = y'(4) = 0", p u 1:2 w p ls 5 t 'data a_i'
  unset output
}
