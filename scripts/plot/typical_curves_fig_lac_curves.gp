# typical_curves section 3, eq (15): log-aesthetic curves for several α and their LCGs.
load 'scripts/plot/style.gp'
f = datadir.'/fig_lac_curves.csv'
array alphas[6] = ["-2", "-1", "-0.5", "1.5", "2", "3"]
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1200,550 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1200,550 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig_lac_curves.'.t
  set multiplot layout 1,2 title 'Eq. (15): C(s) = ∫_0^s exp(iα v^{(α−1)/α}) dv, s ∈ [0, 2]'
  set title 'curves'
  set xlabel 'x'
  set ylabel 'y'
  set size ratio -1
  set key outside right
  plot for [i=1:6] f index (i-1) skip 1 using 3:4 with lines ls i title 'α = '.alphas[i]
  set title 'logarithmic curvature graphs (slope α)'
  set size noratio
  set xlabel 'log ρ'
  set ylabel 'log |ρ ds/dρ|'
  set key outside right
  plot for [i=1:6] f index (i-1) skip 1 using 5:6 with lines ls i title 'α = '.alphas[i]
  unset multiplot
  unset output
}
