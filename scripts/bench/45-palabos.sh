#!/usr/bin/env bash
# make bench, Palabos 1.5 (Debian libplb-dev, the engine the thesis used) beside lbflow's kernel
# in the same run (bench/bench_palabos): the dense and porous 128^3 boxes of bench_lbm speed
# (same lattice, same 20 steps, same fluid nodes; MLUPS over fluid nodes) on 1 MPI process
# (MRT) and 2 (MRT, BGK, TRT; the Debian library is built with MPI: one process per core), the
# N = 50, delta = 0.04 cluster of 40-lbflow_run.sh at M = 1 (20 steps) and M = 3 (10 steps)
# through both codes, and a square-duct permeability from both (the same physics?). Skipped
# when CMake found no Palabos or MPI. bench_palabos is not part of `make all` (a minute of
# Palabos templates): it is built here. PAL_N (128) sets the box side for a quick try. Sourced
# by scripts/bench/run.sh ($build, $bench, $out, $machine, $stamp).
if ! grep -q '^CMP_HAVE_PALABOS:INTERNAL=ON' "$build/CMakeCache.txt"; then
  echo "== Palabos: libplb-dev or MPI not found by CMake; skipped" >&2
else
  cmake --build "$build" --target bench_palabos >&2
  echo "== Palabos 1.5 beside lbflow's kernel: 128^3 boxes, the N = 50 cluster, a square duct" >&2
  pal_dir=$(mktemp -d)
  pal_mpi() { mpirun --allow-run-as-root -np "$1" "$bench/bench_palabos" "${@:2}"; }
  "$build/bin/shellpack" jam -N 50 --seed 1 -q -o "$pal_dir/jam.xyz" --csv /dev/null
  "$build/bin/percolate" "$pal_dir/jam.xyz" --delta 0.04 -q -o "$pal_dir/c.vtk" --csv /dev/null
  {
    bench_header
    pal_mpi 1 speed ${PAL_N:-128} 20 mrt
    pal_mpi 2 speed ${PAL_N:-128} 20 | tail -n +2
    pal_mpi 1 cluster "$pal_dir/c.vtk" 1 20 | tail -n +2
    pal_mpi 2 cluster "$pal_dir/c.vtk" 1 20 | tail -n +2
    pal_mpi 2 cluster "$pal_dir/c.vtk" 3 10 | tail -n +2
  } | tee "$out/palabos.csv" >&2
  {
    bench_header
    "$bench/bench_palabos" lbflow-cluster "$pal_dir/c.vtk" 1 1 20
    "$bench/bench_palabos" lbflow-cluster "$pal_dir/c.vtk" 1 2 20 | tail -n +2
    "$bench/bench_palabos" lbflow-cluster "$pal_dir/c.vtk" 3 2 10 | tail -n +2
  } | tee "$out/palabos_lbflow_cluster.csv" >&2
  {
    bench_header
    "$bench/bench_palabos" poiseuille
  } | tee "$out/palabos_duct.csv" >&2
  rm -rf "$pal_dir"
fi
