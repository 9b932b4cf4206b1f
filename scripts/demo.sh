#!/usr/bin/env bash
# make run: the demo pipeline, every tool that exists so far chained on plain files.
set -euo pipefail
build=${1:-build}
out=${2:-out/demo}
bin="$build/bin"
mkdir -p "$out"
step() { printf '\n== %s\n' "$*" >&2; }

# Each tool's stage is scripts/demo_<tool>.sh, run in pipeline order; later stages read the
# files of earlier ones. Each appends a description of its outputs to $out/README.txt.
printf 'Outputs of make run:\n' >"$out/README.txt"
for tool in rndmesh shellpack percolate lbflow kcfit jam2d study; do
  script="scripts/demo_$tool.sh"
  if [ -f "$script" ]; then source "$script"; fi
done

printf '\n' >&2
cat "$out/README.txt" >&2
printf '(all in %s/; this list is %s/README.txt)\n' "$out" "$out" >&2
printf 'make run: the study'"'"'s report is %s/study/report.html\n' "$out" >&2
