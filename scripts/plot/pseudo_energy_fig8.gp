load 'scripts/plot/style.gp'
f = datadir.'/fig8.csv'
set size ratio -1
set xlabel 'θ0 (degrees)'
set ylabel 'θ1 (degrees)'
set cblabel 'log_{10} J'
set xrange [-180:180]
set yrange [-180:180]
set palette rgbformulae 33,13,10
unset key
do for [t in "png svg"] {
  if (t eq "png") { eval png_terminal } else { eval svg_terminal }
  set output datadir.'/fig8.'.t
  set title 'Fig. 8 — log_{10} J(θ0, θ1)'
  plot f u 1:2:3 w image
  unset output
}
