# The chain's results (make flow-figure): kappa in D0^2 and tau_H against porosity from lbflow,
# with kcfit's Eq. 5.8 and tortuosity fits, and kappa against the refinement M. Every table
# is read by its column names.
# Usage: gnuplot -e "flows='f.csv'; kfit='k.csv'; tfit='t.csv'; refine='r.csv'; out='x.png'" plot_flow.gp
set terminal pngcairo size 1500,480 enhanced font "Sans,11"
set output out
set datafile separator ","
stats kfit using (strcol(1) eq "C" ? $2 : 1/0) nooutput; KC = STATS_mean
stats kfit using (strcol(1) eq "phi_c" ? $2 : 1/0) nooutput; KP = STATS_mean
stats kfit using (strcol(1) eq "gamma" ? $2 : 1/0) nooutput; KG = STATS_mean
stats tfit using (strcol(1) eq "C" ? $2 : 1/0) nooutput; TC = STATS_mean
stats tfit using (strcol(1) eq "phi_c" ? $2 : 1/0) nooutput; TP = STATS_mean
kc(x) = x > KP ? KC * (x - KP)**(KG + 0.76) * x**2 / (1 - x)**2 : 1/0
tau(x) = x > TP ? TC * (x - TP)**(-0.38) : 1/0
set multiplot layout 1,3
set grid
set xlabel "porosity {/Symbol f}"
set xrange [0:0.7]
set key top left
set logscale y
set format y "10^{%L}"
set ylabel "permeability {/Symbol k} [D_0^2]"
set title "{/Symbol k} (lbflow) and Eq. 5.8 (kcfit kc-percolation, log loss)"
plot flows using "porosity":"permeability_d02" with points pt 7 lc rgb "#0072b2" title "inflated jammed spheres", \
     kc(x) lw 2 lc rgb "#d55e00" title sprintf("{/Symbol f}_c = %.3f, {/Symbol g} = %.2f", KP, KG)
unset logscale y
set format y "%g"
set ylabel "hydraulic tortuosity {/Symbol t}_H"
set title "{/Symbol t}_H = {/Symbol S}|u| / {/Symbol S}u_x and C ({/Symbol f} - {/Symbol f}_c)^{-0.38}"
set key top right
plot flows using "porosity":"tortuosity" with points pt 7 lc rgb "#0072b2" title "inflated jammed spheres", \
     tau(x) lw 2 lc rgb "#d55e00" title sprintf("{/Symbol f}_c = %.3f", TP)
set xlabel "refinement M (nodes per voxel side)"
set xrange [0.5:3.5]
set xtics 1
set ylabel "{/Symbol k}(M) / {/Symbol k}(3)"
set title "refinement (thesis 5.3.3): N = 16, loose and tight"
stats refine using (column("refine") == 3 && column("scale") > 1.02 ? column("permeability_d02") : 1/0) nooutput; K3t = STATS_mean
stats refine using (column("refine") == 3 && column("scale") < 1.02 ? column("permeability_d02") : 1/0) nooutput; K3l = STATS_mean
set key top right
plot refine using (column("scale") > 1.02 ? column("refine") : 1/0):(column("permeability_d02") / K3t) \
       with linespoints pt 7 lc rgb "#d55e00" title "tight (scale 1.04)", \
     refine using (column("scale") < 1.02 ? column("refine") : 1/0):(column("permeability_d02") / K3l) \
       with linespoints pt 5 lc rgb "#0072b2" title "loose (scale 1.00)", \
     1 lc rgb "#888888" dt 2 notitle
unset multiplot
