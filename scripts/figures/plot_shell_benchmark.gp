# A shell benchmark of Appendix B: the analytic curve (lib/elasticity's analytic_curve, e.g.
# from `shellpack bench-mechanics`) with computed tables overlaid, one panel per compared column.
# gnuplot -e "analytic='sphere_analytic.csv'; computed='svk.csv springs-kot.csv'; out='sphere.png'" \
#         scripts/figures/plot_shell_benchmark.gp
# The analytic table names its case (# case=), the columns to compare (# compare=, one panel
# each) and extra analytic columns for the first panel (# references=); its first column is x.
# Every computed table must have the x column and the compared columns under the same names
# (other columns are ignored); it is titled by its "# model=" line, else its file name.
# `computed` may be empty (the analytic curve alone).
if (!exists("computed")) computed = ""
meta(file, key) = system(sprintf("sed -n 's/^# %s=//p' '%s' | head -n 1", key, file))
header(file) = system(sprintf("grep -v '^#' '%s' | head -n 1 | tr ',' ' '", file))
case = meta(analytic, "case")
compare = meta(analytic, "compare")
references = meta(analytic, "references")
xcol = word(header(analytic), 1)
title_of(f) = (strlen(meta(f, "model")) > 0 ? meta(f, "model") : f)

label(c) = (c eq "dP_E" ? "{/Symbol D}P / E" : \
            c eq "eps_r" ? "radial strain {/Symbol e}_r" : \
            c eq "nu_input" ? "material {/Symbol n}" : \
            c eq "nu_measured" ? "measured {/Symbol n} = -{/Symbol e}_2/{/Symbol e}_1" : \
            c eq "r_R0" ? "r / R_0" : \
            c eq "w_t" ? "deflection w / t" : \
            c eq "P_star" ? "P^* = (P/E)(R_0/t)^4" : \
            c eq "w_max_t" ? "w_{max} / t" : \
            c eq "X" ? "compression X = 1 - {/Symbol h}/R_i" : \
            c eq "F_hat" ? "F / (E t R_0)" : \
            c eq "P_P0" ? "P / P_0" : \
            c eq "gamma" ? "F\\303\\266ppl-von K\\303\\241rm\\303\\241n number {/Symbol g}" : \
            c eq "p_pc" ? "buckling pressure / p_c" : c)

npanels = words(compare)
set terminal pngcairo size (npanels > 1 ? 1200 : 700),500 enhanced font "Sans,11"
set output out
set datafile separator ","
set datafile commentschars "#"
set grid
set key top left
if (case eq "plate-large") { set logscale xy }
if (case eq "buckling") { set logscale x; set yrange [0:1.2]; set xrange [700:70000]; set key bottom left; set linetype 8 lc rgb '#8c564b' }
if (case eq "plate-point" || case eq "plate-uniform") { set yrange [*:*] reverse; set key bottom right }
set multiplot layout 1,npanels title sprintf("%s: analytic (line) and computed (points)", case) noenhanced
do for [k = 1:npanels] {
  y = word(compare, k)
  set xlabel label(xcol)
  set ylabel label(y)
  if (case eq "plates-contact" && y eq "F_hat") { set logscale xy; set key top left } else { if (case eq "plates-contact") { unset logscale } }
  refs = (k == 1 ? references : "")
  # Built as a string: an empty "for [i = 1:0]" clause still makes gnuplot look for a file.
  cmd = sprintf("plot '%s' using (column('%s')):(column('%s')) with lines lw 2 lc rgb 'black' title 'analytic'", analytic, xcol, y)
  do for [r = 1:words(refs)] {
    cmd = cmd . sprintf(", '%s' using (column('%s')):(column('%s')) with lines dt 2 lw 1.5 title '%s' noenhanced", analytic, xcol, word(refs, r), word(refs, r))
  }
  do for [f = 1:words(computed)] {
    cmd = cmd . sprintf(", '%s' using (column('%s')):(column('%s')) with linespoints pt 7 ps 0.6 title '%s' noenhanced", word(computed, f), xcol, y, title_of(word(computed, f)))
  }
  eval cmd
}
unset multiplot
