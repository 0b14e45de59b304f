# The figures of a method comparison (`cagd compare`, and the comparisons in the report).
# Set before loading: datadir, prefix (file-name prefix inside datadir, may be ''), heading (a
# title line), and optionally formats (default "png svg"), figures (default "curves combs
# curvature"), point_every (draw every n-th data point; default 1), panel_point_every (the same in
# each small panel of the combs figure, which draws the points once per method; default
# point_every) and the file names f_methods, f_points, f_curves, f_combs, f_kappa. The files are the comparison folder's tables
# (src/cagd/compare/comparison_tables.hpp), read by column name: methods.csv (method, and per
# figure file the first row and row count of each method), points.csv (x, y), curves.csv
# (x, y), combs.csv (x, y, tip_x, tip_y) and curvature.csv (s, kappa); it writes prefix.'curves',
# 'combs' and 'curvature' in each format. With space = 1 (space points: points.csv and curves.csv
# also z, curvature.csv also tau) the curves are drawn in a 3-D view, and figure 'torsion' draws
# τ(s); there are no combs. A method's rows are read with `every ::first::last` (gnuplot stops
# reading there). gnuplot only draws.
# This file is not a figure of its own: scripts/reproduce.sh skips it, and `cagd compare` embeds it.
set datafile separator ','
set grid lc rgb '#dddddd'
set border lw 1.2
if (!exists("formats")) formats = "png svg"
if (!exists("figures")) figures = "curves combs curvature"
if (!exists("f_methods")) f_methods = datadir.'/'.prefix.'methods.csv'
if (!exists("f_points")) f_points = datadir.'/'.prefix.'points.csv'
if (!exists("f_curves")) f_curves = datadir.'/'.prefix.'curves.csv'
if (!exists("f_combs")) f_combs = datadir.'/'.prefix.'combs.csv'
if (!exists("f_kappa")) f_kappa = datadir.'/'.prefix.'curvature.csv'
if (!exists("point_every")) point_every = 1
if (!exists("panel_point_every")) panel_point_every = point_every
if (!exists("space")) space = 0
# The positions of the columns called `names` (space-separated) in the header line of file f, as
# words (0 where there is none): one awk run per file.
colnums(f, names) = system("awk -F, -v names='".names."' 'NR == 1 { sub(/\\r$/, \"\"); for (i = 1; i <= NF; i++) c[$i] = i; n = split(names, w, \" \"); for (j = 1; j <= n; j++) printf \"%d \", c[w[j]] + 0; exit }' '".f."'")
# methods.csv's columns as gnuplot strings of words, one per row: `pairs` names variable:column;
# one awk run writes the assignments, and eval makes them.
column_words(pairs) = system("awk -F, -v pairs='".pairs."' 'NR == 1 { sub(/\\r$/, \"\"); for (i = 1; i <= NF; i++) c[$i] = i; n = split(pairs, p, \" \"); next } { sub(/\\r$/, \"\"); for (j = 1; j <= n; j++) { split(p[j], vc, \":\"); v[j] = v[j] (NR > 2 ? \" \" : \"\") ((vc[2] in c) ? $c[vc[2]] : \"\") } } END { for (j = 1; j <= n; j++) { split(p[j], vc, \":\"); printf \"%s = \\\"%s\\\"; \", vc[1], v[j] } }' '".f_methods."'")
eval column_words("names:method curves_first:curves_first curves_count:curves_count kappa_first:curvature_first kappa_count:curvature_count combs_first:combs_first combs_count:combs_count comb_stride:comb_stride comb_scale:comb_scale statuses:status")
p_cols = colnums(f_points, "x y z"); c_cols = colnums(f_curves, "x y z"); b_cols = colnums(f_combs, "x y tip_x tip_y"); k_cols = colnums(f_kappa, "s kappa tau")
px = int(word(p_cols, 1)); py = int(word(p_cols, 2)); pz = int(word(p_cols, 3))
cx = int(word(c_cols, 1)); cy = int(word(c_cols, 2)); cz = int(word(c_cols, 3))
bx = int(word(b_cols, 1)); by = int(word(b_cols, 2)); btx = int(word(b_cols, 3)); bty = int(word(b_cols, 4))
ks = int(word(k_cols, 1)); kk = int(word(k_cols, 2)); kt = int(word(k_cols, 3))
n = words(names)
# rows of method i in a figure file: first(list, i) .. last(list, counts, i). A method without rows
# (not applicable, refused, no result) reads one row, which `with lines` cannot draw (a line needs
# two points; the row lies on another method's curve, so the autoscaled range is the same) and has
# no key entry (label), never another method's data: `every` with its last row before its first
# would read the whole file. Columns are given by number (`using cx:cy`), not as expressions
# (`(column(cx))`): gnuplot evaluates an expression per row, with a signal handler set and a jump
# buffer saved around each (two system calls), which took 60 % of a figure's time at 10^3 points.
first(list, i) = int(word(list, i))
has(counts, i) = int(word(counts, i)) > 0
last(list, counts, i) = has(counts, i) ? int(word(list, i)) + int(word(counts, i)) - 1 : int(word(list, i))
# A method without a curve has no key entry in an overlay (its own panel says why).
label(i, counts) = has(counts, i) ? word(names, i) : ''
# 28 distinct colours (matplotlib's tab20 order: each dark colour then its light one; then eight
# dark ones of tab20b), then dashes: a method's colour is its own up to 28 methods, and the pair
# with its dash type up to 140.
palette = "#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #8c564b #e377c2 #7f7f7f #bcbd22 #17becf #aec7e8 #ffbb78 #98df8a #ff9896 #c5b0d5 #c49c94 #f7b6d2 #c7c7c7 #dbdb8d #9edae5 #393b79 #637939 #8c6d31 #843c39 #7b4173 #5254a3 #8ca252 #bd9e39"
colour(i) = word(palette, (i - 1) % 28 + 1)
dash(i) = int((i - 1) / 28) + 1
# Why a method has no curve, comb or profile: its status (methods.csv, spaces written as '-').
status(i) = word(statuses, i)
cols = n <= 4 ? n : (n <= 9 ? 3 : (n <= 16 ? 4 : 5))
rows = int((n + cols - 1) / cols)
do for [t in formats] {
  # 1. every curve over the points
  if (strstrt(figures, "curves") > 0) {
  if (t eq "png") { set terminal pngcairo size 1100,800 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1100,800 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/'.prefix.'curves.'.t
  set title heading.': every method over the data points' noenhanced
  set size ratio -1
  set key outside right top noenhanced
  set xlabel 'x'
  set ylabel 'y'
  if (space) {
    set size noratio
    set view 60, 30, 0.8, 1.0
    set view equal xyz
    set xyplane relative 0
    set zlabel 'z'
    splot for [i=1:n] f_curves skip 1 every ::first(curves_first, i)::last(curves_first, curves_count, i) using cx:cy:cz with lines lw 1.5 lc rgb colour(i) dt dash(i) title label(i, curves_count), \
          f_points skip 1 every point_every using px:py:pz with points pt 7 ps 0.8 lc rgb '#000000' title 'data'
    unset view
    unset zlabel
  } else {
    plot for [i=1:n] f_curves skip 1 every ::first(curves_first, i)::last(curves_first, curves_count, i) using cx:cy with lines lw 1.5 lc rgb colour(i) dt dash(i) title label(i, curves_count), \
         f_points skip 1 every point_every using px:py with points pt 7 ps 0.8 lc rgb '#000000' title 'data'
  }
  unset output
  }
  # 2. per method: curve and curvature comb
  if (!space && strstrt(figures, "combs") > 0) {
  set size ratio -1
  if (t eq "png") { set terminal pngcairo size 360*cols,300*rows enhanced font 'DejaVu Sans,9' } else { set terminal svg size 360*cols,300*rows enhanced font 'DejaVu Sans,9' }
  set output datadir.'/'.prefix.'combs.'.t
  # the data's box grown by 30 % of its diagonal: the 5 % of teeth longer than 10 % of it are cut
  # at the frame instead of shrinking the curve to a dot
  stats f_points skip 1 using px:py nooutput
  margin = 0.3 * sqrt((STATS_max_x - STATS_min_x)**2 + (STATS_max_y - STATS_min_y)**2)
  set xrange [STATS_min_x - margin:STATS_max_x + margin]
  set yrange [STATS_min_y - margin:STATS_max_y + margin]
  set clip two
  set multiplot layout rows,cols title heading.': curvature combs (teeth -c κ n; one c for every panel: the 95th percentile of |κ| over all methods = 10 % of the diagonal; frame: data box + 30 %)' noenhanced
  unset key
  unset xlabel
  unset ylabel
  do for [i=1:n] {
    comb_note = int(word(comb_stride, i)) > 0 ? ' (c = '.word(comb_scale, i).(int(word(comb_stride, i)) > 1 ? ', a tooth every '.word(comb_stride, i).' samples)' : ')') : ''
    set title word(names, i).comb_note noenhanced
    if (int(word(combs_count, i)) > 0) {
      plot f_combs skip 1 every ::first(combs_first, i)::last(combs_first, combs_count, i) using bx:by:(column(btx) - column(bx)):(column(bty) - column(by)) with vectors nohead lc rgb '#9ecae1', \
           f_combs skip 1 every ::first(combs_first, i)::last(combs_first, combs_count, i) using btx:bty with lines lc rgb '#6baed6', \
           f_curves skip 1 every ::first(curves_first, i)::last(curves_first, curves_count, i) using cx:cy with lines lw 1.5 lc rgb '#08306b', \
           f_points skip 1 every panel_point_every using px:py with points pt 7 ps 0.5 lc rgb '#000000'
    } else {
      set label 1 'no comb: '.status(i).' (see the table)' at graph 0.5, graph 0.92 center noenhanced
      if (has(curves_count, i)) {  # a curve without a comb (a cusp): the curve still shows
        plot f_curves skip 1 every ::first(curves_first, i)::last(curves_first, curves_count, i) using cx:cy with lines lw 1.5 lc rgb '#08306b', \
             f_points skip 1 every panel_point_every using px:py with points pt 7 ps 0.5 lc rgb '#000000'
      } else {
        plot f_points skip 1 every panel_point_every using px:py with points pt 7 ps 0.5 lc rgb '#000000'
      }
      unset label 1
    }
  }
  unset multiplot
  unset output
  set autoscale xy
  }
  # 3. per method: curvature profile κ(s)
  if (strstrt(figures, "curvature") > 0) {
  if (t eq "png") { set terminal pngcairo size 360*cols,300*rows enhanced font 'DejaVu Sans,9' } else { set terminal svg size 360*cols,300*rows enhanced font 'DejaVu Sans,9' }
  unset key
  set output datadir.'/'.prefix.'curvature.'.t
  set size noratio
  set multiplot layout rows,cols title heading.': curvature κ against arc length s (each panel on its own κ scale: its range is in its title)' noenhanced
  do for [i=1:n] {
    set title word(names, i) noenhanced
    set xlabel 's'
    set ylabel 'κ'
    if (int(word(kappa_count, i)) > 0) {
      set autoscale xy   # (stats keeps to the ranges set before)
      stats f_kappa skip 1 every ::first(kappa_first, i)::last(kappa_first, kappa_count, i) using kk nooutput
      set title sprintf('%s: κ from %.4g to %.4g', word(names, i), STATS_min, STATS_max) noenhanced
      plot f_kappa skip 1 every ::first(kappa_first, i)::last(kappa_first, kappa_count, i) using ks:kk with lines lw 1.2 lc rgb '#d62728'
    } else {
      set label 1 'no curvature: '.status(i).' (see the table)' at graph 0.5, graph 0.5 center noenhanced
      plot [0:1] [-1:1] NaN notitle
      unset label 1
    }
  }
  unset multiplot
  unset output
  unset xlabel
  unset ylabel
  }
  # 4. per method (space): torsion profile τ(s)
  if (space && strstrt(figures, "torsion") > 0) {
  if (t eq "png") { set terminal pngcairo size 360*cols,300*rows enhanced font 'DejaVu Sans,9' } else { set terminal svg size 360*cols,300*rows enhanced font 'DejaVu Sans,9' }
  unset key
  set output datadir.'/'.prefix.'torsion.'.t
  set size noratio
  set multiplot layout rows,cols title heading.': torsion τ against arc length s (each panel on its own τ scale: its range is in its title)' noenhanced
  do for [i=1:n] {
    set title word(names, i) noenhanced
    set xlabel 's'
    set ylabel 'τ'
    if (int(word(kappa_count, i)) > 0) {
      set autoscale xy
      stats f_kappa skip 1 every ::first(kappa_first, i)::last(kappa_first, kappa_count, i) using kt nooutput
      set title sprintf('%s: τ from %.4g to %.4g', word(names, i), STATS_min, STATS_max) noenhanced
      plot f_kappa skip 1 every ::first(kappa_first, i)::last(kappa_first, kappa_count, i) using ks:kt with lines lw 1.2 lc rgb '#2ca02c'
    } else {
      set label 1 'no torsion: '.status(i).' (see the table)' at graph 0.5, graph 0.5 center noenhanced
      plot [0:1] [-1:1] NaN notitle
      unset label 1
    }
  }
  unset multiplot
  unset output
  unset xlabel
  unset ylabel
  }
}
