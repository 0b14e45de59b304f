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
  # One scale for the five curve panels (equal aspect, the same x and y ranges: the data's and every
  # curve's extent with a margin) and one for the five curvature panels, so that side by side equal
  # lengths are equal lengths and equal spikes equal curvature.
  stats [*:*][*:*] f u 3:4 nooutput
  mx = 0.04 * (STATS_max_x - STATS_min_x); my = 0.04 * (STATS_max_y - STATS_min_y)
  x_lo = STATS_min_x - mx; x_hi = STATS_max_x + mx; y_lo = STATS_min_y - my; y_hi = STATS_max_y + my
  stats [*:*][*:*] f u 5:6 nooutput
  s_hi = STATS_max_x; k_lo = STATS_min_y; k_hi = STATS_max_y; mk = 0.05 * (k_hi - k_lo)
  # Table 3's cusps reach |κ| ~ 10^3 beside the pseudo-spline's ~1: there each κ panel keeps its own
  # scale and prints it in its title.
  shared_kappa = (name eq 'fig10_14')
  kappa_scale = shared_kappa ? sprintf('every κ panel on one scale, κ from %.3g to %.3g', k_lo, k_hi) : 'each κ panel on its own scale, given in its title'
  set multiplot layout 2,5 title heading.sprintf(' (every curve panel on one scale, x from %.3g to %.3g; ', x_lo, x_hi).kappa_scale.')'
  do for [m=1:5] {
    set title word(titles, m)
    set xlabel 'x'
    set ylabel 'y'
    set size ratio -1
    set xrange [x_lo:x_hi]
    set yrange [y_lo:y_hi]
    unset key
    plot f u ($1==m ? $3 : 1/0):($1==m ? $4 : 1/0) w l ls 1, \
         f u ($1==m && $2==int($2) ? $3 : 1/0):($1==m && $2==int($2) ? $4 : 1/0) w p ls 5
  }
  do for [m=1:5] {
    set xlabel 'arc length s'
    set ylabel 'κ'
    set size noratio
    set xrange [0:s_hi]
    if (shared_kappa) {
      set title 'curvature κ(s)'
      set yrange [k_lo - mk:k_hi + mk]
    } else {
      set autoscale y   # (stats of one column keeps to the y range set before)
      stats f u ($1==m ? $6 : 1/0) nooutput
      set title sprintf('curvature κ(s), from %.3g to %.3g', STATS_min, STATS_max)
    }
    unset key
    plot f u ($1==m ? $5 : 1/0):($1==m ? $6 : 1/0) w l lw 1.5 lc rgb '#d62728'
  }
  unset multiplot
  unset output
}
