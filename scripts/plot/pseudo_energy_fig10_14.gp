# Figs. 10–14 (Table 1 data) and, with name = 'fig20_24', Figs. 20–24 (Table 3 data): the five
# curves of section 4.2 (top row, data points as circles) and their curvature κ(s) (bottom row).
# Data columns: method (1 cubic A, 2 cubic B, 3 Hermite A, 4 Hermite B, 5 pseudo-spline), u, x, y, s, kappa.
load 'scripts/plot/style.gp'
if (!exists("name")) name = 'fig10_14'
f = datadir.'/'.name.'.csv'
titles = "'cubic spline A (uniform t)' 'cubic spline B (chord length)' 'Hermite curve A' 'Hermite curve B' 'pseudo-spline (exact optimisation)'"
heading = (name eq 'fig10_14') ? 'Figs. 10–14 — Table 1 (Newbery–Garrett) data' : 'Figs. 20–24 — Table 3 (knot) data'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 2000,800 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 2000,800 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/'.name.'.'.t
  set multiplot layout 2,5 title heading
  do for [m=1:5] {
    set title word(titles, m)
    set xlabel 'x'
    set ylabel 'y'
    set size ratio -1
    if (name eq 'fig20_24') { set yrange [-0.7:0.5] } else { set autoscale y }
    unset key
    plot f u ($1==m ? $3 : 1/0):($1==m ? $4 : 1/0) w l ls 1, \
         f u ($1==m && $2==int($2) ? $3 : 1/0):($1==m && $2==int($2) ? $4 : 1/0) w p ls 5
  }
  do for [m=1:5] {
    set title 'curvature κ(s)'
    set xlabel 'arc length s'
    set ylabel 'κ'
    set size noratio
    set autoscale y
    unset key
    plot f u ($1==m ? $5 : 1/0):($1==m ? $6 : 1/0) w l lw 1.5 lc rgb '#d62728'
  }
  unset multiplot
  unset output
}
