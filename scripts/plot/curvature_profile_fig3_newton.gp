# curvature_profile Fig. 3: Newton residual per iteration (Moore–Penrose step, C2 start).
load 'scripts/plot/style.gp'
f = datadir.'/fig3_newton.csv'
do for [t in "png svg"] {
  if (t eq "png") { @png_terminal } else { @svg_terminal }
  set output datadir.'/fig3_newton.'.t
  set title 'Fig. 3 design: Newton with the Moore–Penrose step'
  set xlabel 'iteration'
  set ylabel '‖f(u)‖_∞'
  set logscale y
  set format y '10^{%L}'
  set key top right
  plot f skip 1 using 1:2 with linespoints ls 1 pt 7 title 'residual'
  unset output
}
