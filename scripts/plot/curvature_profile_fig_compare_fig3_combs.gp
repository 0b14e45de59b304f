# curvature_profile: Fig. 3 points — combs of every interpolation method (experiment method_comparison; cagd compare draws the same).
prefix = 'fig_compare_fig3_'; heading = 'Fig. 3 points'; figures = 'combs'
f_methods = datadir.'/fig_compare_fig3_methods.csv'
f_points = datadir.'/fig_compare_fig3_points.csv'
f_curves = datadir.'/fig_compare_fig3_curves.csv'
f_combs = datadir.'/fig_compare_fig3_combs.csv'
f_kappa = datadir.'/fig_compare_fig3_curvature.csv'
load 'scripts/plot/compare_panels.gp'
