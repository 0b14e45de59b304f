# hosaka section 6: per-projection smoothing vs the space elastic line, relative difference against amplitude.
load 'scripts/plot/style.gp'
f = datadir.'/space_smoothing.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 900,600 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 900,600 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_space_smoothing.'.t
  set title 'Smoothing y(x), z(x) per projection vs with the true bending energy'
  set logscale xy
  set format y '10^{%L}'
  set xlabel 'amplitude A of the data'
  set ylabel 'max |difference| / A'
  set key top left
  plot f u 1:3 w lp ls 1 pt 7 t 'per-projection vs space elastic line'
  unset output
}
