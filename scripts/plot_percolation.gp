# Percolation probability against porosity per delta (binned, with the fitted sigmoids), and
# phi_c(delta). Usage: gnuplot -e "prob='...'; phic='...'; out='x.png'" plot_percolation.gp
set terminal pngcairo size 1100,460 font ",11"
set output out
set datafile separator ","
set multiplot layout 1,2
set xlabel "porosity (1 - {/Symbol S}V/V_{box}, lenses corrected)"
set ylabel "percolation probability"
set key bottom right
set grid
set xrange [0:0.4]
set yrange [-0.05:1.05]
sig(x, p, w) = 1 / (1 + exp(-(x - p) / w))
deltas = "0.03 0.04 0.05 0.06 0.07"
array P[5]; array W[5]
do for [k = 1:5] {
  stats phic every ::k::k using 2 nooutput; P[k] = STATS_min
  stats phic every ::k::k using 4 nooutput; W[k] = STATS_min
}
plot for [k = 1:5] prob using (column("delta") == real(word(deltas, k)) ? column("porosity_mean") : 1/0):"probability":"probability_error" \
       with yerrorbars pt 7 lc k title sprintf("{/Symbol d} = %s D_0", word(deltas, k)), \
     for [k = 1:5] sig(x, P[k], W[k]) lc k notitle
set xlabel "{/Symbol d} (D_0)"
set ylabel "{/Symbol f}_c"
set xrange [0:0.08]
set yrange [0:0.3]
set key top left
plot phic using 1:2:3 with yerrorbars pt 7 lc rgb "#0077bb" title "jammed spheres, N = 50 (ML sigmoid)", \
     0.035 + 3.67 * x**1.1 lw 2 lc rgb "#888888" title "thesis, shells N = 50: 0.035 + 3.67 {/Symbol d}^{1.1}"
unset multiplot
