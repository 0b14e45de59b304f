# typical_curves Fig. 4: curvature and torsion against the arc-length fraction, degrees 99, 49, 24 and
# the target. space_curvature_torsion.csv: degree, t, arc_length_fraction, curvature, torsion, lcg_x, lcg_y, ltg_x, ltg_y.
load 'scripts/plot/style.gp'
f = datadir.'/space_curvature_torsion.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1300,500 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1300,500 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig4.'.t
  set multiplot layout 1,2 title 'Fig. 4: curvature and torsion of the typical Bézier space curves (α = 1.5, β = 1.2)'
  set xlabel 'arc-length fraction s/L'
  set key top right
  set logscale y
  set title 'curvature'
  set ylabel 'κ'
  plot f index 0 skip 1 u 3:4 w l ls 1 t 'degree 99', f index 1 skip 1 u 3:4 w l ls 2 t 'degree 49', f index 2 skip 1 u 3:4 w l ls 3 t 'degree 24', f index 3 skip 1 u 3:4 w l ls 5 dt 2 t 'target'
  set title 'torsion'
  set ylabel 'τ'
  plot f index 0 skip 1 u 3:5 w l ls 1 t 'degree 99', f index 1 skip 1 u 3:5 w l ls 2 t 'degree 49', f index 2 skip 1 u 3:5 w l ls 3 t 'degree 24', f index 3 skip 1 u 3:5 w l ls 5 dt 2 t 'target'
  unset logscale y
  unset multiplot
  unset output
}
