# typical_curves Fig. 5: LCG and LTG for degrees 99, 49, 24 and the target (slopes α = 1.5, β = 1.2).
load 'scripts/plot/style.gp'
f = datadir.'/space_curvature_torsion.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1300,500 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1300,500 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig5.'.t
  set multiplot layout 1,2 title 'Fig. 5: logarithmic curvature and torsion graphs (α = 1.5, β = 1.2)'
  set key top left
  set title 'logarithmic curvature graph'
  set xlabel 'log ρ'
  set ylabel 'log |ρ ds/dρ|'
  plot f index 0 skip 1 u 6:7 w l ls 1 t 'degree 99', f index 1 skip 1 u 6:7 w l ls 2 t 'degree 49', f index 2 skip 1 u 6:7 w l ls 3 t 'degree 24', f index 3 skip 1 u 6:7 w l ls 5 dt 2 t 'target, slope 1.5'
  set title 'logarithmic torsion graph'
  set xlabel 'log μ'
  set ylabel 'log |μ ds/dμ|'
  plot f index 0 skip 1 u 8:9 w l ls 1 t 'degree 99', f index 1 skip 1 u 8:9 w l ls 2 t 'degree 49', f index 2 skip 1 u 8:9 w l ls 3 t 'degree 24', f index 3 skip 1 u 8:9 w l ls 5 dt 2 t 'target, slope 1.2'
  unset multiplot
  unset output
}
