# Fig. 5 analogue: surface S^A between two boundary curves (eq 31) and S^B joined at x0 = 2 (eq 43), m = 1.
# Columns: surface (0 = S^A, 1 = S^B), s, t, x, y, z; index 0 = S^A, index 1 = S^B.
load 'scripts/plot/style.gp'
f = datadir.'/fig_joined.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1000,700 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1000,700 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_joined.'.t
  set title 'Hosaka eq (31)-(43): S^A between L_0, L_1 and S^B joined at the section x_0 = 2 (m = 1)'
  set xlabel 'x'
  set ylabel 'y'
  set zlabel 'z'
  set view 60,300
  splot f index 0 u 4:5:6 w l ls 1 t 'S^A (sections x = const)', \
        f index 1 u 4:5:6 w l ls 2 t 'S^B (sections y = const)'
  unset output
}
