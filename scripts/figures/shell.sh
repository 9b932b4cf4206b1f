#!/usr/bin/env bash
# Figs B.4-B.10 of the thesis: each `shellpack bench-mechanics` case at the thesis's sizes
# (--full), split into one table per model, drawn over the analytic curve by
# scripts/figures/plot_shell_benchmark.gp. Usage: scripts/figures/shell.sh BUILD_DIR OUT_DIR [CASE...]
# About three minutes on 2 cores (buckling: one more minute, one core).
set -euo pipefail
build=${1:-build}
out=${2:-results/figures}
shift 2 || true
cases=${*:-sphere poisson plate-point plate-uniform plate-large plates-contact buckling}
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
shellpack="$build/bin/shellpack"
mkdir -p "$out/shell"
for c in $cases; do
  dir="$out/shell/$c"
  mkdir -p "$dir"
  echo "shell-figures: $c" >&2
  "$shellpack" bench-mechanics "$c" --full -q -o "$dir/computed.csv"
  "$shellpack" bench-mechanics "$c" --analytic -q -o "$dir/analytic.csv"
  # One table per model (the first column, when the table has one; plates-contact is one
  # model), with a "# model=" line for the key; the plate profiles keep the thesis's load only.
  files=""
  models=$(awk -F, '!/^#/ && !h { h = 1; m = ($1 == "model"); next } !/^#/ && m { print $1 }' "$dir/computed.csv" | sort -u)
  if [ -z "$models" ]; then
    { echo "# model=mesh"; grep -v '^#' "$dir/computed.csv"; } >"$dir/mesh.csv"
    files=" $dir/mesh.csv"
  fi
  for m in $models; do
    f="$dir/$m.csv"
    { echo "# model=$m"
      awk -F, -v m="$m" '/^#/ { next } !h { print; h = 1; for (i = 1; i <= NF; i++) if ($i == "load") l = i; next }
                         $1 == m && (!l || $l == "thesis")' "$dir/computed.csv"; } >"$f"
    files="$files $f"
  done
  gnuplot -e "analytic='$dir/analytic.csv'; computed='${files# }'; out='$out/shell_$c.png'" "$src/scripts/figures/plot_shell_benchmark.gp"
  echo "shell-figures: wrote $out/shell_$c.png" >&2
done
