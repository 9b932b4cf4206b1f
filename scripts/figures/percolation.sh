#!/usr/bin/env bash
# make percolation-figure: the trend of thesis Fig. 5.2C-D on jammed sphere packings, the whole
# chain shellpack jam -> percolate -> kcfit, no reshaping of tables in between. COUNT (40)
# jammed packings of N (50) spheres are inflated by 1.00 ... 1.40, voxelised at
# delta = 0.03 ... 0.07 (in diameters) and labelled (percolate, one row per packing, scale and
# delta); kcfit fits per delta the percolation probability (maximum-likelihood sigmoid of the
# 0/1 `percolates` against `porosity`) for phi_c(delta), then the threshold law
# phi_c = phi_c* + A delta^beta to its own output. Writes $out/percolate.csv,
# percolation_probability.csv (percolate sweep), phi_c.csv, threshold_fit.csv,
# percolation_fit.png, threshold_fit.png and percolation.png.
set -euo pipefail
build=${1:-build}
out=${2:-out/figures}
count=${COUNT:-40} n=${N:-50}
deltas=0.03,0.04,0.05,0.06,0.07
scales=$(seq -s , 1.00 0.02 1.40)
mkdir -p "$out/jammed"
echo "== shellpack jam -N $n --seeds 1:$count" >&2
"$build/bin/shellpack" jam -N "$n" --seeds "1:$count" -q -o "$out/jammed/jam_{seed}.xyz" --csv "$out/jammed/jam.csv"
echo "== percolate: $count packings x 21 inflations x 5 deltas" >&2
"$build/bin/percolate" "$out"/jammed/jam_*.xyz --delta "$deltas" --scale "$scales" -q --csv "$out/percolate.csv"
"$build/bin/percolate" sweep "$out/percolate.csv" --bins 12 -o "$out/percolation_probability.csv"
echo "== kcfit: sigmoid per delta, then the threshold law on those fits" >&2
"$build/bin/kcfit" "$out/percolate.csv" --model sigmoid --group-by delta -o "$out/phi_c.csv" \
  --plot "$out/percolation_fit.png"
"$build/bin/kcfit" "$out/phi_c.csv" --model threshold -o "$out/threshold_fit.csv" --plot "$out/threshold_fit.png"
gnuplot -e "prob='$out/percolation_probability.csv'; phic='$out/phi_c.csv'; law='$out/threshold_fit.csv'; out='$out/percolation.png'" \
  scripts/figures/plot_percolation.gp
echo "make percolation-figure: $out/percolation.png, $out/phi_c.csv, $out/threshold_fit.csv" >&2
