load 'scripts/plot/style.gp'
c = datadir.'/fig7_curves.csv'
f = datadir.'/fig7.csv'
do for [t in "png svg"] {
  if (t eq "png") { eval png_terminal } else { eval svg_terminal }
  set output datadir.'/fig7.'.t
  set multiplot layout 1,2 title 'Fig. 7 — θ0 = 30°: the minimiser jumps from s- to c-shape'
  set title 'minimising segments at the jump'
  set size ratio -1
  set xlabel 'x'
  set ylabel 'y'
  set key top left box opaque
    set offsets 0, 0, 0.35, 0.05   # room for the key above the curves
  plot c u 2:3 w l ls 1 t 's-type (just before)', c u 4:5 w l ls 2 t 'c-type (just after)'
  set size noratio
    set offsets 0, 0, 0, 0
  set title 'minimisers against θ1'
  set xlabel 'θ1 (degrees)'
  set ylabel 'r'
  set y2label 'J'
  set y2tics
  set key top left
  plot f u 1:3 w l ls 1 t 'r0', f u 1:4 w l ls 3 t 'r1', f u 1:2 axes x1y2 w l ls 2 t 'J (right axis)'
  unset y2tics
  unset y2label
  unset multiplot
  unset output
}
