# The figures of make chamber-figures (thesis Figs 2.2b-c, 2.2e, S2.10, S2.13, 2.4c).
# Usage: gnuplot -e "dir='out/figures'" scripts/figures/plot_chamber.gp
set terminal pngcairo size 860,580 font ",11"
set grid
set datafile separator ","
set datafile commentschars "#"

# Fig. 2.2b-c: the wall pressure against time, without and with feedback.
set output dir."/chamber_fig2_2.png"
set multiplot layout 2,1
set xlabel "t [1/{/Symbol g}_0]"
set ylabel "P [k]"
set key right top
plot dir."/chamber_nofb.csv" using 1:6 every ::1 with lines lw 1 lc rgb "#0077bb" title "no feedback, {/Symbol m} = 8x10^4", \
     0.19 dt 2 lw 2 lc rgb "#888888" title "thesis <P> = 0.19 k"
plot dir."/chamber_fb.csv" using 1:6 every ::1 with lines lw 1 lc rgb "#cc3311" title "feedback P_0 = 0.07 k, {/Symbol m} = 2x10^3"
unset multiplot

# Fig. 2.2e: survival function of the drops over their mean, with the exponential tail fitted
# to the drops above the mean.
set output dir."/chamber_fig2_2e.png"
set logscale y
set xlabel "{/Symbol D}P / <{/Symbol D}P>"
set ylabel "fraction of drops larger"
set key right top
plot dir."/chamber_nofb_drops_dist.csv" using 1:2 every ::1 with points pt 7 ps 0.6 lc rgb "#0077bb" title "no feedback", \
     "" using 1:($3 > 0 ? $3 : 1/0) every ::1 with lines lw 2 lc rgb "#0077bb" title "exponential fit (drops > mean)", \
     dir."/chamber_fb_drops_dist.csv" using 1:2 every ::1 with points pt 5 ps 0.6 lc rgb "#cc3311" title "feedback", \
     "" using 1:($3 > 0 ? $3 : 1/0) every ::1 with lines lw 2 lc rgb "#cc3311" title "exponential fit"
unset logscale y

# Fig. S2.10: ratio of the mean drop rate to the mean rise rate against the mobility.
set datafile separator whitespace
set output dir."/chamber_figS2_10.png"
set logscale x
set xlabel "{/Symbol m} k / {/Symbol g}_0"
set ylabel "<dP/dt down> / <dP/dt up>"
set key left top
plot dir."/chamber_rates.dat" using 1:2 with linespoints pt 7 lw 2 lc rgb "#0077bb" title "no feedback (thesis fit: 8x10^4)", \
     "" using 1:3 with linespoints pt 5 lw 2 lc rgb "#cc3311" title "feedback P_0 = 0.07 k (thesis fit: 2x10^3)"
unset logscale x

# Figs. S2.13 and 2.4c: steady pressure and avalanche size against the outlet width.
set output dir."/chamber_outlets.png"
set xlabel "outlet a [{/Symbol s}]"
set ylabel "<P> [k]"
set y2label "mean avalanche [cells]"
set y2tics
set ytics nomirror
set key right top
plot dir."/chamber_outlets.dat" using 1:2 with linespoints pt 7 lw 2 lc rgb "#0077bb" title "<P>, repulsive", \
     "" using 1:4 with linespoints pt 5 lw 2 lc rgb "#cc3311" title "<P>, sticky {/Symbol D} = 0.05 {/Symbol s}", \
     "" using 1:6:7 axes x1y2 with yerrorlines pt 6 dt 2 lw 2 lc rgb "#0077bb" title "avalanche, repulsive (mean of seeds, standard error)", \
     "" using 1:5 axes x1y2 with linespoints pt 4 dt 2 lw 2 lc rgb "#cc3311" title "avalanche, sticky"
