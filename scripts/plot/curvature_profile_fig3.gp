# curvature_profile Fig. 3: composite interpolant with lines and arcs, and its curvature profile.
load 'scripts/plot/style.gp'
c = datadir.'/fig3_curve.csv'
p = datadir.'/fig3_points.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1500,550 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1500,550 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig3.'.t
  set multiplot layout 1,2 title 'Fig. 3: curvature piecewise 0th–1st degree in arc length; arcs on spans 4, 7, 9, lines on spans 1, 3, 5, 8, 12'
  set title 'curve and data points'
  set xlabel 'x'
  set ylabel 'y'
  set size ratio -1
  set key top right
  plot c skip 1 using 2:3 with lines ls 1 title 'designed curve', \
       p skip 1 using 1:2 with points ls 5 title 'data points'
  set size noratio
  set offsets 0, 0, 0.1, 0.1
  set title 'curvature profile'
  set xlabel 'arc length s'
  set ylabel 'κ'
  set key bottom left
  plot c skip 1 using 1:5 with lines ls 3 title 'κ(s)'
  unset multiplot
  unset output
}
