#!/usr/bin/env bash
# Percolation probability versus porosity from sphere packings inflated step by step (the
# trend of thesis Fig. 5.2C): every packing at every scale and every delta through percolate,
# then `percolate sweep` per N and delta. For shellpack's jammed packings:
#   shellpack jam -N 32 --seeds 1:50 -o 'jam_{seed}.xyz'
#   scripts/data/percolation_sweep.sh -b build -d 0.03,0.04,0.05 -s "1.00 1.02 1.04 1.06 1.08 1.10" -o out/perc jam_*.xyz
# Writes OUT/percolate.csv (one row per packing, scale and delta) and
# OUT/percolation_probability.csv (binned per N and delta over the porosity column `porosity`:
# columns particles, delta, porosity, porosity_low, porosity_high, packings, percolating,
# probability, probability_error; kcfit's sigmoid fit reads either file as it is).
set -euo pipefail
build=build deltas=0.04 scales="1.0" out=out/percolation bins=10
while getopts "b:d:s:o:n:" opt; do
  case $opt in
    b) build=$OPTARG ;; d) deltas=$OPTARG ;; s) scales=$OPTARG ;; o) out=$OPTARG ;; n) bins=$OPTARG ;;
    *) echo "usage: $0 [-b build] [-d deltas] [-s 'scales'] [-o out] [-n bins] packing.xyz..." >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -gt 0 ] || { echo "$0: no packing given" >&2; exit 2; }
mkdir -p "$out"
# One percolate run over every packing x scale x delta (scales may be given with spaces or
# commas), then the binning: no merging of tables by hand.
"$build/bin/percolate" "$@" --delta "$deltas" --scale "$(echo $scales | tr ' ' ',')" -q --csv "$out/percolate.csv"
"$build/bin/percolate" sweep "$out/percolate.csv" --bins "$bins" -o "$out/percolation_probability.csv"
echo "$out/percolate.csv: $(($(grep -vc '^#' "$out/percolate.csv") - 1)) rows; $out/percolation_probability.csv" >&2
