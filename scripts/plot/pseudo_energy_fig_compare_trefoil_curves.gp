# pseudo_energy: a trefoil knot, 24 points, closed — curves of every method (experiment space_pseudo_spline; cagd compare draws the same).
prefix = 'fig_compare_trefoil_'; heading = 'Trefoil, 24 points'; figures = 'curves'; space = 1
f_methods = datadir.'/fig_compare_trefoil_methods.csv'
f_points = datadir.'/fig_compare_trefoil_points.csv'
f_curves = datadir.'/fig_compare_trefoil_curves.csv'
f_combs = datadir.'/fig_compare_trefoil_combs.csv'
f_kappa = datadir.'/fig_compare_trefoil_curvature.csv'
load 'scripts/plot/compare_panels.gp'
