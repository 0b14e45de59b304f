# Splines continuous to order 2m (m = 1, 2, 3) through the uneven data, and their curvature.
load 'scripts/plot/style.gp'
f = datadir.'/fig_higher_order.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1200,500 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1200,500 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_higher_order.'.t
  set multiplot layout 1,2 title 'Hosaka: derivatives continuous up to order 2m (section 3)'
  set xlabel 'x'
  set ylabel 'y'
  set title 'curves'
  set key top right
  set size ratio -1
  plot for [m=1:3] f u ($1==m ? $3 : 1/0):($1==m ? $4 : 1/0) w l ls m t sprintf('m = %d (C%d)', m, 2*m), \
       f u ($1==1 && $2==int($2) ? $3 : 1/0):($1==1 && $2==int($2) ? $4 : 1/0) w p ls 5 t 'data'
  set size noratio
  set title 'curvature along the parameter'
  set xlabel 'u (segment index + t)'
  set ylabel 'κ'
  set key top right
  plot for [m=1:3] f u ($1==m ? $2 : 1/0):($1==m ? $5 : 1/0) w l ls m t sprintf('m = %d', m)
  unset multiplot
  unset output
}
