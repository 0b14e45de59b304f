# The space pseudo-spline through a circular helix (bisector tangents), 6 and 16 points per turn,
# the middle turn: curvature and torsion against arc length, with the helix's constants and the
# torsion's limit, three times the helix's.
# Columns of space_helix_profile.csv: points_per_turn, s, curvature, torsion, helix_curvature, helix_torsion.
load 'scripts/plot/style.gp'
f = datadir.'/space_helix_profile.csv'
set datafile separator ','
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1100,450 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1100,450 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_space_helix.'.t
  set multiplot layout 1,2 title 'Space pseudo-spline through a helix (radius 1, pitch 1.5): the middle turn'
  set xlabel 'arc length s'
  set key top right
  set title 'curvature κ(s)'
  plot f index 0 skip 1 u 2:3 w l ls 1 t '6 points per turn', f index 1 skip 1 u 2:3 w l ls 2 t '16 points per turn', f index 0 skip 1 u 2:5 w l ls 5 dt 2 t 'helix'
  set title 'torsion τ(s)'
  set key center right
  plot f index 0 skip 1 u 2:4 w l ls 1 t '6 points per turn', f index 1 skip 1 u 2:4 w l ls 2 t '16 points per turn', f index 0 skip 1 u 2:6 w l ls 5 dt 2 t 'helix', f index 0 skip 1 u 2:($6*3) w l ls 4 dt 3 t '3 × helix (the limit)'
  unset multiplot
  unset output
}
