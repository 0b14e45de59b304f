load 'scripts/plot/style.gp'
f = datadir.'/fig3.csv'
set title 'Fig. 3 — interpolating blending function of p_0 (B2-spline; S-spline dashed)'
set xlabel 'u'
set ylabel 'value'
set xrange [-6:6]
do for [t in "png svg"] {
  if (t eq "png") { eval png_terminal } else { eval svg_terminal }
  set output datadir.'/fig3.'.t
  plot for [m=0:3] f u 1:(column(2+m)) w l lw 2 lc m+1 dt 1 t sprintf('B2, m = %d', m), \
       for [m=0:3] f u 1:(column(6+m)) w l lw 1 lc m+1 dt 2 t sprintf('S, m = %d', m)
  unset output
}
