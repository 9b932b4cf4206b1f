#!/usr/bin/env bash
# kcfit as a user runs it. `kcfit_cli.sh --list` prints the cases; `kcfit_cli.sh CASE` runs one
# (ctest registers each). Needs CMP_BIN (the built programs) and CMP_SRC (the sources, for
# the sample tables of data/kcfit).
set -uo pipefail
bin=${CMP_BIN:-build/bin}
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
kcfit="$bin/kcfit"
if [ "${1:-}" != --list ]; then
  case $bin in /*) ;; *) kcfit="$PWD/$kcfit" ;; esac
  case $src in /*) ;; *) src="$PWD/$src" ;; esac
fi
flow="$src/data/kcfit/flow_synthetic.csv"
thr="$src/data/kcfit/threshold_synthetic.csv"
perc="$src/data/kcfit/percolation_synthetic.csv"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
cli_tool=kcfit
enter_scratch_dir
# value FILE PARAMETER: the fitted value of a parameter in kcfit's output.
value() { awk -F, -v p="$2" '!/^#/ && $1 == p { print $2 }' "$1"; }
near() { awk -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= tol) }'; }

case_help() {
  "$kcfit" --help >help.txt || fail "--help"
  for opt in --model --x --y --sigma --loss --where --group-by --fix --free --plot --xlabel --ylabel --plot-kc \
    --bootstrap --seed --threads --list-models; do
    grep -q -- "$opt" help.txt || fail "--help lacks $opt"
  done
  "$kcfit" --version | grep -Eq "^kcfit [0-9]" || fail "--version"
}
case_list_models() {
  "$kcfit" --list-models >models.txt || fail "--list-models"
  for m in kc-classical kc-percolation kc-fixed power hydraulic-radius tortuosity threshold sigmoid; do
    grep -q "^model,$m," models.txt || fail "--list-models lacks $m"
  done
  grep -q "gamma + 0.76" models.txt || fail "Eq. 5.8 formula missing"
  grep -q "fixed at -0.38 unless --free e" models.txt || fail "tortuosity exponent note missing"
  # The default columns are those percolate and lbflow write (the first present wins).
  grep -q '^model,sigmoid,.*,"porosity","percolates probability"$' models.txt || fail "sigmoid columns"
  grep -q '^model,threshold,.*,"delta","phi_c"$' models.txt || fail "threshold columns"
  grep -q '^model,kc-percolation,.*,"porosity","permeability_delta2 permeability_d02 permeability"$' models.txt ||
    fail "permeability columns"
  grep -q '^model,hydraulic-radius,.*,"porosity","rh_sites_d0 hydraulic_radius"$' models.txt || fail "R_h columns"
}
case_fit_csv() {
  "$kcfit" "$flow" --model kc-percolation --x porosity --y permeability --loss log >fit.csv 2>err.txt || fail "fit"
  grep -q "^kcfit: kc-percolation (log loss), 120 points: C = .*gamma = .*R^2 (ln y) = 0.99.*chi^2/dof = " err.txt || fail "summary: $(cat err.txt)"
  grep -q "^parameter,value,stderr,fixed,cov_C,cov_phi_c,cov_gamma$" fit.csv || fail "header: $(cat fit.csv)"
  grep -q "^# input.synthetic=1$" fit.csv || fail "input provenance not carried"
  grep -q "^# provenance=kcfit .*--model kc-percolation" fit.csv || fail "own provenance"
  for k in model=kc-percolation loss=log n=120 dropped=0 "status=converged" r2= aic= rss= at_bound=0; do
    grep -q "^# $k" fit.csv || fail "meta $k missing"
  done
  near "$(value fit.csv phi_c)" 0.146 0.006 || fail "phi_c = $(value fit.csv phi_c)"
  near "$(value fit.csv gamma)" 0.83 0.15 || fail "gamma = $(value fit.csv gamma)"
  # stdin and -o give the same table.
  "$kcfit" - --model kc-percolation --loss log -q -o fit2.csv <"$flow" || fail "stdin"
  same_lines "stdin differs" '^# \(provenance\|input=\)' fit.csv fit2.csv
}
case_fix_and_free() {
  "$kcfit" "$flow" --model power --fix phi_c=0.141 --loss linear -q >fit.csv || fail "power --fix"
  grep -q "^phi_c,0.141,0,1," fit.csv || fail "phi_c not fixed: $(cat fit.csv)"
  "$kcfit" "$flow" --model kc-percolation --fix phi_c=0.141,gamma=1 --loss log -q >fit.csv || fail "two fixes"
  grep -q "^gamma,1,0,1," fit.csv || fail "gamma not fixed"
  # --fix takes one value: the input may follow it; repeated --fix accumulate.
  "$kcfit" --fix phi_c=0.141 "$flow" --fix gamma=1 --model kc-percolation --loss log -q >fit2.csv || fail "--fix before input"
  same_lines "--fix order changes the fit" '^# provenance' fit.csv fit2.csv
  grep -q "^gamma,1,0,1," fit.csv || fail "gamma not fixed"
  "$kcfit" "$flow" --model tortuosity --y tortuosity -q >tau.csv || fail "tortuosity"
  grep -q "^e,-0.38,0,1," tau.csv || fail "exponent not fixed at -0.38"
  near "$(value tau.csv phi_c)" 0.124 0.002 || fail "tortuosity phi_c $(value tau.csv phi_c)"
  "$kcfit" "$flow" --model tortuosity --free e -q >tau.csv || fail "--free e"
  grep -q "^e,[-0-9.e]*,[0-9.e-]*,0," tau.csv || fail "exponent not freed"
  "$kcfit" "$flow" --model hydraulic-radius -q >rh.csv || fail "hydraulic-radius"
  near "$(value rh.csv C)" 1.0 0.01 || fail "R_h C $(value rh.csv C)"
}
case_threshold() {
  "$kcfit" "$thr" --model threshold --x delta --y phi_c -q >fit.csv || fail "threshold"
  near "$(value fit.csv phi_c_star)" 0.035 0.001 || fail "phi_c_star $(value fit.csv phi_c_star)"
  near "$(value fit.csv A)" 3.67 0.02 || fail "A $(value fit.csv A)"
  near "$(value fit.csv beta)" 1.1 0.005 || fail "beta $(value fit.csv beta)"
}
case_sigmoid() {
  "$kcfit" "$perc" --model sigmoid --x porosity --y percolates -q >ml.csv || fail "sigmoid"
  grep -q "^# loss=ml$" ml.csv || fail "0/1 data should default to maximum likelihood"
  grep -q "^# log_likelihood=" ml.csv || fail "log-likelihood"
  near "$(value ml.csv phi_c)" 0.141 0.006 || fail "phi_c $(value ml.csv phi_c)"
  "$kcfit" "$perc" --model sigmoid --loss linear -q >ls.csv || fail "sigmoid linear"
  grep -q "^# loss=linear$" ls.csv || fail "--loss linear ignored"
}
case_bootstrap() {
  "$kcfit" "$flow" --model tortuosity --y tortuosity --bootstrap 300 --seed 5 --threads 1 -q >a.csv || fail "a"
  "$kcfit" "$flow" --model tortuosity --y tortuosity --bootstrap 300 --seed 5 --threads 2 -q >b.csv || fail "b"
  "$kcfit" "$flow" --model tortuosity --y tortuosity --bootstrap 300 --seed 6 -q >c.csv || fail "c"
  grep -q "bootstrap_mean,bootstrap_stderr,bootstrap_q025,bootstrap_q975$" a.csv || fail "bootstrap columns"
  grep -q "^# bootstrap=300$" a.csv || fail "bootstrap meta"
  same_lines "threads change the bootstrap" '^# provenance' a.csv b.csv
  cmp -s <(grep -v '^#' a.csv) <(grep -v '^#' c.csv) && fail "seed ignored"
  true
}
case_plot() {
  "$kcfit" "$flow" --model kc-percolation --loss log --plot kc.png --plot-kc -q >fit.csv || fail "plot"
  [ "$(head -c 4 kc.png | od -An -c | tr -d ' ')" = "211PNG" ] || fail "kc.png is not a PNG"
  [ "$(stat -c %s kc.png)" -gt 10000 ] || fail "kc.png too small"
  grep -q "^# kc_classical_C=" fit.csv || fail "classical KC not recorded"
  "$kcfit" "$thr" --model threshold --plot thr.png -q >/dev/null || fail "threshold plot"
  [ -s thr.png ] || fail "thr.png"
  ! ls .*.tmp* 2>/dev/null | grep >/dev/null . || fail "temporary files left: $(ls -a)"
}
case_bad_input() {
  printf 'porosity,permeability\n0.2,1\n0.3,2\n' >in.csv
  expect_error 2 "in.csv:1: .*permeabilty" "$kcfit" in.csv --model power --y permeabilty -o out.csv
  : >empty.csv
  expect_error 2 "empty.csv.*empty" "$kcfit" empty.csv --model power -o out.csv
  printf 'porosity,permeability\n' >header.csv
  expect_error 2 "header.csv:1: no data rows" "$kcfit" header.csv --model power -o out.csv
  printf '# a=1\nporosity,permeability\n0.2,1\n0.3,abc\n0.4,3\n' >nan.csv
  expect_error 2 "nan.csv:4: .*abc" "$kcfit" nan.csv --model power -o out.csv
  expect_error 2 "unknown model 'kozeny'" "$kcfit" in.csv --model kozeny -o out.csv
  expect_error 2 "--fix: expected name=value" "$kcfit" in.csv --model power --fix phi_c -o out.csv
  expect_error 2 "--fix: 'abc' is not a finite number (in phi_c=abc)$" "$kcfit" in.csv --model power --fix phi_c=abc -o out.csv
  expect_error 2 "--fix: expected name=value" "$kcfit" in.csv --model power --fix =0.1 -o out.csv
  expect_error 2 "--fix: model power has no parameter 'gamma'" "$kcfit" in.csv --model power --fix gamma=1 -o out.csv
  expect_error 2 "--loss: unknown loss" "$kcfit" in.csv --model power --loss cubic -o out.csv
  expect_error 2 "--loss: ml is for 0/1 outcomes" "$kcfit" in.csv --model power --loss ml -o out.csv
  printf 'porosity,percolates\n0.1,0\n0.2,0.5\n0.3,1\n' >half.csv
  expect_error 2 "half.csv:3: percolates holds 0/1 outcomes (model sigmoid), got 0.5" "$kcfit" half.csv --model sigmoid --loss ml -o out.csv
  expect_error 2 "no-such.csv" "$kcfit" no-such.csv --model power -o out.csv
  expect_error 2 "input CSV file is required" "$kcfit" --model power
  expect_error 2 "--plot-kc: needs --plot$" "$kcfit" in.csv --model power --plot-kc -o out.csv
}
case_fit_failures() {
  printf 'porosity,permeability\n0.2,1\n0.3,2\n' >two.csv
  expect_error 2 "two.csv: 2 points for 3 free parameters" "$kcfit" two.csv --model kc-percolation -o out.csv --plot out.png
  printf 'porosity,permeability\n1.2,1\n1.3,2\n1.5,3\n1.7,4\n' >outside.csv
  expect_error 1 "no point lies in the domain of model kc-percolation" "$kcfit" outside.csv --model kc-percolation -o out.csv
  expect_error 1 "no point lies in the domain" "$kcfit" "$flow" --model power --fix phi_c=0.9 -o out.csv
  expect_error 1 "did not converge" "$kcfit" "$flow" --model kc-percolation --loss log --max-iter 1 -o out.csv
  printf 'porosity,percolates\n0.1,0\n0.11,0\n0.15,1\n0.16,1\n' >sep.csv
  expect_error 1 "perfectly separated" "$kcfit" sep.csv --model sigmoid -o out.csv --plot out.png
}

# percolate's per-run table (the column contract shared with percolate): PACKINGS packings
# per delta at 21 scales each, percolating (a Bernoulli draw, deterministic LCG) with
# P = sigmoid((porosity - phi_c(delta)) / 0.012), phi_c(delta) = 0.035 + 3.67 delta^1.1.
percolate_runs() {
  awk -v packings="${1:-30}" -v seed="${2:-1}" 'BEGIN {
    print "# tool=percolate (synthetic, for the kcfit tests)"
    print "file,particles,delta,scale,porosity,porosity_voxels,percolates"
    s = seed; split("0.03 0.04 0.05 0.06 0.07", d, " ")
    for (k = 1; k <= 5; k++) {
      pc = 0.035 + 3.67 * exp(1.1 * log(d[k]))
      for (j = 0; j < packings; j++) for (i = 0; i <= 20; i++) {
        phi = 0.36 - 0.3 * i / 20 + 0.004 * ((j * 7) % 5)
        s = (s * 1103515245 + 12345) % 2147483648; u = s / 2147483648
        p = 1 / (1 + exp(-(phi - pc) / 0.012))
        printf "jam_%d.xyz,50,%s,%.2f,%.6f,%.6f,%d\n", j, d[k], 1 + 0.02 * i, phi, phi + 0.01, (u < p)
      }
    }
  }'
}
# percolate sweep's table (the contract): per delta, bins of porosity with the fraction
# percolating and its binomial error, zero where every packing percolates or none.
percolate_sweep_table() {
  awk 'BEGIN {
    print "# tool=percolate sweep (synthetic, for the kcfit tests)"
    print "particles,delta,scale,porosity,porosity_low,porosity_high,packings,percolating,probability,probability_error"
    split("0.03 0.04 0.05", d, " ")
    for (k = 1; k <= 3; k++) {
      pc = 0.035 + 3.67 * exp(1.1 * log(d[k]))
      for (i = 0; i < 12; i++) {
        phi = 0.06 + 0.025 * i; n = 40
        m = int(n / (1 + exp(-(phi - pc) / 0.012)) + 0.5); p = m / n
        printf "50,%s,1,%.4f,%.4f,%.4f,%d,%d,%.6f,%.6f\n", d[k], phi, phi - 0.0125, phi + 0.0125, n, m, p, sqrt(p * (1 - p) / n)
      }
    }
  }'
}

case_percolate_chain() {
  # percolate -> kcfit -> kcfit with the default columns and no awk in between.
  percolate_runs 30 >perc.csv
  "$kcfit" perc.csv --model sigmoid --group-by delta -o fits.csv 2>err.txt || fail "sigmoid --group-by: $(cat err.txt)"
  grep -q "^# loss=ml$" fits.csv || fail "0/1 percolates should give maximum likelihood"
  grep -q "^# group_by=delta$" fits.csv || fail "group_by meta"
  grep -q "^delta,n,dropped,phi_c,phi_c_error,width,width_error,log_likelihood,null_log_likelihood,deviance,pseudo_r2,aic,at_bound$" fits.csv ||
    fail "grouped header: $(grep -v '^#' fits.csv | head -1)"
  [ "$(grep -vc '^#' fits.csv)" -eq 6 ] || fail "one row per delta: $(cat fits.csv)"
  grep -q "^0.04,630,0,0.14" fits.csv || fail "phi_c(0.04): $(grep '^0.04' fits.csv)"
  [ "$(grep -c '^kcfit: delta=0.0[3-7]: sigmoid (ml loss), 630 points' err.txt)" -eq 5 ] || fail "summaries: $(cat err.txt)"
  lacks "warned although grouped" "warning" err.txt
  "$kcfit" fits.csv --model threshold -o thr.csv 2>err.txt || fail "threshold on kcfit's output: $(cat err.txt)"
  grep -q "^# sigma=phi_c_error$" thr.csv || fail "phi_c_error not used as sigma"
  near "$(value thr.csv phi_c_star)" 0.035 0.03 || fail "phi_c_star $(value thr.csv phi_c_star)"
  # The same data through --where: one fit, the same numbers as the group's row.
  "$kcfit" perc.csv --model sigmoid --where delta=0.040 -q -o one.csv || fail "--where"
  grep -q "^# n=630$" one.csv || fail "--where delta=0.040 kept $(grep '^# n=' one.csv)"
  [ "$(value one.csv phi_c)" = "$(grep '^0.04,' fits.csv | cut -d, -f4)" ] || fail "--where and --group-by differ"
  "$kcfit" perc.csv --model sigmoid --where "delta>0.035" --where "delta<0.065" --group-by delta -q -o three.csv || fail "<, >"
  [ "$(grep -vc '^#' three.csv)" -eq 4 ] || fail "--where delta>0.035 delta<0.065: $(cat three.csv)"
  # Two groupings at once: the group columns first, in the order given.
  "$kcfit" perc.csv --model sigmoid --group-by delta,particles -q -o two.csv || fail "two group columns"
  grep -q "^delta,particles,n," two.csv || fail "two group columns header"
}
case_percolate_sweep() {
  # percolate sweep's binned table: probability, weighted by probability_error (zeros replaced).
  percolate_sweep_table >sweep.csv
  "$kcfit" sweep.csv --model sigmoid --group-by delta -o fits.csv 2>err.txt || fail "sweep: $(cat err.txt)"
  grep -q "^# y=probability$" fits.csv || fail "probability column not the default"
  grep -q "^# loss=linear$" fits.csv || fail "binned probabilities: least squares"
  grep -q "^# sigma=probability_error$" fits.csv || fail "not weighted by probability_error"
  grep -q "^# sigma_zero=[1-9][0-9]* zero errors replaced" fits.csv || fail "zero errors not reported: $(grep '^#' fits.csv)"
  grep -q "^delta,n,dropped,phi_c,phi_c_error,width,width_error,r2,chi2_dof,aic,at_bound$" fits.csv || fail "header"
  grep -q "^0.04,12,0,0.14" fits.csv || fail "phi_c(0.04) $(grep '^0.04' fits.csv)"
  grep -q "weighted" err.txt || fail "summary does not say weighted: $(cat err.txt)"
  "$kcfit" sweep.csv --model sigmoid --where delta=0.04 --sigma none -q -o plain.csv || fail "--sigma none"
  lacks "--sigma none still weighted" "^# sigma=" plain.csv
  expect_error 2 "sweep.csv:2: no column 'nope' (--sigma)" "$kcfit" sweep.csv --model sigmoid --sigma nope -o out.csv
  sed 's/,0.000000$/,-0.1/' sweep.csv >neg.csv
  expect_error 2 "neg.csv:[0-9]*: probability_error .* is negative" "$kcfit" neg.csv --model sigmoid -o out.csv
}
case_several_files() {
  percolate_runs 10 1 >all.csv
  grep -v ',0.0[67],' all.csv >a.csv
  { grep '^file' all.csv; grep ',0.0[67],' all.csv; } >b.csv
  "$kcfit" all.csv --model sigmoid --group-by delta -q -o one.csv || fail "one file"
  "$kcfit" a.csv b.csv --model sigmoid --group-by delta -q -o two.csv || fail "two files"
  same_lines "files differ from one" '^# \(provenance\|input\)' one.csv two.csv
  grep -q "^# input=a.csv b.csv$" two.csv || fail "inputs not recorded"
  cat b.csv - <<<'x.xyz,50,0.06,1.1,abc,0.2,1' >bad.csv
  expect_error 2 "bad.csv:$(wc -l <bad.csv): column 'porosity': expected a number, got 'abc'" \
    "$kcfit" a.csv bad.csv --model sigmoid -o out.csv
  cut -d, -f2- b.csv >c.csv
  expect_error 2 "c.csv:1: columns differ from those of a.csv" "$kcfit" a.csv c.csv --model sigmoid -o out.csv
  # Several deltas fitted as one set: said on stderr.
  "$kcfit" all.csv --model sigmoid -o one.csv 2>err.txt || fail "ungrouped"
  grep -q "^kcfit: warning: the data hold 5 values of delta (0.03 ... 0.07), fitted as one set; fit each with --group-by delta" err.txt ||
    fail "no warning: $(cat err.txt)"
  lacks "warned about the scale, which is what moves the porosity" "values of scale" err.txt
  "$kcfit" all.csv --model sigmoid --where "delta<1" -o one.csv 2>err.txt || fail "ungrouped --where"
  lacks "warned with --where" warning err.txt
  expect_error 2 "all.csv:2: no row satisfies --where delta=0.5" "$kcfit" all.csv --model sigmoid --where delta=0.5 -o out.csv
  expect_error 2 "no column 'dleta' (--group-by)" "$kcfit" all.csv --model sigmoid --group-by dleta -o out.csv
  expect_error 2 "--where: expected column=value" "$kcfit" all.csv --model sigmoid --where delta -o out.csv
  expect_error 2 "--where: delta=x: the value 'x' is not a number" "$kcfit" all.csv --model sigmoid --where delta=x -o out.csv
  # A group whose fit fails is named.
  printf 'delta,porosity,percolates\n0.04,0.1,0\n0.04,0.2,1\n0.04,0.15,1\n0.04,0.16,0\n0.04,0.12,0\n0.05,0.1,0\n0.05,0.11,0\n0.05,0.2,1\n0.05,0.21,1\n' >sep.csv
  expect_error 1 "delta=0.05: .*perfectly separated" "$kcfit" sep.csv --model sigmoid --group-by delta -o out.csv
}
case_goodness() {
  "$kcfit" "$perc" --model sigmoid -q >ml.csv || fail "ml"
  for k in log_likelihood null_log_likelihood deviance pseudo_r2 aic; do grep -q "^# $k=" ml.csv || fail "ml lacks $k"; done
  lacks "an R^2 quoted for a maximum-likelihood fit" "^# r2=" ml.csv
  "$kcfit" "$flow" --model kc-percolation --loss log -q >ls.csv || fail "ls"
  for k in r2 chi2_dof aic; do grep -q "^# $k=" ls.csv || fail "least squares lacks $k"; done
  lacks "pseudo R^2 for least squares" "^# pseudo_r2=" ls.csv
  "$kcfit" "$perc" --model sigmoid 2>&1 >/dev/null | grep >/dev/null "McFadden pseudo-R^2 = 0\.[0-9]" || fail "summary lacks pseudo-R^2"
}
case_bad_options_at_once() {
  printf 'porosity,permeability\n0.2,1\n0.3,2\n' >in.csv
  "$kcfit" in.csv --model kozeny --fix phi_c=abc --where delta --plot x.txt --loss cubic -o out.csv 2>err.txt
  [ $? -eq 2 ] || fail "exit status"
  for p in "--model: unknown model 'kozeny'" "--fix: 'abc' is not a finite number (in phi_c=abc)" "--where: expected column=value" \
    "--plot: the figure's format comes from its extension (.png, .svg or .pdf), got 'x.txt'" "--loss: unknown loss 'cubic'"; do
    grep -q -- "^kcfit: $p" err.txt || fail "lacks '$p': $(cat err.txt)"
  done
  grep -qx "kcfit: run 'kcfit --help' for the options" err.txt || fail "no --help hint: $(cat err.txt)"
  [ "$(wc -l <err.txt)" -eq 6 ] || fail "not one line per problem: $(cat err.txt)"
  ! ls out.* x.txt .x.txt* 2>/dev/null | grep >/dev/null . || fail "left a file"
  expect_error 2 "--plot: the figure's format" "$kcfit" in.csv --model power --plot fit.txt -o out.csv
}
case_bad_numbers_at_once() {
  # Number options are converted after parsing: every bad one is reported with the others,
  # under its flag, then the --help hint; nothing written.
  printf 'porosity,permeability\n0.2,1\n0.3,2\n' >in.csv
  "$kcfit" in.csv --model kozeny --bootstrap -3 --max-iter abc --seed x --threads -1 --sigma e --loss log \
    -o out.csv 2>err.txt
  [ $? -eq 2 ] || fail "exit status"
  for p in "--bootstrap: must lie in \[0, 10000000\], got '-3'" "--max-iter: 'abc' is not an integer" \
    "--seed: 'x' is not a non-negative integer" "--threads: must lie in \[0, [0-9]*\] (64 per core of this machine's [0-9]*), got '-1'" \
    "--model: unknown model 'kozeny' (known: .*)" "--sigma: weights the linear loss only, not --loss log" \
    "run 'kcfit --help' for the options"; do
    grep -qx -- "kcfit: $p" err.txt || fail "lacks '$p': $(cat err.txt)"
  done
  [ "$(wc -l <err.txt)" -eq 7 ] || fail "not one line per problem: $(cat err.txt)"
  expect_error 2 "--max-iter: must lie in \[1, 1000000\], got '0'$" "$kcfit" in.csv --model power --max-iter 0 -o out.csv
  expect_error 2 "--model: required" "$kcfit" in.csv -o out.csv
  ! ls -a | grep >/dev/null '^out\.\|\.tmp' || fail "left a file: $(ls -a)"
}
case_plot_formats() {
  "$kcfit" "$perc" --model sigmoid --plot p.svg -q >/dev/null || fail "svg"
  head -c 200 p.svg | grep >/dev/null "<svg\|<?xml" || fail "p.svg is not SVG"
  grep -q "porosity" p.svg || fail "axis label missing in the SVG"
  grep -q "McFadden" p.svg || fail "the ML figure does not quote McFadden's pseudo-R^2"
  grep -q "R<tspan[^>]*>2" p.svg && ! grep -q "pseudo" p.svg && fail "an R^2"
  "$kcfit" "$perc" --model sigmoid --plot p.pdf -q >/dev/null || fail "pdf"
  [ "$(head -c 4 p.pdf)" = "%PDF" ] || fail "p.pdf is not a PDF"
  "$kcfit" "$perc" --model sigmoid --plot P.PNG -q >/dev/null || fail "PNG"
  [ "$(head -c 4 P.PNG | od -An -c | tr -d ' ')" = "211PNG" ] || fail "P.PNG"
  percolate_runs 10 >perc.csv
  "$kcfit" perc.csv --model sigmoid --group-by delta --plot groups.svg -q -o fits.csv || fail "grouped plot"
  [ "$(grep -c 'path stroke=' groups.svg)" -gt 5 ] || fail "grouped plot draws little"
  ! ls -a | grep >/dev/null '\.tmp' || fail "temporary left: $(ls -a)"
}
# A stand-in gnuplot on PATH: answers the terminal probe, then runs $FAKE_GNUPLOT.
fake_gnuplot() {
  mkdir -p fakebin
  printf '#!/bin/sh\ncase "$1" in -e) exit 0 ;; esac\ntouch "%s/gnuplot.started"\n%s\n' "$PWD" "$1" >fakebin/gnuplot
  chmod +x fakebin/gnuplot
}
case_plot_interrupted() {
  # Ctrl-C (SIGINT to the foreground process group) while gnuplot runs: kcfit stops at once,
  # by the signal, with no temporary folder or file and no "gnuplot failed". The stand-in
  # gnuplot ignores SIGINT and finishes only when the test releases it, so a kcfit that waited
  # for it would never exit (ctest's timeout fails it): the test waits for events (files the
  # stand-in writes), never for a time, and a loaded machine only makes it slower. (The
  # stand-in also ends when this test's folder is removed, so a failing test leaves no loop.)
  fake_gnuplot "trap '' INT; until [ -e '$PWD/release' ] || [ ! -d '$PWD' ]; do sleep 0.01; done; touch '$PWD/gnuplot.finished'; cat >/dev/null; exit 0"
  set -m
  PATH="$PWD/fakebin:$PATH" "$kcfit" "$perc" --model sigmoid --plot fig.png -o out.csv 2>err.txt &
  local pid=$!
  until [ -e gnuplot.started ]; do
    kill -0 "$pid" 2>/dev/null || [ -e gnuplot.started ] || fail "kcfit ended before gnuplot started: $(cat err.txt)"
    sleep 0.01
  done
  ! ls -a | grep >/dev/null '\.tmp' || fail "a temporary exists while gnuplot runs: $(ls -a)"
  kill -INT -- -"$pid"
  wait "$pid"; local status=$?
  set +m
  local waited=no
  [ -e gnuplot.finished ] && waited=yes
  touch release
  until [ -e gnuplot.finished ]; do sleep 0.01; done
  [ "$waited" = no ] || fail "kcfit waited for gnuplot after Ctrl-C"
  [ "$status" -eq 130 ] || fail "exit status $status after SIGINT (expected 130); stderr: $(cat err.txt)"
  lacks "Ctrl-C reported as a gnuplot failure" "gnuplot failed" err.txt
  ! ls -a | grep >/dev/null '\.tmp\|fig.png\|out.csv' || fail "left behind: $(ls -a)"
}
case_plot_gnuplot_killed() {
  fake_gnuplot 'kill -KILL $$'
  PATH="$PWD/fakebin:$PATH" expect_error 1 "gnuplot was killed by signal 9" "$kcfit" "$perc" --model sigmoid --plot out.png -o out.csv
  fake_gnuplot 'echo "line 3: unknown terminal" >&2; exit 1'
  PATH="$PWD/fakebin:$PATH" expect_error 1 "gnuplot failed (exit status 1): line 3: unknown terminal" \
    "$kcfit" "$perc" --model sigmoid --plot out.png -o out.csv
}
case_same_seed_same_bytes() {
  # Grouped bootstrap fits and their figure: the same bytes for the same seed on 1 and 2
  # threads (provenance aside), no wall-clock time anywhere.
  percolate_runs 10 >perc.csv
  for t in 1 2; do
    "$kcfit" perc.csv --model sigmoid --group-by delta --bootstrap 200 --seed 3 --threads $t -q -o g$t.csv --plot g$t.png ||
      fail "threads $t"
    "$kcfit" "$flow" --model kc-percolation --loss log --bootstrap 200 --seed 3 --threads $t -q -o f$t.csv || fail "flow $t"
  done
  same_lines "grouped bootstrap differs by threads" '^# provenance' g1.csv g2.csv
  same_lines "bootstrap differs by threads" '^# provenance' f1.csv f2.csv
  [ -s g1.png ] && cmp -s g1.png g2.png || fail "figures differ (or are missing)"
  grep -q "phi_c_bootstrap_stderr,phi_c_bootstrap_q025,phi_c_bootstrap_q975" g1.csv || fail "grouped bootstrap columns"
  lacks -i "wall-clock time in the output" "seconds\|time\|elapsed" g1.csv f1.csv
}

run_cases "$@"
