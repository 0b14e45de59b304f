# pseudo_energy: Table 1 data — combs of every interpolation method (experiment method_comparison; cagd compare draws the same).
prefix = 'fig_compare_table1_'; heading = 'Table 1 data'; figures = 'combs'
f_methods = datadir.'/fig_compare_table1_methods.csv'
f_points = datadir.'/fig_compare_table1_points.csv'
f_curves = datadir.'/fig_compare_table1_curves.csv'
f_combs = datadir.'/fig_compare_table1_combs.csv'
f_kappa = datadir.'/fig_compare_table1_curvature.csv'
load 'scripts/plot/compare_panels.gp'
