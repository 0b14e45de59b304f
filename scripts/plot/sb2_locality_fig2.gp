load 'scripts/plot/style.gp'
f = datadir.'/fig2.csv'
set title 'Fig. 2 — blending functions of the B2-spline (g, h) and S-spline (ĝ, ĥ)'
set xlabel 'u'
set ylabel 'value'
do for [t in "png svg"] {
  if (t eq "png") { eval png_terminal } else { eval svg_terminal }
  set output datadir.'/fig2.'.t
  plot f u 1:2 w l ls 1 t 'g (B2)', f u 1:3 w l ls 2 t 'h (B2)', \
       f u 1:4 w l ls 3 t 'ĝ (S)', f u 1:5 w l ls 4 t 'ĥ (S)'
  unset output
}
