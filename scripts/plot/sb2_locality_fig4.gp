load 'scripts/plot/style.gp'
f = datadir.'/fig4.csv'
set title 'Fig. 4 — interpolating S-spline blending function minus B2-spline blending function'
set xlabel 'u'
set ylabel 'S − B2'
set xrange [-6:6]
do for [t in "png svg"] {
  if (t eq "png") { eval png_terminal } else { eval svg_terminal }
  set output datadir.'/fig4.'.t
  plot for [m=0:3] f u 1:(column(2+m)) w l lw 2 lc m+1 t sprintf('m = %d', m)
  unset output
}
