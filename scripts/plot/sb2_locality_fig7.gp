load 'scripts/plot/style.gp'
f = datadir.'/fig7.csv'
pts = datadir.'/fig7_points.csv'
set title 'Fig. 7 — shape control of the interpolating S-spline by an m-vector'
set xlabel 'x'
set ylabel 'y'
set size ratio -1
do for [t in "png svg"] {
  if (t eq "png") { eval png_terminal } else { eval svg_terminal }
  set output datadir.'/fig7.'.t
  plot f u 2:3 w l ls 2 t 'dotted m-vector', f u 4:5 w l ls 1 t 'solid m-vector', pts u 1:2 w p ls 5 t 'data'
  unset output
}
