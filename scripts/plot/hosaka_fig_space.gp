# Fig. 2 analogue: hosaka C2 space curves through 8 (open, index 0) and 9 (closed, index 1) points,
# in perspective and in the three orthographic projections. Columns: curve, u, x, y, z, is_data.
load 'scripts/plot/style.gp'
f = datadir.'/fig_space.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1200,1000 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1200,1000 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_space.'.t
  set multiplot layout 2,2 title 'Hosaka eq (20) in space: 8 points (open) and 9 points (closed)'
  set key top left
  set title 'perspective'
  set view 60,30
  set xlabel 'x'
  set ylabel 'y'
  set zlabel 'z'
  splot f index 0 u 3:4:5 w l ls 1 t '8 points', f index 0 u ($6==1?$3:1/0):4:5 w p ls 5 notitle, \
        f index 1 u 3:4:5 w l ls 2 t '9 points, closed', f index 1 u ($6==1?$3:1/0):4:5 w p ls 5 notitle
  set size ratio -1
  do for [v=1:3] {
    cx = (v == 3 ? 4 : 3)
    cy = (v == 1 ? 4 : 5)
    set title (v == 1 ? 'plan (x-y)' : (v == 2 ? 'front (x-z)' : 'side (y-z)'))
    set xlabel (v == 3 ? 'y' : 'x')
    set ylabel (v == 1 ? 'y' : 'z')
    plot f index 0 u cx:cy w l ls 1 t '8 points', f index 0 u ($6==1?column(cx):1/0):cy w p ls 5 notitle, \
         f index 1 u cx:cy w l ls 2 t '9 points, closed', f index 1 u ($6==1?column(cx):1/0):cy w p ls 5 notitle
  }
  unset multiplot
  unset output
}
