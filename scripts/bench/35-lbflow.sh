#!/usr/bin/env bash
# make bench, lbflow's kernel (lib/lbm, bench/bench_lbm): MLUPS of a dense 128^3 box (body
# force, fully periodic) and of a porous box at porosity 0.35 (pressure planes) on 1 and 2
# threads, each beside a STREAM-style triad measured in the same run (the memory-bandwidth
# bounds of a D3Q19 double update: 2 x 19 x 8 bytes, and the bytes the solver moves with its
# link table, 340), with the even and odd AA steps
# alone; MRT (the default) and TRT, double and float storage; and the
# simple cubic sphere array against Zick & Homsy's drag at n = 16, 24, 32 nodes per cell,
# half-way and interpolated walls. Sourced by scripts/bench/run.sh ($bench, $out, $machine, $stamp).
echo "== lbflow kernel: D3Q19 MLUPS beside a triad; sphere array against Zick & Homsy" >&2
{
  bench_header
  "$bench/bench_lbm" speed 128 1 mrt 20
  "$bench/bench_lbm" speed 128 2 mrt 20 | tail -n +2
  "$bench/bench_lbm" speed 128 2 trt 20 | tail -n +2
  "$bench/bench_lbm" speed 128 1 mrt 20 float | tail -n +2
  "$bench/bench_lbm" speed 128 2 mrt 20 float | tail -n +2
} | tee "$out/lbflow_kernel.csv" >&2
{
  bench_header
  "$bench/bench_lbm" sphere-array ${LBM_SPHERE_SIZES:-16 24 32}
} | tee "$out/lbflow_sphere_array.csv" >&2
