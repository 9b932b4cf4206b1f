#!/usr/bin/env bash
# make bench, lbflow on MPI ranks (issue 40): the thesis-sized cluster (N = 50 jammed spheres,
# delta = 0.04) at M = LBFLOW_MPI_M (3) for LBFLOW_MPI_STEPS (200) steps, on 1 rank x 2 threads
# and on 2 ranks x 1 thread (same cores: the two should be within 10 %), then on 2, 3 and 4
# ranks x 1 thread for the halo: bytes sent between ranks per step and rank 0's seconds in the
# exchange per step (shared memory here; waiting for a slower rank included). The parallel
# efficiency on 8-256 machines is modelled from these in 42-lbflow_mpi.table.py. Needs lbflow
# built with MPI and mpirun (skipped otherwise). Sourced by scripts/bench/run.sh ($build,
# $bench, $out, $machine, $stamp).
if ! grep -q '^CMP_MPI:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null || ! command -v mpirun >/dev/null; then
  echo "== lbflow on MPI ranks: skipped (lbflow built without MPI, or no mpirun)" >&2
else
  M=${LBFLOW_MPI_M:-3} steps=${LBFLOW_MPI_STEPS:-200}
  echo "== lbflow on MPI ranks: N = 50 jammed, delta = 0.04, M = $M, $steps steps: 1 x 2 threads, 2-4 ranks x 1 thread" >&2
  mpi_dir=$(mktemp -d)
  "$build/bin/shellpack" jam -N 50 --seed 1 -q -o "$mpi_dir/jam.xyz" --csv /dev/null
  "$build/bin/percolate" "$mpi_dir/jam.xyz" --delta 0.04 -q -o "$mpi_dir/c.vtk" --csv /dev/null
  mpi_row() {  # ranks threads: one CSV row (ranks 0: plain lbflow, no launcher)
    local launch=()
    [ "$1" -gt 0 ] && launch=(env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 PMIX_MCA_psec=native
                              mpirun -q --oversubscribe -np "$1")
    rm -f "$mpi_dir/f.csv"  # a failed run must not report the row before it
    if ! "${launch[@]}" "$build/bin/lbflow" "$mpi_dir/c.vtk" --refine "$M" --threads "$2" --max-steps "$steps" \
      --check-every "$steps" --timings -q -o "$mpi_dir/f.csv" 2>"$mpi_dir/err.txt"; then
      echo "== lbflow on $1 rank(s) x $2 thread(s) failed: $(tail -1 "$mpi_dir/err.txt")" >&2
      return
    fi
    /usr/bin/python3 - "$mpi_dir/f.csv" "$1" "$2" <<'PY'
import csv, sys
r = next(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
steps = int(r["steps"])
ny, nz, m = int(r["ny"]), int(r["nz"]), int(r["refine"])
print(",".join([str(max(1, int(sys.argv[2]))), sys.argv[3], r["refine"], r["fluid_nodes"], str(ny * nz * m * m),
                r["porosity"], str(steps), r["seconds"], r["mlups"], r["bytes_per_fluid_node"],
                r["halo_bytes_per_step"], f"{float(r['halo_seconds']) / steps * 1e6:.1f}"]))
PY
  }
  {
    bench_header
    echo "ranks,threads_per_rank,refine,fluid_nodes,plane_nodes,porosity,steps,seconds,mlups,bytes_per_fluid_node,halo_bytes_per_step,halo_us_per_step"
    mpi_row 0 2
    mpi_row 2 1
    mpi_row 3 1
    mpi_row 4 1
  } | tee "$out/lbflow_mpi.csv" >&2
  # The model's inputs (42-lbflow_mpi.table.py): porosity and the speed per core of 1 rank x 2 threads.
  { bench_header; echo "porosity,per_core_mlups"
    grep -v '^#' "$out/lbflow_mpi.csv" | awk -F, '$1 == 1 && $2 == 2 { printf "%s,%.3f\n", $6, $9 / 2 }'; } > "$out/lbflow_mpi_model.csv"
  rm -rf "$mpi_dir"
fi
