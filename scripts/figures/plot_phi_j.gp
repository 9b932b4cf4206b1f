# phi_J against N: our means with one standard deviation (as the thesis's Fig. S5.2 draws its
# points), the maxima of the distributions, packings with rattlers kept at larger N, and the
# finite-size law of the thesis with its three values.
# Usage: gnuplot -e "in='phi_J.csv'; out='phi_J.png'"
set terminal pngcairo size 860,580 font ",11"
set output out
set datafile separator ","
set xlabel "N (spheres)"
set ylabel "{/Symbol f}_J"
set logscale x
set xtics (16, 32, 50, 128, 256)
set xrange [12:330]
set yrange [0.56:0.65]
set key bottom right
set grid
law(n) = 0.639 - 0.12 * n**(-1.0 / (3 * 0.71))
iso(s) = (strcol(2) eq "rattler_free_isostatic") ? s : NaN
all(s) = (strcol(2) eq "all_packings") ? s : NaN
plot law(x) title "thesis: 0.639 - 0.12 N^{-1/(3{/Symbol n})}, {/Symbol n} = 0.71 (maximum of the distribution)" lw 2 lc rgb "#888888", \
     0.639 title "{/Symbol f}* = 0.639" dt 2 lc rgb "#888888", \
     "-" using 1:2 with points pt 6 ps 1.6 lc rgb "#cc3311" title "thesis (law's values quoted)", \
     in every ::1 using (iso($1)):4:6 with yerrorbars pt 7 ps 1.2 lc rgb "#0077bb" title "rattler-free isostatic, mean ± s.d.", \
     in every ::1 using (iso($1)*1.04):7 with points pt 12 ps 1.4 lc rgb "#0077bb" title "rattler-free isostatic, maximum", \
     in every ::1 using (all($1)*0.96):4:6 with yerrorbars pt 5 ps 1.0 lc rgb "#009988" title "rattlers kept, mean ± s.d."
16,0.606
32,0.615
50,0.620
e
