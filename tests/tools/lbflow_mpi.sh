#!/usr/bin/env bash
# lbflow on several MPI ranks (issue 40): `mpirun -np N lbflow ...` gives the bits of one
# process (CSV rows, VTK field), a checkpoint taken on 2 ranks resumes on 3, memory per rank
# falls with the ranks, and bad runs stop every rank with one line. `lbflow_mpi.sh --list`
# prints the cases; `lbflow_mpi.sh CASE` runs one (ctest registers each). Needs CMP_BIN and an
# lbflow built with MPI (CMake CMP_MPI, the default): exit 77 (skipped) only when it was not.
set -uo pipefail
bin=${CMP_BIN:-build/bin}
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
cli_tool=lbflow
if [ "${1:-}" != --list ] && ! grep -q '^CMP_MPI:BOOL=ON' "$bin/../CMakeCache.txt" 2>/dev/null; then
  echo "lbflow_mpi: $bin was built without MPI (cmake -DCMP_MPI=OFF): skipped" >&2
  exit 77
fi
[ "${1:-}" = --list ] || bin=$(cd "$bin" && pwd)
lbflow="$bin/lbflow" percolate="$bin/percolate" shellpack="$bin/shellpack"
# OpenMPI as a test runs it: any number of ranks on this machine's cores, as root too, the
# PMIx security plugin that needs no munge; -q: no banner besides lbflow's own line.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 PMIX_MCA_psec=native OMP_NUM_THREADS=1
mpirun() { command mpirun -q --oversubscribe "$@"; }
enter_scratch_dir

