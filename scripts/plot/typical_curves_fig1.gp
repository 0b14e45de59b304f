# typical_curves Fig. 1: degree-24 polygon and curve, curvature and LCG for degrees 99, 49, 24.
load 'scripts/plot/style.gp'
c = datadir.'/fig1_curvature.csv'
p = datadir.'/fig1_polygon.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1500,500 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1500,500 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig1.'.t
  set multiplot layout 1,3 title 'Fig. 1: scale-1 typical Bézier curves approximating the log-aesthetic curve α = −0.5 (L = 1)'
  set title 'degree 24: control polygon (axes not to scale)'
  set xlabel 'x'
  set ylabel 'y'
  set size noratio
  set key bottom left
  plot p index 2 skip 1 using 2:3 with linespoints ls 5 title 'control points (degree 24)'
  set size noratio
  set title 'curvature'
  set xlabel 'arc-length fraction s/L'
  set ylabel 'κ'
  set key bottom left
  plot c index 0 skip 1 using 3:4 with lines ls 1 title 'degree 99', \
       c index 1 skip 1 using 3:4 with lines ls 2 title 'degree 49', \
       c index 2 skip 1 using 3:4 with lines ls 3 title 'degree 24', \
       c index 3 skip 1 using 3:4 with lines ls 5 title 'eq. (15)'
  set title 'logarithmic curvature graph'
  set xlabel 'log ρ'
  set ylabel 'log |ρ ds/dρ|'
  set key top right
  plot c index 0 skip 1 using 5:6 with lines ls 1 title 'degree 99', \
       c index 1 skip 1 using 5:6 with lines ls 2 title 'degree 49', \
       c index 2 skip 1 using 5:6 with lines ls 3 title 'degree 24', \
       c index 3 skip 1 using 5:6 with lines ls 5 title 'eq. (15), slope −0.5'
  unset multiplot
  unset output
}
