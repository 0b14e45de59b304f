load 'scripts/plot/style.gp'
f = datadir.'/fig_convergence.csv'
set title 'Distance to the conventional cubic B-spline interpolant (eq 10) against m'
set xlabel 'm'
set ylabel 'max distance / bounding-box diagonal'
set logscale y
set format y '10^{%L}'
do for [t in "png svg"] {
  if (t eq "png") { eval png_terminal } else { eval svg_terminal }
  set output datadir.'/fig_convergence.'.t
  plot f u 1:2 w lp ls 1 pt 7 t 'S-spline, open', f u 1:3 w lp ls 2 pt 5 t 'B2-spline, open', \
       f u 1:4 w lp ls 3 pt 6 t 'S-spline, closed', f u 1:5 w lp ls 4 pt 4 t 'B2-spline, closed', \
       f u 1:6 w l ls 5 dt 3 t '0.1 |α|^m'
  unset output
}