# The data rows of a CSV without the column that depends on the decomposition (the storage
# per fluid node, halo included) and the provenance lines.
rows() { grep -v '^#' "$1" | /usr/bin/python3 -c '
import csv, sys
r = list(csv.reader(sys.stdin)); drop = r[0].index("bytes_per_fluid_node")
for row in r: print(",".join(v for i, v in enumerate(row) if i != drop))'; }
# The VTK field from its FIELD data on (the title holds the command line).
field_bytes() { /usr/bin/python3 -c 'import sys; d = open(sys.argv[1], "rb").read(); sys.stdout.buffer.write(d[d.index(b"FIELD"):])' "$1"; }

# same_bits INPUT ARGS...: lbflow on 1 process, then on 2..4 ranks, each in its own folder
# (the same file names): CSV rows and VTK field identical to the one process's. (mpirun -np 1
# is one process: lbflow leaves MPI alone for a single task.)
same_bits() {
  local input=$1; shift
  mkdir one && (cd one && "$lbflow" "../$input" "$@" -q -o f.csv --vtk f.vtk) || fail "one process: $(ls one)"
  for n in 2 3 4; do
    mkdir "r$n"
    (cd "r$n" && mpirun -np "$n" "$lbflow" "../$input" "$@" -q -o f.csv --vtk f.vtk 2>err.txt) ||
      fail "$n ranks exited $?: $(cat "r$n/err.txt")"
    grep -q "^# provenance=.* (ranks=$n threads=1 per rank)\$" "r$n/f.csv" || fail "$n ranks: not in the provenance: $(grep '^#' "r$n/f.csv")"
    [ "$(rows one/f.csv)" = "$(rows "r$n/f.csv")" ] || fail "$n ranks: rows differ: $(rows one/f.csv) vs $(rows "r$n/f.csv")"
    cmp -s <(field_bytes one/f.vtk) <(field_bytes "r$n/f.vtk") || fail "$n ranks: VTK field differs"
  done
}

# A simple cubic array of 4 spheres along x (Zick & Homsy's geometry, exact walls): 64 x 16 x 16 nodes, 4 slabs.
sphere_array() {
  { echo 4; echo 'Lattice="4 0 0 0 1 0 0 0 1" Properties=species:S:1:pos:R:3:radius:R:1 pbc="T T T" D0=1'
    for x in 0.5 1.5 2.5 3.5; do echo "X $x 0.5 0.5 0.4"; done; } > array.xyz
}
# A percolating cluster of 16 jammed spheres (24^3 voxels; at M = 3, 72 planes: 5 slabs).
cluster() {
  "$shellpack" jam -N 16 --seed 2 -o jam.xyz -q >/dev/null || fail "shellpack jam"
  "$percolate" jam.xyz --delta 0.1 --sphere-marking centre -q -o cluster.vtk --csv /dev/null || fail "percolate"
}

case_same_bits_sphere_array() {
  sphere_array
  same_bits array.xyz --delta 0.0625 --refine 1
}
case_same_bits_cluster_refined() {
  cluster
  same_bits cluster.vtk --refine 3 --tol 1e-3 --check-every 50 --window 2
}
case_same_bits_force_float() {  # body force: periodic along the axis, ghosts across the ends; float storage
  sphere_array
  same_bits array.xyz --delta 0.0625 --refine 1 --drive force --precision float --tol 1e-4
}

case_checkpoint_2_ranks_resumed_on_3() {
  sphere_array
  # An odd check interval: the checkpoint falls after an odd step (the halo is filled on resume).
  local run=(--delta 0.0625 --refine 1 --check-every 101)
  "$lbflow" array.xyz "${run[@]}" -q -o full.csv --vtk full.vtk || fail "uninterrupted run"
  mpirun -np 2 "$lbflow" array.xyz "${run[@]}" --max-steps 707 --checkpoint run.ckpt -q -o part.csv 2>err.txt
  [ $? -eq 1 ] && grep -q 'not converged after 707 steps' err.txt || fail "the stopped run: $(cat err.txt)"
  mpirun -np 3 "$lbflow" --resume run.ckpt --max-steps 200000 -q -o resumed.csv --vtk resumed.vtk || fail "resume on 3 ranks"
  [ "$(rows full.csv)" = "$(rows resumed.csv)" ] || fail "resumed rows differ: $(rows full.csv) vs $(rows resumed.csv)"
  cmp -s <(field_bytes full.vtk) <(field_bytes resumed.vtk) || fail "resumed field differs"
}

case_more_ranks_than_slabs() {
  sphere_array
  expect_error 2 "5 ranks but only 4 slabs of 16 planes along the flow axis" \
    mpirun -np 5 "$lbflow" array.xyz --delta 0.0625 --refine 1 -o out.csv
}

case_standard_input_refused() {
  sphere_array
  expect_error 2 "'-' (standard input) reaches only rank 0 under mpirun" \
    mpirun -np 2 "$lbflow" - --delta 0.0625 --refine 1 -o out.csv < array.xyz
}

case_checkpoint_of_another_lattice() {
  sphere_array
  "$lbflow" array.xyz --delta 0.0625 --refine 1 --max-steps 100 --checkpoint run.ckpt -q -o /dev/null 2>/dev/null
  [ -s run.ckpt ] || fail "no checkpoint"
  expect_error 2 "checkpoint is from another run" \
    mpirun -np 2 "$lbflow" array.xyz --delta 0.05 --refine 1 --resume run.ckpt -o out.csv
}

# The cluster at M = 10: 240^3 nodes, 5.6 M fluid, 1.3 GB of populations and links on one
# process (each rank also holds the 14 MB pore mask); four steps.
big_run=(cluster.vtk --refine 10 --max-steps 4 --check-every 2 --window 1 --tol 1)

case_rank_cannot_allocate() {  # rank 1 alone under a limit its half (650 MB) does not fit: exit 1, as out of memory on one process
  cluster
  expect_error 1 "rank 1: out of memory" \
    mpirun -np 2 sh -c '[ "$OMPI_COMM_WORLD_RANK" = 1 ] && ulimit -v 500000; exec "$0" "$@"' "$lbflow" "${big_run[@]}" -o out.csv
}

case_checkpoint_of_an_older_version() {  # the state format before MPI (version 1), its checksum made good: refused on every rank
  sphere_array
  "$lbflow" array.xyz --delta 0.0625 --refine 1 --max-steps 100 --checkpoint run.ckpt -q -o /dev/null 2>/dev/null
  [ -s run.ckpt ] || fail "no checkpoint"
  /usr/bin/python3 - run.ckpt <<'PY' || fail "could not rewrite the checkpoint"
import sys
path = sys.argv[1]
data = open(path, "rb").read()
head_end = data.index(b"state fnv1a64\n") + len(b"state fnv1a64\n")
state = data[head_end:-26].replace(b"CMPLBM2\n", b"CMPLBM1\n", 1)
h = 0xcbf29ce484222325
for b in state:
    h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
open(path, "wb").write(data[:head_end] + state + b"\nfnv1a64 %016x\n" % h)
PY
  expect_error 2 "checkpoint written by an older lbflow" mpirun -np 2 "$lbflow" --resume run.ckpt -o out.csv
}

case_rank_0_cannot_gather_the_field() {  # rank 0 holds its half but not the whole VTK field: it names itself and ends every rank, no hang
  cluster
  timeout 120 mpirun -np 2 sh -c '[ "$OMPI_COMM_WORLD_RANK" = 0 ] && ulimit -v 1100000; exec "$0" "$@"' \
    "$lbflow" "${big_run[@]}" -o out.csv --vtk out.vtk 2>err.txt
  local got=$?
  [ "$got" -eq 1 ] || fail "exited $got (124: a rank hung), expected 1: $(cat err.txt)"
  # lbflow's one line, wherever OpenMPI's MPI_Abort notice lands around it (mpirun writes its
  # own notice and the ranks' forwarded stderr in no fixed order)
  [ "$(grep '^lbflow:' err.txt)" = "lbflow: rank 0: out of memory" ] || fail "lbflow's lines: $(cat err.txt)"
  ! ls out.* .out.* 2>/dev/null | grep >/dev/null . || fail "left a file behind: $(ls -a)"
}

case_memory_falls_with_ranks() {  # under 900 MB per process: one process cannot hold it, four ranks can
  cluster
  sh -c 'ulimit -v 900000; exec "$0" "$@"' "$lbflow" "${big_run[@]}" -o one.csv 2>err.txt
  [ $? -eq 1 ] && grep -q "out of memory" err.txt || fail "one process fitted in 900 MB: $(cat err.txt)"
  # (four steps are no steady state: the cap ends the run with its row, exit 1)
  mpirun -np 4 sh -c 'ulimit -v 900000; exec "$0" "$@"' "$lbflow" "${big_run[@]}" -q -o four.csv 2>err.txt
  [ $? -eq 1 ] && grep -q "not converged after 4 steps" err.txt || fail "4 ranks under 900 MB each: $(cat err.txt)"
  [ "$(rows four.csv | tail -1 | cut -d, -f1)" = cluster.vtk ] || fail "no row: $(cat four.csv)"
}

case_srun_two_ranks() {  # Slurm's launcher: the single-node slurm-wlm of make test-slurm (scripts/study/slurm_local.sh)
  sphere_array
  "$lbflow" array.xyz --delta 0.0625 --refine 1 -q -o one.csv || fail "one process"
  # (without OMP_NUM_THREADS: slurm_local.sh gives the node $(nproc) CPUs, and nproc obeys it)
  env -u OMP_NUM_THREADS "$src/scripts/study/slurm_local.sh" start "$cli_scratch/slurm" >/dev/null || fail "Slurm did not start"
  trap '"$src/scripts/study/slurm_local.sh" stop "$cli_scratch/slurm"; rm -rf "$cli_scratch"' EXIT
  # --mpi=pmix: OpenMPI's ranks find each other through Slurm's PMIx (MpiDefault is none here).
  SLURM_CONF="$cli_scratch/slurm/slurm.conf" timeout 120 srun --mpi=pmix -N 1 -n 2 -c 1 "$lbflow" array.xyz --delta 0.0625 --refine 1 -q \
    -o two.csv 2>err.txt || fail "srun -n 2: $(cat err.txt)"
  grep -q "(ranks=2 threads=1 per rank)" two.csv || fail "not 2 ranks: $(grep provenance two.csv)"
  [ "$(rows one.csv)" = "$(rows two.csv)" ] || fail "srun rows differ"
}

run_cases "$@"
