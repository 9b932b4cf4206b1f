# phi_J against N: our 100-packing means with standard errors, the thesis's finite-size law
# (Fig. S5.2) and its three quoted values. Usage: gnuplot -e "in='phi_J.csv'; out='phi_J.png'"
set terminal pngcairo size 800,560 font ",11"
set output out
set datafile separator ","
set xlabel "N (spheres)"
set ylabel "{/Symbol f}_J"
set logscale x
set xrange [10:200]
set yrange [0.56:0.65]
set key bottom right
set grid
law(n) = 0.639 - 0.12 * n**(-1.0 / (3 * 0.71))
plot law(x) title "thesis: 0.639 - 0.12 N^{-1/(3{/Symbol n})}, {/Symbol n} = 0.71" lw 2 lc rgb "#888888", \
     0.639 title "{/Symbol f}* = 0.639" dt 2 lc rgb "#888888", \
     "-" using 1:2 with points pt 6 ps 1.6 lc rgb "#cc3311" title "thesis (quoted, Fig. S5.2)", \
     in every ::1 using 1:3:4 with yerrorbars pt 7 ps 1.2 lc rgb "#0077bb" title "shellpack jam, 100 packings per N (mean ± s.e.)"
16,0.606
32,0.615
50,0.620
e
