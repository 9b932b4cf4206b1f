# Figs 4.3, 4.4 and 4.6 of the thesis from shellpack compress (one row per box step),
# shellpack analyze (one row per written packing, and g(r)) and kcfit's power-law fit of dZ.
# Every table is read by its column names.
# Usage: gnuplot -e "runs='dir1 dir2'; labels='N=32 N=50'; packs='a.off b.off'; packlabels='0.001 0.3'; out='x.png'" plot_compress.gp
# Each run directory holds compress.csv, structure.csv, rdf.csv and dz_fit.csv; packs names
# packings of the first run (as in rdf.csv's file column) whose g(r) is drawn, packlabels
# their dphi (or, with packvar='{/Symbol f}', their phi).
if (!exists("packvar")) packvar = "{/Symbol df}"
set terminal pngcairo size 1500,900 enhanced font "Sans,10"
set output out
set datafile separator ","
nruns = words(runs)
label(k) = word(labels, k)
file(k, name) = word(runs, k) . "/" . name
array C[nruns]; array PC[nruns]; array B[nruns]
do for [k = 1:nruns] {
  stats file(k, "dz_fit.csv") using (strcol(1) eq "C" ? $2 : 1/0) nooutput; C[k] = STATS_mean
  stats file(k, "dz_fit.csv") using (strcol(1) eq "phi_c" ? $2 : 1/0) nooutput; PC[k] = STATS_mean
  stats file(k, "dz_fit.csv") using (strcol(1) eq "e" ? $2 : 1/0) nooutput; B[k] = STATS_mean
}
set multiplot layout 2,3
set grid
set key top left

set title "Fig. 4.3b: {/Symbol D}Z = Z - (6 - 4/N) against {/Symbol df} = {/Symbol f} - {/Symbol f}_J"
set logscale xy
set xlabel "{/Symbol df}"
set ylabel "{/Symbol D}Z"
set xrange [1e-3:0.5]
set yrange [0.05:20]
plot for [k = 1:nruns] file(k, "compress.csv") using "dphi":(column("dZ") > 0 ? column("dZ") : 1/0) with points pt 7 ps 0.5 lc k title label(k), \
     for [k = 1:nruns] (x > PC[k] && x <= 0.15 ? C[k] * (x - PC[k])**B[k] : 1/0) lw 2 lc k title sprintf("fit to {/Symbol df} = 0.15: %.1f ({/Symbol df} - %.3f)^{%.2f}", C[k], PC[k], B[k]), \
     4 * x**0.6 dt 2 lc rgb "#888888" title "slope 0.6 (thesis)"
unset logscale

set title "Z against {/Symbol f} (Statistical Honeycomb: 13.6)"
set xlabel "{/Symbol f} = N V_0 / L^3"
set ylabel "Z"
set autoscale
set xrange [*:*]
set yrange [0:16]
plot for [k = 1:nruns] file(k, "compress.csv") using "phi":"Z" with lines lw 2 lc k title label(k), \
     13.6 dt 2 lc rgb "#888888" title "13.6", 6 dt 3 lc rgb "#888888" title "6"

set title "Fig. 4.4 inset: reduced aspect ratio {/Symbol de} = {/Symbol l}_1/{/Symbol l}_3 - 1"
set logscale xy
set xlabel "{/Symbol df}"
set ylabel "{/Symbol de}"
set xrange [1e-3:0.5]
set yrange [*:*]
plot for [k = 1:nruns] file(k, "compress.csv") using "dphi":"delta_eps_mean" with points pt 7 ps 0.5 lc k title label(k), \
     2 * x**2 dt 2 lc rgb "#888888" title "{/Symbol df}^2"
unset logscale

set title "Fig. 4.6a: mean turgor <{/Symbol P}>/{/Symbol P}_0 (and its cv x 10)"
set xlabel "{/Symbol f}"
set ylabel "<{/Symbol P}>/{/Symbol P}_0"
set xrange [*:*]
set yrange [0:*]
plot for [k = 1:nruns] file(k, "compress.csv") using "phi":"turgor_mean_P0" with lines lw 2 lc k title label(k), \
     for [k = 1:nruns] file(k, "compress.csv") using "phi":(10 * column("turgor_cv")) with lines dt 2 lc k title "cv x 10"

set title "Fig. 4.3a: g(r) of the shell centres ({/Symbol s} = D_0 + the contact reach)"
set xlabel "r / {/Symbol s}"
set ylabel "g(r)"
set xrange [0.5:2.5]
set yrange [0:12]
set arrow 1 from sqrt(3), graph 0 to sqrt(3), graph 1 nohead dt 2 lc rgb "#888888"
set arrow 2 from 2, graph 0 to 2, graph 1 nohead dt 2 lc rgb "#888888"
plot for [k = 1:words(packs)] file(1, "rdf.csv") using (strcol("file") eq word(packs, k) ? column("r_d0") : 1/0):"g" \
       with lines lw 1.5 lc k title sprintf("%s, %s = %s", label(1), packvar, word(packlabels, k))
unset arrow 1
unset arrow 2

set title "Fig. 4.6c: <{/Symbol P}> against the mean normal contact force"
set xlabel "<F_c^{/Symbol \\136}> [E D_0^2]"
set ylabel "<{/Symbol P}> [E]"
set xrange [0:*]
set yrange [0:*]
plot for [k = 1:nruns] file(k, "structure.csv") using "force_normal_mean_F":"turgor_mean_P" with linespoints pt 7 lc k title label(k)
unset multiplot
