#!/usr/bin/env bash
# make bench: performance figures for the README's table. Writes CSV files and a Markdown
# table into the output folder and prints the table.
set -euo pipefail
build=${1:-build}
out=${2:-out/bench}
mkdir -p "$out"
here=$(dirname "${BASH_SOURCE[0]}")
source "$here/common.sh"

# Each benchmark is a file NN-<tool>.sh of this folder, sourced in the order of NN (pipeline
# order; its rows of the table come from NN-<tool>.table.py); a tool may be skipped with
# BENCH_ONLY="rndmesh kcfit" (a space-separated list of the ones to run).
export build out bench machine stamp
for script in "$here"/[0-9][0-9]-*.sh; do
  tool=$(basename "$script" .sh)
  tool=${tool#*-}
  if [ -n "${BENCH_ONLY:-}" ] && [[ " $BENCH_ONLY " != *" $tool "* ]]; then continue; fi
  source "$script"
done

/usr/bin/python3 "$here/table.py" "$out" "$machine" "$stamp" | tee "$out/table.md"
