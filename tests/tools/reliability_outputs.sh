#!/usr/bin/env bash
# Issue 37, items 2 and 3: every program checks every output before any work (its folder
# exists and is writable, no two outputs of one run are one file, no output is an input) and
# refuses with exit 2 naming the option; a secondary output that fails after the work never
# discards the primary result. `reliability_outputs.sh --list` prints the cases;
# `reliability_outputs.sh CASE` runs one (ctest registers each). Needs CMP_BIN and CMP_SRC.
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
export OMP_NUM_THREADS=1
enter_scratch_dir

# refused_at_once TOOL PATTERN cmd...: exit 2 with one line naming the option (no summary
# line of a finished computation before it), and no output left behind.
refused_at_once() {
  cli_tool=$1
  shift
  expect_error 2 "$@"
}

case_lbflow_unwritable_checkpoint_or_vtk_before_the_solve() {
  cluster_vtk
  refused_at_once lbflow "--checkpoint: notadir/ck: cannot write: No such file or directory" \
    "$lbflow" c.vtk --refine 1 -o out.csv --checkpoint notadir/ck
  refused_at_once lbflow "--vtk: notadir/v.vtk: cannot write" "$lbflow" c.vtk --refine 1 -o out.csv --vtk notadir/v.vtk
  refused_at_once lbflow "--history: notadir/h.csv: cannot write" "$lbflow" c.vtk --refine 1 -o out.csv --history notadir/h.csv
  refused_at_once lbflow "--output: notadir/o.csv: cannot write" "$lbflow" c.vtk --refine 1 -o notadir/o.csv
  mkdir adir
  refused_at_once lbflow "--vtk: adir: cannot write: Is a directory" "$lbflow" c.vtk --refine 1 -o out.csv --vtk adir
}
case_lbflow_two_outputs_on_one_file() {
  cluster_vtk
  refused_at_once lbflow "--history: out.csv is also the output of --output" \
    "$lbflow" c.vtk --refine 1 -o out.csv --history out.csv
  # compared as files, not as strings
  mkdir sub
  refused_at_once lbflow "--history: sub/../out.csv is also the output of --output" \
    "$lbflow" c.vtk --refine 1 -o ./out.csv --history sub/../out.csv
  echo old >old.csv
  ln -s old.csv link.csv
  "$lbflow" c.vtk --refine 1 -q -o old.csv --history link.csv 2>err.txt
  [ $? -eq 2 ] && grep -q "^lbflow: --history: link.csv is also the output of --output" err.txt ||
    fail "a symbolic link to the table: $(cat err.txt)"
  [ "$(cat old.csv)" = old ] || fail "the table was replaced"
  refused_at_once lbflow "--vtk: out.csv is also the output of --output" "$lbflow" c.vtk --refine 1 -o out.csv --vtk out.csv
  refused_at_once lbflow "--checkpoint: c.vtk is also an input (c.vtk)" "$lbflow" c.vtk --refine 1 -o out.csv --checkpoint c.vtk
  # /dev/null twice is fine
  "$lbflow" c.vtk --refine 1 -q -o /dev/null --history /dev/null || fail "/dev/null twice"
}
case_lbflow_secondary_failure_keeps_the_table() {
  [ -w /dev/full ] || fail "no /dev/full"
  cluster_vtk
  "$lbflow" c.vtk --refine 1 -q -o table.csv --history /dev/full 2>err.txt
  local status=$?
  [ "$status" -eq 2 ] || fail "exit $status; $(cat err.txt)"
  grep -q "^lbflow: /dev/full: write error: No space left on device (the other outputs were written: table.csv)" err.txt ||
    fail "message: $(cat err.txt)"
  [ "$(grep -v '^#' table.csv | wc -l)" -eq 2 ] || fail "the table was lost: $(ls -a)"
  "$lbflow" c.vtk --refine 1 -q -o table2.csv --vtk /dev/full 2>err.txt
  [ $? -eq 2 ] && grep -q "/dev/full: write error.*(the table was written: table2.csv)" err.txt || fail "vtk: $(cat err.txt)"
  [ "$(grep -v '^#' table2.csv | wc -l)" -eq 2 ] || fail "the table was lost after --vtk failed"
}
case_shellpack_jam_outputs() {
  refused_at_once shellpack "--csv: f is also the output of --packing" "$shellpack" jam -N 12 -o f --csv f
  [ ! -e f ] || fail "f written"
  refused_at_once shellpack "--csv: notadir/x.csv: cannot write" \
    "$shellpack" jam -N 12 --seeds 1:4 -o 'out_{seed}.xyz' --csv notadir/x.csv
  ! ls out_* 2>/dev/null | grep >/dev/null . || fail "per-seed packings left behind: $(ls)"
  refused_at_once shellpack "--csv: out_{seed}.xyz is also the output of --packing" \
    "$shellpack" jam -N 12 --seeds 1:2 -o 'out_{seed}.xyz' --csv 'out_{seed}.xyz'
  refused_at_once shellpack "--packing: notadir/p_{seed}.xyz: cannot write" \
    "$shellpack" jam -N 12 --seeds 1:2 -o 'notadir/p_{seed}.xyz'
}
case_shellpack_analyze_and_structure_outputs() {
  refused_at_once shellpack "--rdf: out.csv is also the output of --output" \
    "$shellpack" analyze "$src/tests/data/io/octahedron_packing.off" -o out.csv --rdf out.csv
  refused_at_once shellpack "--summary: notadir/s.csv: cannot write" "$shellpack" structure "$sc" --summary notadir/s.csv
  cp "$sc" in.xyz
  refused_at_once shellpack "--output: in.xyz is also an input" "$shellpack" structure in.xyz -o in.xyz
  cmp -s "$sc" in.xyz || fail "input replaced"
}
case_rndmesh_trace_unwritable_before_the_anneal() {
  refused_at_once rndmesh "--trace: notadir/t.csv: cannot write" "$rndmesh" random -n 40 --trace notadir/t.csv -o out.off
  refused_at_once rndmesh "out.off is also the output of" "$rndmesh" random -n 40 --trace out.off -o out.off
  "$rndmesh" icosa -l 2 -o m.off -q || fail "icosa"
  cp m.off m2.off
  refused_at_once rndmesh "--output: m.off is also an input" "$rndmesh" stats m2.off m.off -o m.off
}
case_percolate_output_on_its_input() {
  cp "$sc" j.xyz
  refused_at_once percolate "--output: j.xyz is also an input (j.xyz): the output would replace it" \
    "$percolate" j.xyz --delta 0.1 -o j.xyz
  cmp -s "$sc" j.xyz || fail "the input was replaced"
  ln j.xyz hard.xyz
  refused_at_once percolate "--csv: hard.xyz is also an input (j.xyz)" "$percolate" j.xyz --delta 0.1 --csv hard.xyz
  refused_at_once percolate "--csv: out.vtk is also the output of --output" "$percolate" j.xyz --delta 0.1 -o out.vtk --csv out.vtk
  "$percolate" j.xyz --delta 0.1 -q >t.csv || fail "percolate"
  refused_at_once percolate "--output: t.csv is also an input" "$percolate" sweep t.csv -o t.csv
}
case_kcfit_and_jam2d_outputs() {
  printf 'porosity,percolates\n0.1,0\n0.2,0\n0.3,1\n0.25,1\n0.15,0\n0.35,1\n' >t.csv
  refused_at_once kcfit "--output: t.csv is also an input" "$kcfit" t.csv --model sigmoid -o t.csv
  refused_at_once kcfit "--plot: notadir/f.png: cannot write" "$kcfit" t.csv --model sigmoid -o out.csv --plot notadir/f.png
  refused_at_once jam2d "--csv: out.xyz is also the output of --packing" "$jam2d" grow -o out.xyz --csv out.xyz
  refused_at_once jam2d "--trajectory: notadir/t.xyz: cannot write" "$jam2d" grow -o out.xyz --trajectory notadir/t.xyz
}

run_cases "$@"
