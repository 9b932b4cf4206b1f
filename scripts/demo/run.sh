#!/usr/bin/env bash
# make run: the demo pipeline, every tool that exists so far chained on plain files.
set -euo pipefail
build=${1:-build}
out=${2:-out/demo}
bin="$build/bin"
mkdir -p "$out"
step() { printf '\n== %s\n' "$*" >&2; }

# Each tool's stage is a file NN-<tool>.sh of this folder, sourced in the order of NN (pipeline
# order); later stages read the files of earlier ones. Each appends a description of its
# outputs to $out/README.txt.
printf 'Outputs of make run:\n' >"$out/README.txt"
for script in "$(dirname "${BASH_SOURCE[0]}")"/[0-9][0-9]-*.sh; do
  source "$script"
done

printf '\n' >&2
cat "$out/README.txt" >&2
printf '(all in %s/; this list is %s/README.txt)\n' "$out" "$out" >&2
printf 'make run: the study'"'"'s report is %s/study/report.html\n' "$out" >&2
