# Percolation probability against porosity per delta (percolate sweep's bins with their
# binomial errors, and kcfit's maximum-likelihood sigmoids), and phi_c(delta) with kcfit's
# threshold law. Every table is read by its column names.
# Usage: gnuplot -e "prob='probability.csv'; phic='phi_c.csv'; law='threshold_fit.csv'; out='x.png'" plot_percolation.gp
set terminal pngcairo size 1200,500 enhanced font "Sans,11"
set output out
set datafile separator ","
# The fitted parameters first (stats obeys the axis ranges set later).
sig(x, p, w) = 1 / (1 + exp(-(x - p) / w))
deltas = "0.03 0.04 0.05 0.06 0.07"
array P[5]; array W[5]
do for [k = 1:5] {
  d = real(word(deltas, k))
  stats phic using (abs(column("delta") - d) < 1e-9 ? column("phi_c") : 1/0) nooutput; P[k] = STATS_mean
  stats phic using (abs(column("delta") - d) < 1e-9 ? column("width") : 1/0) nooutput; W[k] = STATS_mean
}
stats law using (strcol(1) eq "phi_c_star" ? $2 : 1/0) nooutput; S = STATS_mean
stats law using (strcol(1) eq "A" ? $2 : 1/0) nooutput; A = STATS_mean
stats law using (strcol(1) eq "beta" ? $2 : 1/0) nooutput; B = STATS_mean
set multiplot layout 1,2
set xlabel "porosity {/Symbol f}"
set ylabel "percolation probability P"
set key bottom right
set grid
set xrange [0:0.4]
set yrange [-0.05:1.05]
set title "P({/Symbol f}) = 1 / (1 + exp(-({/Symbol f} - {/Symbol f}_c) / w)), one maximum-likelihood fit per {/Symbol d}"
plot for [k = 1:5] prob using (abs(column("delta") - real(word(deltas, k))) < 1e-9 ? column("porosity") : 1/0):"probability":"probability_error" \
       with yerrorbars pt 7 lc k title sprintf("{/Symbol d} = %s D_0", word(deltas, k)), \
     for [k = 1:5] sig(x, P[k], W[k]) lc k notitle
set xlabel "voxel side {/Symbol d} / D_0"
set ylabel "percolation threshold {/Symbol f}_c"
set title "{/Symbol f}_c({/Symbol d}) = {/Symbol f}_c^* + A {/Symbol d}^{/Symbol b}, weighted by the errors of {/Symbol f}_c"
set xrange [0:0.08]
set yrange [0:0.3]
set key top left
plot phic using "delta":"phi_c":"phi_c_error" with yerrorbars pt 7 lc rgb "#0072b2" title "jammed spheres, ML sigmoid per {/Symbol d}", \
     S + A * x**B lw 2 lc rgb "#0072b2" title sprintf("fit: %.3f + %.2f {/Symbol d}^{%.2f}", S, A, B), \
     0.035 + 3.67 * x**1.1 lw 2 dt 2 lc rgb "#888888" title "thesis, shells N = 50: 0.035 + 3.67 {/Symbol d}^{1.1}"
unset multiplot
