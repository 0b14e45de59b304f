# typical_curves Fig. 3: the degree-24 typical Bézier space curve (α = 1.5, β = 1.2) with its control
# polygon and the x, y, z axes; perspective and three views. space_curve.csv: degree, t, x, y, z
# (index 0/1/2 = degrees 99/49/24, index 3 the target); space_polygon.csv: degree, x, y, z.
load 'scripts/plot/style.gp'
c = datadir.'/space_curve.csv'
p = datadir.'/space_polygon.csv'
do for [t in "png svg"] {
  if (t eq "png") { set terminal pngcairo size 1200,1000 enhanced font 'DejaVu Sans,11' } else { set terminal svg size 1200,1000 enhanced font 'DejaVu Sans,11' }
  set output datadir.'/fig3.'.t
  set multiplot layout 2,2 title 'Fig. 3: typical Bézier space curve, degree 24, α = 1.5, β = 1.2 (our s0 = 0.1, L = 1)'
  set title 'perspective, with the x, y, z axes'
  set view 65,40
  set xlabel 'x'
  set ylabel 'y'
  set zlabel 'z'
  set key top left
  set arrow 1 from 0,0,0 to 1,0,0 lc rgb 'black'
  set arrow 2 from 0,0,0 to 0,0.6,0 lc rgb 'black'
  set arrow 3 from 0,0,0 to 0,0,0.3 lc rgb 'black'
  splot c index 2 skip 1 u 3:4:5 w l ls 1 t 'Bézier curve', p index 2 skip 1 u 2:3:4 w lp ls 5 t 'control polygon', \
        c index 3 u 3:4:5 w l ls 3 dt 2 t 'target (Frenet–Serret)'
  unset arrow 1
  unset arrow 2
  unset arrow 3
  do for [v=1:3] {
    cx = (v == 3 ? 4 : 3)
    cy = (v == 1 ? 4 : 5)
    set title (v == 1 ? 'plan (x-y)' : (v == 2 ? 'front (x-z)' : 'side (y-z)')).', axes not to scale'
    set xlabel (v == 3 ? 'y' : 'x')
    set ylabel (v == 1 ? 'y' : 'z')
    plot c index 2 skip 1 u cx:cy w l ls 1 t 'Bézier curve', p index 2 skip 1 u (column(cx-1)):(column(cy-1)) w lp ls 5 t 'control polygon', \
         c index 3 u cx:cy w l ls 3 dt 2 t 'target'
  }
  unset multiplot
  unset output
}
