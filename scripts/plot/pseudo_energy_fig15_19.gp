# Figs. 15–19 (Table 2, spike data, a = 0..5): the five curves of section 4.2 (top row) and their
# curvature κ(s) (bottom row), one line per a.
# Data columns: method (1..5 as in fig10_14), a, u, x, y, s, kappa.
load 'scripts/plot/style.gp'
f = datadir.'/fig15_19.csv'
titles = "'cubic spline A (uniform t)' 'cubic spline B (chord length)' 'Hermite curve A' 'Hermite curve B' 'pseudo-spline (exact optimisation)'"
set palette defined (0 '#1f77b4', 1 '#2ca02c', 2 '#bcbd22', 3 '#ff7f0e', 4 '#d62728', 5 '#7f7f7f')
set cbrange [0:5]
# The rows come in 30 blocks of equal length, a = 0..5 and within each a the methods 1..5: each
# curve reads the rows of its block (every ::start::end, one row of slack either side, as the header
# line may count as a point), not the whole file; the conditions in `using` keep only its own rows.
stats f u 1 nooutput
block = STATS_records / 30
if (STATS_records != 30 * block) { print 'fig15_19.csv: ', STATS_records, ' rows, not 30 equal blocks'; exit status 1 }
first(m, a) = (a * 5 + m - 1) * block
last(m, a) = first(m, a) + block + 1
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 2000,800 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 2000,800 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig15_19.'.t
  set multiplot layout 2,5 title 'Figs. 15–19 — Table 2 (spike) data, y_4 = a for a = 0..5 (colour = a); curves on one scale, each κ panel on its own scale, given in its title'
  do for [m=1:5] {
    set title word(titles, m)
    set xlabel 'x'
    set ylabel 'y'
    set yrange [-1.5:6.5]
    set size ratio -1
    unset key
    unset colorbox
    plot for [a=0:5] f every ::(first(m, a))::(last(m, a)) u ($1==m && $2==a ? $4 : 1/0):($1==m && $2==a ? $5 : 1/0):(a) w l lw 2 lc palette, \
         for [a=0:5] f every ::(first(m, a))::(last(m, a)) u ($1==m && $2==a && $3==int($3) ? $4 : 1/0):($1==m && $2==a && $3==int($3) ? $5 : 1/0) w p ls 5
  }
  set size noratio
  do for [m=1:5] {
    set autoscale y   # (stats of one column keeps to the y range set before)
    stats f u ($1==m ? $7 : 1/0) nooutput
    set title sprintf('curvature κ(s), from %.3g to %.3g', STATS_min, STATS_max)
    set xlabel 'arc length s'
    set ylabel 'κ'
    unset key
    plot for [a=0:5] f every ::(first(m, a))::(last(m, a)) u ($1==m && $2==a ? $6 : 1/0):($1==m && $2==a ? $7 : 1/0):(a) w l lw 1.5 lc palette
  }
  unset multiplot
  unset output
}
