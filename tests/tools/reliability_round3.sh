#!/usr/bin/env bash
# Issue 58 (reliability, third round), items 1, 3, 5 and 7: option values checked against what
# they mean (thread counts, scales), a finished table kept when a secondary output fails,
# degenerate fits refused, and output names (NAME_MAX, templates in folders) checked before
# any work. `reliability_round3.sh --list` prints the cases; `reliability_round3.sh CASE` runs
# one (ctest registers each). Needs CMP_BIN and CMP_SRC.
set -uo pipefail
bin=${CMP_BIN:-build/bin}
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
lbflow="$bin/lbflow"
percolate="$bin/percolate"
shellpack="$bin/shellpack"
rndmesh="$bin/rndmesh"
kcfit="$bin/kcfit"
jam2d="$bin/jam2d"
sc="$src/data/percolate/simple_cubic_4x4x4.xyz"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
source "$(dirname "${BASH_SOURCE[0]}")/../support/compress_start.sh"
export OMP_NUM_THREADS=1
enter_scratch_dir

# bounded TOOL STATUS PATTERN cmd...: within 20 s of CPU time and 300 MB, one line, no output left.
bounded() { expect_bounded 20 300000 "$@"; }
# rows CSV: its data rows (below the header).
rows() { grep -v '^#' "$1" | tail -n +2 | wc -l; }

# --- item 1: --threads against what the machine and OpenMP allow, before any work ---
case_threads_beyond_the_machine_refused() {
  local bound=$((64 * $(nproc)))
  # libgomp segfaulted at 100000 and failed "Thread creation failed" at 40000.
  for n in 100000 40000 2147483647; do
    bounded rndmesh 2 "--threads: must lie in \[0, [0-9]*\] (64 per core of this machine's [0-9]*), got '$n'" \
      "$rndmesh" random -n 20 -o out.off --threads "$n"
  done
  cluster_vtk
  printf 'porosity,permeability\n0.2,1\n0.3,2\n0.4,3\n0.5,5\n' >k.csv
  bounded percolate 2 "--threads: must lie in" "$percolate" "$sc" --delta 0.1 -o out.vtk --threads 100000
  bounded lbflow 2 "--threads: must lie in" "$lbflow" c.vtk -o out.csv --threads 100000
  bounded kcfit 2 "--threads: must lie in" "$kcfit" k.csv --model power -o out.csv --threads 100000
  bounded jam2d 2 "--threads: must lie in" "$jam2d" moduli x.xyz -o out.csv --threads 100000
  bounded shellpack 2 "--threads: must lie in" "$shellpack" jam -N 12 -o out.xyz --threads 100000
  bounded shellpack 2 "--threads: must lie in" "$shellpack" analyze x.off -o out.csv --threads 100000
  bounded rndmesh 2 "--threads: must lie in" "$rndmesh" stats x.off -o out.csv --threads 100000
  # The bound itself is accepted (a few threads more than cores is legitimate), and OpenMP's own
  # limit lowers it.
  "$rndmesh" random -n 20 --sweeps 1 --anneals 1 -o r.off -q --threads "$bound" || fail "--threads $bound refused"
  OMP_THREAD_LIMIT=3 bounded rndmesh 2 "--threads: must lie in \[0, 3\] (OpenMP's thread limit, OMP_THREAD_LIMIT=3), got '4'" \
    "$rndmesh" random -n 20 -o out.off --threads 4
}

run_cases "$@"
