#!/usr/bin/env bash
# make bench, jam2d: growth-driven jamming of budding cells (thesis 3.4.2) to the thesis's
# criterion 1e-16 <= V/(kN) <= 2e-16, one colony at a time on one thread: wall time and FIRE
# iterations at boxes 8 (the thesis's own Fortran code: 48 cells, 60 s on one core), 10, 15
# and 20 sigma; then the time per packing of a sweep (jamming + dphi = 0.05 at 15 sigma) on
# 2 threads, with the thesis's step reset and with --double-step. Sourced by scripts/bench/run.sh, which sets $bench, $out, $machine and $stamp.
echo "== jam2d: jamming at L = 8, 10, 15, 20 sigma (1 thread)" >&2
{
  bench_header
  echo "box,seed,cells,phi_J,Z,f_u,seconds,fire_iterations,accepted,rejected"
  OMP_NUM_THREADS=1 "$bench/bench_jam2d" 8 1 3
  OMP_NUM_THREADS=1 "$bench/bench_jam2d" 10 1 3
  OMP_NUM_THREADS=1 "$bench/bench_jam2d" 15 1 2
  OMP_NUM_THREADS=1 "$bench/bench_jam2d" 20 1 1
} | tee "$out/jam2d_jamming.csv" >&2

{
  bench_header
  echo "box,packings,dphi,threads,step_after_acceptance,seconds,seconds_per_packing"
  for mode in reset double; do
    flag=; [ $mode = double ] && flag=--double-step
    echo "== jam2d sweep --box 15 --seeds 1:4 --dphi 0.05 --P0 inf --threads 2 $flag" >&2
    t0=$(date +%s%N)
    "$build/bin/jam2d" sweep --box 15 --seeds 1:4 --dphi 0.05 --P0 inf --threads 2 -q $flag >/dev/null
    t1=$(date +%s%N)
    ms=$(((t1 - t0) / 1000000))
    echo "15,4,0.05,2,$mode,$((ms / 1000)).$(printf '%03d' $((ms % 1000))),$((ms / 4000)).$(printf '%03d' $(((ms / 4) % 1000)))"
  done
} | tee "$out/jam2d_sweep.csv" >&2
