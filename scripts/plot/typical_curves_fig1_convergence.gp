# typical_curves Fig. 1, beyond the paper: LCG slope vs degree; power-basis error vs degree.
load 'scripts/plot/style.gp'
f = datadir.'/fig1_convergence.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1200,500 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1200,500 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig1_convergence.'.t
  set multiplot layout 1,2 title 'Scale-1 typical Bézier curve, α = −0.5, L = 1'
  unset logscale
  set format y '%g'
  set title 'LCG slope against degree (stable O(n) Bernstein evaluation)'
  set logscale x
  set xlabel 'degree n'
  set ylabel 'fitted LCG slope'
  set key bottom right
  plot f skip 1 using 1:2 with linespoints ls 1 pt 7 title 'fit over t ∈ [0.05, 0.95]', \
       f skip 1 using 1:3 with linespoints ls 2 pt 5 title 'fit over t ∈ [0, 1]', \
       -0.5 with lines ls 5 title 'α = −0.5'
  set title 'power-basis evaluation: position error'
  set logscale xy
  set format y '10^{%L}'
  set ylabel 'max |power basis − stable|'
  set key top left
  plot f skip 1 using 1:($4 > 0 ? $4 : 1/0) with linespoints ls 2 pt 7 title 'power basis (Horner)'
  unset multiplot
  unset output
}
