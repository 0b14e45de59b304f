# typical_curves Fig. 6: the rotation of a control polygon about its diagonal; the 25×25 net and the
# bi-24 patch; Gaussian and mean curvature maps. fig6_diagonal.csv: kind, x, y, z; fig6_net.csv:
# i, j, x, y, z; fig6_surface.csv: u, v, x, y, z, gaussian, mean (blocks of constant u).
load 'scripts/plot/style.gp'
d = datadir.'/fig6_diagonal.csv'
n = datadir.'/fig6_net.csv'
s = datadir.'/fig6_surface.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1300,1100 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1300,1100 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig6.'.t
  set multiplot layout 2,2 title 'Fig. 6: nonstationary typical surface (25×25 control points, α = −0.5 / −0.6 boundaries, 0.01° per polygon)'
  set view 60,30
  set xlabel 'x'
  set ylabel 'y'
  set zlabel 'z'
  set key top left
  set title 'P(i+1,j+1) turns about the diagonal P(i+1,j)–P(i,j+1)'
  splot d skip 1 u ((strcol(1) eq 'circle') ? $2 : 1/0):3:4 w l ls 3 t 'circle of the fourth point', \
        d skip 1 u ((strcol(1) eq 'given') ? $2 : 1/0):3:4 w p ls 5 pt 7 ps 1.5 t 'P(i,j), P(i+1,j), P(i,j+1)', \
        d skip 1 u ((strcol(1) eq 'parallelogram') ? $2 : 1/0):3:4 w p ls 1 pt 9 ps 2 t 'parallelogram point', \
        d skip 1 u ((strcol(1) eq 'turned_40deg') ? $2 : 1/0):3:4 w p ls 2 pt 5 ps 2 t 'turned by 40°'
  set title 'control net and bi-24 Bézier patch'
  splot s skip 1 every 2:2 u 3:4:5 w l ls 1 t 'patch', n skip 1 u 3:4:5 w l ls 5 lw 0.5 t 'control net (rows i)'
  set view map
  set size ratio -1
  set xlabel 'u'
  set ylabel 'v'
  set palette rgbformulae 33,13,10
  set title 'Gaussian curvature K'
  splot s skip 1 u 1:2:6 w pm3d notitle
  set title 'mean curvature H (normal S_u × S_v)'
  splot s skip 1 u 1:2:7 w pm3d notitle
  unset multiplot
  unset output
}
