# The basis p_i(m, t), q_i(m, t) of hosaka eq (2) for m = 1 (left) and m = 2 (right).
load 'scripts/plot/style.gp'
f = datadir.'/fig_basis.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1200,500 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1200,500 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_basis.'.t
  set multiplot layout 1,2 title 'Hosaka generalised Hermite basis (eq 2)'
  set xlabel 't'
  set key top center
  set title 'm = 1 (eq 12: 1 − f, f, g, h)'
  plot f u 1:2 w l ls 1 t 'p_0', f u 1:3 w l ls 2 t 'q_0', f u 1:4 w l ls 3 t 'p_1', f u 1:5 w l ls 4 t 'q_1'
  set title 'm = 2 (eq 14)'
  plot f u 1:6 w l ls 1 t 'p_0', f u 1:7 w l ls 2 t 'q_0', f u 1:8 w l ls 3 t 'p_1', f u 1:9 w l ls 4 t 'q_1', \
       f u 1:10 w l ls 6 t 'p_2', f u 1:11 w l lc rgb '#8c564b' lw 2 t 'q_2'
  unset multiplot
  unset output
}
