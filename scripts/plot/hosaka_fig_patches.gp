# Hosaka eq (27) tensor patch (m = 1, index 0 of the data) and Coons' surface with the same edges
# (eq 28 with S0 = 0). Columns: m, u, v, x, y, z_eq27, z_coons; scan lines separated by blank lines.
load 'scripts/plot/style.gp'
f = datadir.'/fig_patches.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1300,560 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1300,560 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_patches.'.t
  set multiplot layout 1,2 title 'Hosaka eq (27) and Coons (eq 28 with S_0 = 0), m = 1, our corner data'
  set view 55,35
  set xlabel 'x'
  set ylabel 'y'
  set zlabel 'z'
  set zrange [-0.3:1.3]
  set hidden3d
  set title 'eq (27): corner twists as given'
  splot f index 0 u 4:5:6 w l ls 1 notitle
  unset hidden3d
  set view map
  set pm3d map
  set autoscale z
  set palette defined (-1 '#2166ac', 0 '#f7f7f7', 1 '#b2182b')
  set title 'S_0 = eq (27) - Coons (z): the twist terms Coons drops'
  splot f index 0 u 4:5:($6-$7) w pm3d notitle
  unset multiplot
  unset output
}
