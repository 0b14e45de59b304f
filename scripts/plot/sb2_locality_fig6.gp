load 'scripts/plot/style.gp'
f = datadir.'/fig6.csv'
set title 'Fig. 6 — close-up of a convex span: S-spline (solid) and B2-spline (dashed)'
set xlabel 'x'
set ylabel 'y'
set size ratio -1
do for [t in "png svg"] {
  if (t eq "png") { eval png_terminal } else { eval svg_terminal }
  set output datadir.'/fig6.'.t
  plot f u 2:3 w l ls 1 t 'S, m = 1', f u 4:5 w l ls 2 t 'B2, m = 1', \
       f u 6:7 w l ls 3 t 'S, m = 2', f u 8:9 w l ls 4 t 'B2, m = 2'
  unset output
}
