# Beyond typical_curves Fig. 5: slopes against the degree and the polygon's distance from the target;
# Alexa's limit (eq 37) against n. space_convergence.csv: degree, lcg_slope, ltg_slope, vertex_error;
# alexa_limit.csv: k, n, error, error_times_n, predicted_error_times_n.
load 'scripts/plot/style.gp'
f = datadir.'/space_convergence.csv'
a = datadir.'/alexa_limit.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1500,500 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1500,500 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig5_convergence.'.t
  set multiplot layout 1,3 title 'Typical Bézier space curves as the degree grows (α = 1.5, β = 1.2), and eq. (37)'
  set logscale x
  set xlabel 'degree n'
  set key bottom right
  set title 'slopes of LCG and LTG'
  set ylabel 'slope'
  plot f skip 1 u 1:2 w lp ls 1 t 'LCG', f skip 1 u 1:3 w lp ls 2 t 'LTG', 1.5 w l ls 5 dt 2 t 'α', 1.2 w l ls 6 dt 2 t 'β'
  set logscale y
  set format y '10^{%L}'
  set title 'control polygon vs target curve'
  set ylabel 'max_j |b_j − C(jΔs)|'
  plot f skip 1 u 1:4 w lp ls 1 t 'vertex error'
  set title 'eq. (37): (A^{1/n}B^{1/n})^n → exp(log A + log B)'
  set xlabel 'n'
  set ylabel 'Frobenius error'
  plot a skip 1 u 2:3 w lp ls 1 t 'limit form, square roots only', a skip 1 u 2:($5/$2) w l ls 5 dt 2 t 'predicted: ‖L_{exp}(Z, [log A, log B]/2)‖/n'
  unset logscale x
  unset logscale y
  set format y '% h'
  unset multiplot
  unset output
}
