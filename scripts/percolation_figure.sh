#!/usr/bin/env bash
# make percolation-figure: the trend of thesis Fig. 5.2C-D on jammed sphere packings, the whole
# chain shellpack jam -> percolate -> kcfit. COUNT (40) jammed packings of N (50) spheres are
# inflated by 1.00 ... 1.40, voxelised at delta = 0.03 ... 0.07 (in diameters), labelled;
# per delta kcfit fits the percolation probability (maximum likelihood sigmoid on the 0/1
# outcomes) for phi_c(delta), then the threshold law phi_c = phi_c* + A delta^beta.
# Writes $out/percolate.csv, percolation_probability.csv, phi_c.csv, threshold_fit.csv and
# percolation.png.
set -euo pipefail
build=${1:-build}
out=${2:-out/figures}
count=${COUNT:-40} n=${N:-50}
deltas="0.03 0.04 0.05 0.06 0.07"
mkdir -p "$out/jammed"
echo "== shellpack jam -N $n --seeds 1:$count" >&2
"$build/bin/shellpack" jam -N "$n" --seeds "1:$count" -q -o "$out/jammed/jam_{seed}.xyz" --csv "$out/jammed/jam.csv"
echo "== percolate: $count packings x 21 inflations x 5 deltas" >&2
scripts/percolation_sweep.sh -b "$build" -d "${deltas// /,}" -s "$(seq -s ' ' 1.00 0.02 1.40)" -n 12 -o "$out" \
  "$out"/jammed/jam_*.xyz
echo "== kcfit: sigmoid per delta, then the threshold law" >&2
{
  echo "# phi_c(delta): maximum-likelihood sigmoid of percolates against porosity_geometry_overlap, N = $n"
  echo "delta,phi_c,phi_c_stderr,width"
  for d in $deltas; do
    awk -F, -v d="$d" '/^#/ { next } $1 == "file" { for (i = 1; i <= NF; i++) c[$i] = i; print "porosity,percolates"; next }
      $c["delta"] == d { print $c["porosity_geometry_overlap"] "," $c["percolates"] }' "$out/percolate.csv" >"$out/.rows_$d.csv"
    "$build/bin/kcfit" "$out/.rows_$d.csv" --model sigmoid --x porosity --y percolates -q -o "$out/.fit_$d.csv"
    awk -F, -v d="$d" '$1 == "phi_c" { p = $2; e = $3 } $1 == "width" { w = $2 } END { print d "," p "," e "," w }' "$out/.fit_$d.csv"
    rm -f "$out/.rows_$d.csv" "$out/.fit_$d.csv"
  done
} >"$out/phi_c.csv"
cat "$out/phi_c.csv" >&2
"$build/bin/kcfit" "$out/phi_c.csv" --model threshold --x delta --y phi_c -o "$out/threshold_fit.csv"
gnuplot -e "prob='$out/percolation_probability.csv'; phic='$out/phi_c.csv'; out='$out/percolation.png'" \
  scripts/plot_percolation.gp
echo "make percolation-figure: $out/percolation.png, $out/phi_c.csv, $out/threshold_fit.csv" >&2
