# hosaka sections 6-7: Franke's function, noisy samples, and four smoothing methods (best λ each).
# Columns: x, y, truth, noisy (spline through the data), net+splines, plate (i) eq 57, plate (ii), approx. 1.
load 'scripts/plot/style.gp'
array titles[6] = ['truth', 'spline through the noisy data', 'elastic net + splines (approx. 2)', 'plate (i), eq 57', 'plate (ii), m = 2', 'approximation 1, eq 57']
f = datadir.'/fig_surface_smoothing.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1500,950 enhanced font 'DejaVu Sans,10' } else { set terminal svg size 1500,950 enhanced font 'DejaVu Sans,10' }
  set output datadir.'/fig_surface_smoothing.'.t
  set multiplot layout 2,3 title 'Smoothing noisy samples of Franke''s function (21 x 21, σ = 0.02)'
  set view 55,35
  set hidden3d
  set xlabel 'x'
  set ylabel 'y'
  unset key
  set zrange [-0.1:1.3]
  do for [k=1:6] {
    set title titles[k]
    splot f u 1:2:(column(k+2)) w l lc rgb '#1f77b4'
  }
  unset multiplot
  unset output
}
