# Draws Fig. 2; pseudo_energy_fig3.gp sets name = 'fig3' and loads this file.
load 'scripts/plot/style.gp'
if (!exists("name")) name = 'fig2'
{
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
    set key top left box opaque
    set offsets 0, 0, 0.35, 0.05   # room for the key above the curves
    plot c u 2:3 w l ls 1 t 'r = 0.5', c u 4:5 w l ls 2 t 'r = 1', c u 6:7 w l ls 3 t 'r = 2', c u 8:9 w l ls 4 t 'r = 4'
    set size noratio
    set offsets 0, 0, 0, 0
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
