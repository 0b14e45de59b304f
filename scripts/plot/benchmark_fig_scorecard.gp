# The scorecard (cagd scorecard, results/benchmark/): locality against fairness, one point per
# configuration of the registry and per peer. x: the mean number of the 15 spans of a random polygon
# that a move of its middle point displaces (locality: fewer is more local); y: the median bending
# energy L∫κ² ds (fairness: lower is fairer). Filled: the median G2 defect is 0 (curvature continuous);
# open: curvature jumps at the points. scorecard_locality.dat: spans, bending, continuous, name.
load 'scripts/plot/style.gp'
set datafile separator whitespace
set logscale y
set xlabel 'spans displaced by moving the middle point (of 15; mean over the polygons)'
set ylabel 'bending L∫κ^2 ds (median over the polygons)'
set xrange [0:16.5]
set key top left box opaque
f = datadir.'/scorecard_locality.dat'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1200,800 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1200,800 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/scorecard_locality.'.t
  set title 'Scorecard: locality against fairness (16-point random polygons)'
  plot f using 1:($3 == 1 ? $2 : 1/0) with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'curvature continuous (G2 defect 0)', \
       f using 1:($3 == 0 ? $2 : 1/0) with points pt 8 ps 1.2 lc rgb '#d62728' title 'curvature jumps at the points', \
       f using 1:2:4 with labels left offset 0.6,0 font 'DejaVu Sans,7' notitle
  unset output
}
