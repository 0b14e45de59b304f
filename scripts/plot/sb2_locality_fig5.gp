load 'scripts/plot/style.gp'
f = datadir.'/fig5.csv'
pts = datadir.'/fig5_points.csv'
set size ratio -1
set key outside right top
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,10' } else { set terminal svg size 1200,900 enhanced font 'DejaVu Sans,10' }
  set output datadir.'/fig5.'.t
  set multiplot layout 2,2 title 'Fig. 5 — interpolating S-spline (solid) and B2-spline (dotted)'
  do for [m=0:3] {
    set title sprintf('m = %d', m)
    set xlabel 'x'
    set ylabel 'y'
    plot f u (column(2+4*m)):(column(3+4*m)) w l ls 1 t 'S-spline', \
         f u (column(4+4*m)):(column(5+4*m)) w l ls 2 t 'B2-spline', \
         pts u 1:2 w p ls 5 t 'data'
  }
  unset multiplot
  unset output
}
