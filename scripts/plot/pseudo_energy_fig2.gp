load 'scripts/plot/style.gp'
do for [name in "fig2 fig3"] {
  f = datadir.'/'.name.'.csv'
  c = datadir.'/'.name.'_curves.csv'
  do for [t in "png svg"] {
    if (t eq "png") { eval png_terminal } else { eval svg_terminal }
    set output datadir.'/'.name.'.'.t
    set multiplot layout 1,2 title (name eq "fig2" ? 'Fig. 2 — (θ0, θ1) = (150°, −150°): E has no minimum' : 'Fig. 3 — (θ0, θ1) = (45°, −45°): local minimum only')
    set title 'curves, r0 = r1 = r'
    set size ratio -1
    set xlabel 'x'
    set ylabel 'y'
    set key bottom right
    plot c u 2:3 w l ls 1 t 'r = 0.5', c u 4:5 w l ls 2 t 'r = 1', c u 6:7 w l ls 3 t 'r = 2', c u 8:9 w l ls 4 t 'r = 4'
    set size noratio
    set title 'strain energy'
    set logscale x
    set xlabel 'r'
    set ylabel 'log_{10} E'
    set key top right
    plot f u 1:2 w l ls 1 t 'log_{10} E'
    unset logscale x
    unset multiplot
    unset output
  }
}
