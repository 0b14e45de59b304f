# A trefoil knot through 24 points by every closed 3-D method (index per method: the experiment's
# space_trefoil_methods.csv). Columns of space_trefoil.csv: method, u, x, y, z, s, curvature, torsion.
load 'scripts/plot/style.gp'
f = datadir.'/space_trefoil.csv'
set datafile separator ','
stats f skip 1 u 1 nooutput
n = int(STATS_max) + 1
names = system("tail -n +2 '".datadir."/space_trefoil_methods.csv' | cut -d, -f2 | tr '\n' ' '")
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,10' } else { set terminal svg size 1200,900 enhanced font 'DejaVu Sans,10' }
  set output datadir.'/fig_space_trefoil.'.t
  set multiplot layout 2,2 title 'Trefoil knot, 24 points, closed: every 3-D method'
  set key off
  set title 'the curves (perspective)'
  set view 55,35
  splot for [i=0:n-1] f index i skip 1 u 3:4:5 w l lw 1.2 lc i+1
  set title 'the curves (plan, x-y)'
  set size ratio -1
  plot for [i=0:n-1] f index i skip 1 u 3:4 w l lw 1.2 lc i+1
  set size noratio
  set xlabel 'arc length s'
  set title 'curvature κ(s)'
  set key outside right top font ',8' noenhanced
  plot for [i=0:n-1] f index i skip 1 u 6:7 w l lw 1 lc i+1 t word(names, i+1)
  set key off
  set title 'torsion τ(s)'
  set yrange [-10:10]
  plot for [i=0:n-1] f index i skip 1 u 6:8 w l lw 1 lc i+1
  unset multiplot
  unset output
}
