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
  for opt in --model --x --y --loss --fix --free --plot --plot-kc --bootstrap --seed --threads --list-models; do
    grep -q -- "$opt" help.txt || fail "--help lacks $opt"
  done
  "$kcfit" --version | grep -Eq "^kcfit [0-9]" || fail "--version"
}
case_list_models() {
  "$kcfit" --list-models >models.txt || fail "--list-models"
  for m in kc-classical kc-percolation kc-fixed power hydraulic-radius tortuosity threshold sigmoid; do
    grep -q "^$m: " models.txt || fail "--list-models lacks $m"
  done
  grep -q "gamma + 0.76" models.txt || fail "Eq. 5.8 formula missing"
  grep -q "fixed at -0.38 unless --free e" models.txt || fail "tortuosity exponent note missing"
}
case_fit_csv() {
  "$kcfit" "$flow" --model kc-percolation --x porosity --y permeability --loss log >fit.csv 2>err.txt || fail "fit"
  grep -q "^kcfit: kc-percolation (log loss), 120 points: C = .*gamma = .*R^2 = 0.99" err.txt || fail "summary: $(cat err.txt)"
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
  diff <(grep -v '^# \(provenance\|input=\)' fit.csv) <(grep -v '^# \(provenance\|input=\)' fit2.csv) || fail "stdin differs"
}
case_fix_and_free() {
  "$kcfit" "$flow" --model power --fix phi_c=0.141 --loss linear -q >fit.csv || fail "power --fix"
  grep -q "^phi_c,0.141,0,1," fit.csv || fail "phi_c not fixed: $(cat fit.csv)"
  "$kcfit" "$flow" --model kc-percolation --fix phi_c=0.141,gamma=1 --loss log -q >fit.csv || fail "two fixes"
  grep -q "^gamma,1,0,1," fit.csv || fail "gamma not fixed"
  # --fix takes one value: the input may follow it; repeated --fix accumulate.
  "$kcfit" --fix phi_c=0.141 "$flow" --fix gamma=1 --model kc-percolation --loss log -q >fit2.csv || fail "--fix before input"
  cmp -s <(grep -v '^# provenance' fit.csv) <(grep -v '^# provenance' fit2.csv) || fail "--fix order changes the fit"
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
  cmp -s <(grep -v '^# provenance' a.csv) <(grep -v '^# provenance' b.csv) || fail "threads change the bootstrap"
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
  ! ls .*.tmp* 2>/dev/null | grep -q . || fail "temporary files left: $(ls -a)"
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
  expect_error 2 "--fix: expected name=value" "$kcfit" in.csv --model power --fix phi_c=abc -o out.csv
  expect_error 2 "--fix: expected name=value" "$kcfit" in.csv --model power --fix =0.1 -o out.csv
  expect_error 2 "--fix: model power has no parameter 'gamma'" "$kcfit" in.csv --model power --fix gamma=1 -o out.csv
  expect_error 2 "--loss: unknown loss" "$kcfit" in.csv --model power --loss cubic -o out.csv
  expect_error 2 "--loss ml is for 0/1 outcomes" "$kcfit" in.csv --model power --loss ml -o out.csv
  printf 'porosity,percolates\n0.1,0\n0.2,0.5\n0.3,1\n' >half.csv
  expect_error 2 "half.csv:3: --loss ml needs percolates to be 0 or 1" "$kcfit" half.csv --model sigmoid --loss ml -o out.csv
  expect_error 2 "no-such.csv" "$kcfit" no-such.csv --model power -o out.csv
  expect_error 2 "input CSV file is required" "$kcfit" --model power
  expect_error 2 "--plot-kc needs --plot" "$kcfit" in.csv --model power --plot-kc -o out.csv
}
case_fit_failures() {
  printf 'porosity,permeability\n0.2,1\n0.3,2\n' >two.csv
  expect_error 1 "2 points for 3 free parameters" "$kcfit" two.csv --model kc-percolation -o out.csv --plot out.png
  printf 'porosity,permeability\n1.2,1\n1.3,2\n1.5,3\n1.7,4\n' >outside.csv
  expect_error 1 "no point lies in the domain of model kc-percolation" "$kcfit" outside.csv --model kc-percolation -o out.csv
  expect_error 1 "no point lies in the domain" "$kcfit" "$flow" --model power --fix phi_c=0.9 -o out.csv
  expect_error 1 "did not converge" "$kcfit" "$flow" --model kc-percolation --loss log --max-iter 1 -o out.csv
  printf 'porosity,percolates\n0.1,0\n0.11,0\n0.15,1\n0.16,1\n' >sep.csv
  expect_error 1 "perfectly separated" "$kcfit" sep.csv --model sigmoid -o out.csv --plot out.png
}

run_cases "$@"
