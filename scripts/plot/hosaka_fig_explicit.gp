# The explicit form y(x), z(x) of hosaka eq (21)-(23) (left) and y'', z'' (right).
load 'scripts/plot/style.gp'
f = datadir.'/fig_explicit.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1200,500 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1200,500 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_explicit.'.t
  set multiplot layout 1,2 title 'Hosaka eq (21)-(23): y(x), z(x) with natural ends'
  set xlabel 'x'
  set title 'y(x), z(x)'
  plot f u 1:2 w l ls 1 t 'y(x)', f u 1:3 w l ls 2 t 'z(x)'
  set title 'second derivatives (continuous, zero at the ends)'
  plot f u 1:4 w l ls 1 t "y''(x)", f u 1:5 w l ls 2 t "z''(x)"
  unset multiplot
  unset output
}
