# Shared plot style for every cagd-repro figure. Scripts set `datadir` (via -e) and
# `name`, then `load 'scripts/plot/style.gp'`, then call `render` twice (png, svg) through
# the macros below. gnuplot only draws: every number comes from the experiment's CSV.
set datafile separator ','
set key top right box opaque
set grid lc rgb '#dddddd'
set border lw 1.2
set style line 1 lc rgb '#1f77b4' lw 2 dt 1
set style line 2 lc rgb '#d62728' lw 2 dt 2
set style line 3 lc rgb '#2ca02c' lw 2 dt 1
set style line 4 lc rgb '#9467bd' lw 2 dt 2
set style line 5 lc rgb '#000000' lw 1 pt 6 ps 1.2
set style line 6 lc rgb '#ff7f0e' lw 2 dt 3
png_terminal = "set terminal pngcairo size 900,600 enhanced font 'DejaVu Sans,11'"
svg_terminal = "set terminal svg size 900,600 enhanced font 'DejaVu Sans,11'"
