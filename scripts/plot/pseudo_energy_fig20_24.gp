# Figs. 20–24: the drawing of pseudo_energy_fig10_14.gp for the Table 3 (knot) data.
name = 'fig20_24'
load 'scripts/plot/pseudo_energy_fig10_14.gp'
