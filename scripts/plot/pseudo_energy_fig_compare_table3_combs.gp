# pseudo_energy: Table 3 (knot) data — combs of every interpolation method (experiment method_comparison; cagd compare draws the same).
prefix = 'fig_compare_table3_'; heading = 'Table 3 (knot) data'; figures = 'combs'
f_methods = datadir.'/fig_compare_table3_methods.csv'
f_points = datadir.'/fig_compare_table3_points.csv'
f_curves = datadir.'/fig_compare_table3_curves.csv'
f_combs = datadir.'/fig_compare_table3_combs.csv'
f_kappa = datadir.'/fig_compare_table3_curvature.csv'
load 'scripts/plot/compare_panels.gp'
