# curvature_profile Fig. 2: closed G2 clothoid spline and its curvature profile.
load 'scripts/plot/style.gp'
c = datadir.'/fig2_curve.csv'
p = datadir.'/fig2_points.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1400,600 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1400,600 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig2.'.t
  set multiplot layout 1,2 title 'Fig. 2: closed G2 clothoid spline (curvature piecewise linear and continuous; data of our choice)'
  set title 'curve and data points'
  set xlabel 'x'
  set ylabel 'y'
  set size ratio -1
  set key bottom right
  plot c skip 1 using 2:3 with lines ls 1 title 'clothoid spline', \
       p skip 1 using 1:2 with points ls 5 title 'data points'
  set size noratio
  set title 'curvature profile'
  set xlabel 'arc length s'
  set ylabel 'κ'
  set key bottom left
  plot c skip 1 using 1:5 with lines ls 3 title 'κ(s)'
  unset multiplot
  unset output
}
