# Fig. 3: the same drawing as Fig. 2 for the Fig. 3 direction pair.
name = 'fig3'
load 'scripts/plot/pseudo_energy_fig2.gp'
