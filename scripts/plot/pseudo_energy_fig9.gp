load 'scripts/plot/style.gp'
f = datadir.'/fig9.csv'
set xlabel 'θ (degrees)'
set ylabel 'J(θ)'
set y2label 'θ1(θ) (degrees)'
set logscale y
set y2tics
set xrange [-180:180]
set key top center
do for [t in "png svg"] {
  if (t eq "png") { eval png_terminal } else { eval svg_terminal }
  set output datadir.'/fig9.'.t
  set title 'Fig. 9 — J(θ) = min_{θ1} J(θ, θ1) and its minimiser θ1(θ)'
  plot f u 1:($2 > 0 ? $2 : 1/0) w l ls 1 t 'J(θ)', f u 1:3 axes x1y2 w l ls 2 t 'θ1(θ)'
  unset output
}
