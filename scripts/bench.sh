#!/usr/bin/env bash
# make bench: performance figures for the README's table. Writes CSV files and a Markdown
# table into the output folder and prints the table.
set -euo pipefail
build=${1:-build}
out=${2:-out/bench}
mkdir -p "$out"
bench="$build/bench"
machine="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores"
stamp="$(date -u +%Y-%m-%d)"

# Each tool's figures come from scripts/bench_<tool>.sh, run in pipeline order; a tool may
# be skipped with BENCH_ONLY="rndmesh kcfit" (a space-separated list of the ones to run).
export build out bench machine stamp
for tool in rndmesh shellpack shell compress percolate lbflow lbflow_run palabos kcfit jam2d study threads; do
  script="scripts/bench_$tool.sh"
  [ -f "$script" ] || continue
  if [ -n "${BENCH_ONLY:-}" ] && [[ " $BENCH_ONLY " != *" $tool "* ]]; then continue; fi
  source "$script"
done

/usr/bin/python3 scripts/bench_table.py "$out" "$machine" "$stamp" | tee "$out/table.md"
