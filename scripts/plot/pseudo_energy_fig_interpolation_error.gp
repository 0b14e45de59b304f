load 'scripts/plot/style.gp'
f = datadir.'/fig_interpolation_error.csv'
set logscale xy
set xlabel 'grid spacing (degrees)'
set ylabel 'error of J / max(1, J)'
set key top left
set format y '10^{%L}'
do for [t in "png svg"] {
  if (t eq "png") { eval png_terminal } else { eval svg_terminal }
  set output datadir.'/fig_interpolation_error.'.t
  set title 'Table interpolation error of J, 2000 random direction pairs'
  plot f u 2:3 w lp ls 1 t 'max, same-type rule (paper)', \
       f u 2:4 w lp ls 3 t 'RMS, same-type rule', \
       f u 2:5 w lp ls 2 t 'max, plain bilinear', \
       f u 2:6 w lp ls 4 t 'RMS, plain bilinear'
  unset output
}
