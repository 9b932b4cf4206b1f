# Annealing trace of `rndmesh random --trace`: acceptance and energy per point against T.
# gnuplot -e "in='anneal.csv'; out='anneal.png'" scripts/figures/plot_anneal.gp
# The title names N and the seed, read from the trace's "# points=" and "# seed=" lines.
meta(key) = system(sprintf("sed -n 's/^# %s=//p' '%s' | head -n 1", key, in))
N = meta("points")
seed = meta("seed")
set terminal pngcairo size 900,420 font ",11"
set output out
set datafile separator ","
set datafile commentschars "#"
set key autotitle columnhead
set logscale x
set autoscale xfix
set xrange [*:*] reverse
set xlabel "temperature T [energy units]"
set multiplot layout 1,2 title sprintf("simulated annealing of N = %s points on the sphere, seed %s", N, seed)
set ylabel "acceptance"
plot in using 2:3 with linespoints pt 7 ps 0.4 notitle
set ylabel "energy per point [energy units]"
set logscale y
plot in using 2:4 with linespoints pt 7 ps 0.4 notitle
unset multiplot
