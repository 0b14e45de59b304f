# The interpolant benchmark (cagd benchmark, results/benchmark/): per truth family, the largest
# distance to the true curve (÷ its length) against the number of points, log-log, one line per
# configuration (uniform spacing; closed where the family is closed). convergence_<family>.dat
# holds one index block per configuration, its first line naming it.
load 'scripts/plot/style.gp'
set datafile separator whitespace
# The comparison figures' palette (scripts/plot/compare_panels.gp): 28 colours, then dashes.
palette = "#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #8c564b #e377c2 #7f7f7f #bcbd22 #17becf #aec7e8 #ffbb78 #98df8a #ff9896 #c5b0d5 #c49c94 #f7b6d2 #c7c7c7 #dbdb8d #9edae5 #393b79 #637939 #8c6d31 #843c39 #7b4173 #5254a3 #8ca252 #bd9e39"
colour(i) = word(palette, (i - 1) % 28 + 1)
dash(i) = int((i - 1) / 28) + 1
families = "line circle ellipse epitrochoid clothoid log-aesthetic helix trefoil"
set logscale xy
set format y '10^{%L}'
set xlabel 'points n'
set ylabel 'max distance to the truth / length'
set key outside right top box opaque
do for [fam in families] {
  f = datadir.'/convergence_'.fam.'.dat'
  do for [t in "png svg"] {
    if (t eq "png") { set terminal pngcairo size 1100,650 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1100,650 enhanced font 'DejaVu Sans,11' }
    set output datadir.'/convergence_'.fam.'.'.t
    set title 'Benchmark: '.fam.' (uniform in arc length); distances at rounding (1e-17) mean exact'
    plot for [i=0:*] f index i using 1:3 with linespoints lw 1.5 pt 7 ps 0.6 lc rgb colour(i + 1) dt dash(i + 1) title columnheader(2)
    unset output
  }
}
