#!/usr/bin/env bash
# make flow-figure: the chain of thesis Chapter 5 on inflated jammed sphere packings,
# shellpack jam -> percolate -> lbflow -> kcfit, with no reshaping of tables in between.
# COUNT (4) jammed packings of N (32) spheres are inflated by SCALES (0.90 ... 1.14),
# voxelised at DELTA (0.08 D0) with percolate's default overlap marking, and every cluster
# image that percolates goes through lbflow at refinement M (1); kcfit fits Eq. 5.8 (Table
# S5.1 model i, log loss as Fig. 5.5) to kappa in D0^2 and the tortuosity law tau_H =
# C (phi - phi_c)^-0.38 (Fig. 5.4B) to tau_H. A second, small packing (16 spheres) at its
# loosest and tightest percolating inflation runs at M = 1, 2, 3 (thesis 5.3.3: kappa in D0^2
# converges with M, M = 1 fails in narrow throats). 6-8 minutes on 2 (busy) cores.
# Writes $out/flow/{percolate.csv,flows.csv,kappa_fit.csv,tau_fit.csv,refine.csv} and
# $out/flow.png.
set -euo pipefail
build=${1:-build}
out=${2:-out/figures}
count=${COUNT:-4} n=${N:-32} delta=${DELTA:-0.08} M=${M:-1}
scales=${SCALES:-0.90,0.94,0.98,1.02,1.06,1.10,1.14}
dir="$out/flow"
mkdir -p "$dir/jammed" "$dir/images"
echo "== shellpack jam -N $n --seeds 1:$count" >&2
"$build/bin/shellpack" jam -N "$n" --seeds "1:$count" -q -o "$dir/jammed/jam_{seed}.xyz" --csv "$dir/jammed/jam.csv"
echo "== percolate: $count packings x scales $scales at delta $delta" >&2
"$build/bin/percolate" "$dir"/jammed/jam_*.xyz --delta "$delta" --scale "$scales" -q --csv "$dir/percolate.csv" \
  -o "$dir/images/c_{name}_{scale}.vtk"
images=$(scripts/data/percolating_images.sh "$dir/percolate.csv" "$dir/images" "$scales")
echo "== lbflow: $(echo "$images" | wc -l) percolating clusters at M = $M" >&2
# shellcheck disable=SC2086
"$build/bin/lbflow" $images --refine "$M" --threads 2 -o "$dir/flows.csv"
echo "== kcfit: Eq. 5.8 on kappa (D0^2, log loss) and the tortuosity law on tau_H" >&2
"$build/bin/kcfit" "$dir/flows.csv" --model kc-percolation --y permeability_d02 --loss log -q -o "$dir/kappa_fit.csv"
"$build/bin/kcfit" "$dir/flows.csv" --model tortuosity -q -o "$dir/tau_fit.csv"
echo "== refinement: M = 1, 2, 3 on a packing of 16 spheres, loose and tight" >&2
"$build/bin/shellpack" jam -N 16 --seed 1 -q -o "$dir/jammed/small.xyz" --csv /dev/null
"$build/bin/percolate" "$dir/jammed/small.xyz" --delta "$delta" --scale 1.00,1.04 -q --csv "$dir/percolate_small.csv" \
  -o "$dir/images/small_{scale}.vtk"
rm -f "$dir/refine.csv"
for m in 1 2 3; do
  "$build/bin/lbflow" "$dir/images/small_1.00.vtk" "$dir/images/small_1.04.vtk" --refine $m --threads 2 -q \
    -o "$dir/refine_$m.csv"
  if [ $m = 1 ]; then cat "$dir/refine_$m.csv"; else grep -v '^#' "$dir/refine_$m.csv" | tail -n +2; fi >> "$dir/refine.csv"
  rm "$dir/refine_$m.csv"
done
gnuplot -e "flows='$dir/flows.csv'; kfit='$dir/kappa_fit.csv'; tfit='$dir/tau_fit.csv'; refine='$dir/refine.csv'; out='$out/flow.png'" \
  scripts/figures/plot_flow.gp
echo "make flow-figure: $out/flow.png, $dir/flows.csv, $dir/kappa_fit.csv, $dir/tau_fit.csv, $dir/refine.csv" >&2
