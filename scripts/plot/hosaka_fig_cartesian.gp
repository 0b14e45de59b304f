# Fig. 4 analogue: the Cartesian surface of hosaka eq (30), m = 1, from heights on a 6 x 5 grid.
# Columns: x, y, z, z_exact; scan lines separated by blank lines.
load 'scripts/plot/style.gp'
f = datadir.'/fig_cartesian.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1300,560 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1300,560 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_cartesian.'.t
  set multiplot layout 1,2 title 'Hosaka eq (30): Cartesian surface over a grid (m = 1, node derivatives from splines along the grid lines)'
  set xlabel 'x'
  set ylabel 'y'
  set view 55,30
  set hidden3d
  set title 'surface {/Symbol z}(x, y)'
  splot f u 1:2:3 w l ls 1 notitle
  unset hidden3d
  set view map
  set pm3d map
  set palette defined (-1 '#2166ac', 0 '#f7f7f7', 1 '#b2182b')
  set title 'error {/Symbol z} - 0.5 sin(1.1x) cos(0.9y)'
  splot f u 1:2:($3-$4) w pm3d notitle
  unset multiplot
  unset output
}
