# The figures of make jam2d-figures (thesis Figs 3.1h, 3.2a, 3.3, S3.2 at small boxes).
# Usage: gnuplot -e "dir='out/figures'" scripts/figures/plot_jam2d.gp
set terminal pngcairo size 860,580 font ",11"
set grid
set key left top
cols = "#009988 #0077bb #cc3311"
P0s = "inf 0.005 0.001"
name(i) = word(P0s, i) eq "inf" ? "no feedback" : "P_0 = ".word(P0s, i)

# Fig. 3.1h: P against phi, one colony at L = 15 sigma per P0.
set output dir."/jam2d_fig3_1h.png"
set xlabel "{/Symbol f}"
set ylabel "P [k]"
set xrange [0.8:1.01]
plot for [i=1:3] dir."/jam2d_fig3_1h_P0_".word(P0s, i).".dat" using 1:2 with lines lw 2 lc rgb word(cols, i) title name(i), \
     (x > 0.84 ? 2 / pi * (x - 0.84) : 0) dt 2 lc rgb "#888888" title "thesis 3.4.4: (2/{/Symbol p}) ({/Symbol f} - 0.84), P_{max} ≈ 0.1 k"

# Fig. 3.2a: f_u against P (means over seeds at each dphi, L = 10 sigma).
set output dir."/jam2d_fig3_2.png"
set autoscale x
set logscale x
set xlabel "P [k]"
set ylabel "f_u (unconstrained buds per cell)"
set key right top
plot for [i=1:3] dir."/jam2d_fig3_3_P0_".word(P0s, i).".dat" using 2:5 with linespoints pt 7 lw 2 lc rgb word(cols, i) title name(i), \
     0.25 dt 2 lc rgb "#888888" title "thesis: f_u ≈ 0.25 at jamming"

# Fig. 3.3: Z - Z_J and G against P, with the thesis's P^{1/2}; with FIG33_SEEDS, also the
# no-feedback means at L = 15 sigma (black, bars: s.d. over seeds).
set output dir."/jam2d_fig3_3.png"
L15 = dir."/jam2d_fig3_3_L15.dat"
has15 = system("test -f '".L15."' && echo 1 || echo 0") + 0
set multiplot layout 1,2
set logscale xy
set key left top
set ylabel "Z - Z_J"
if (has15) {
  plot for [i=1:3] dir."/jam2d_fig3_3_P0_".word(P0s, i).".dat" using 2:3 with linespoints pt 7 lw 2 lc rgb word(cols, i) title name(i), \
       L15 using 2:3:5 with yerrorlines pt 5 lw 2 lc rgb "black" title "no feedback, L = 15 {/Symbol s}", \
       20 * sqrt(x) dt 2 lc rgb "#888888" title "thesis: ∝ P^{1/2}"
} else {
  plot for [i=1:3] dir."/jam2d_fig3_3_P0_".word(P0s, i).".dat" using 2:3 with linespoints pt 7 lw 2 lc rgb word(cols, i) title name(i), \
       20 * sqrt(x) dt 2 lc rgb "#888888" title "thesis: ∝ P^{1/2}"
}
set ylabel "G [k]"
if (has15) {
  plot for [i=1:3] dir."/jam2d_fig3_3_P0_".word(P0s, i).".dat" using 2:4 with linespoints pt 7 lw 2 lc rgb word(cols, i) title name(i), \
       L15 using 2:4 with linespoints pt 5 lw 2 lc rgb "black" title "no feedback, L = 15 {/Symbol s}", \
       1.5 * sqrt(x) dt 2 lc rgb "#888888" title "thesis: ∝ P^{1/2}"
} else {
  plot for [i=1:3] dir."/jam2d_fig3_3_P0_".word(P0s, i).".dat" using 2:4 with linespoints pt 7 lw 2 lc rgb word(cols, i) title name(i), \
       1.5 * sqrt(x) dt 2 lc rgb "#888888" title "thesis: ∝ P^{1/2}"
}
unset multiplot

# Fig. S3.2: Z_J + 2/(N - N_r) against f_u, one point per packing, and Z_iso = 6 - 2 f_u.
set output dir."/jam2d_figS3_2.png"
unset logscale
set xlabel "f_u"
set ylabel "Z_J + 2/(N - N_r)"
set xrange [0:0.5]
set key right top
plot dir."/jam2d_figS3_2.dat" using 1:2 with points pt 7 lc rgb "#0077bb" title "jam2d, L = 10 {/Symbol s}", \
     6 - 2 * x dt 2 lw 2 lc rgb "#888888" title "thesis: Z_{iso} = 6 - 2 f_u"
